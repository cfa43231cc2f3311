// Short-axis slices that do not line up: each slice is its own breath-hold,
// and a patient who breathes in a little deeper shifts the slice's heart
// in the image by several mm.
#ifndef PFDM_SEGMENTATION_SLICE_ALIGNMENT_H_
#define PFDM_SEGMENTATION_SLICE_ALIGNMENT_H_

#include <vector>

#include "Eigen/Core"
#include "pfdm/segmentation/mask_contours.h"

namespace pfdm {

// Beyond this a cavity centre's distance from its neighbours' line is a
// shift, not the ventricle's shape: the phantom's slices stay within 0.5 mm
// of it, a segmentation's noise within about 1.5 mm.
inline constexpr double kMisalignedMm = 3.0;

// Per frame, each kept slice with a closed ring (not partial) and a cavity
// between two others: the
// distance across the slices' normal of its cavity centroid from the line
// through its neighbours' centroids.  A slice is named where that distance
// exceeds kMisalignedMm and its neighbours' (a shifted slice also moves
// the line its neighbours are measured against, by half as much).
std::vector<MisalignedSlice> FindMisalignedSlices(
    const std::vector<SliceRing>& rings, int num_slices, int num_frames,
    const Eigen::Vector3d& slice_normal);

}  // namespace pfdm

#endif  // PFDM_SEGMENTATION_SLICE_ALIGNMENT_H_
