// slices.svg: a few slices of a segmentation with the fitted walls' cuts
// drawn over them, the first thing to look at after a fit of a mask.
#ifndef PFDM_IO_SEGMENTATION_OVERLAY_H_
#define PFDM_IO_SEGMENTATION_OVERLAY_H_

#include <string>
#include <vector>

#include "Eigen/Core"
#include "pfdm/model/model.h"
#include "pfdm/segmentation/label_volume.h"
#include "pfdm/segmentation/mask_contours.h"

namespace pfdm {

// Where surface w of `model` crosses slice k's plane of `volume`, in the
// slice's voxel coordinates (i, j): per meridian (of `meridians`) the
// first crossing from the apex, linearly interpolated between 400 steps
// in u; none where the meridian does not reach the plane.
std::vector<Eigen::Vector2d> WallCut(const Model& model, double w,
                                     const LabelVolume& volume, int k,
                                     int meridians = 180);

// An SVG of frames {0, es_frame} by three kept slices of frame 0 (the
// apical, middle and basal), each the labels (cavity red, myocardium
// green, RV blue) with the fitted endocardium (w = -1) and epicardium
// (w = +1) cut drawn as dots.  models: per frame, the fit's.
std::string SegmentationOverlaySvg(const LabelVolume& volume,
                                   const LabelMap& labels,
                                   const MaskContours& contours,
                                   const std::vector<Model>& models,
                                   int es_frame);

}  // namespace pfdm

#endif  // PFDM_IO_SEGMENTATION_OVERLAY_H_
