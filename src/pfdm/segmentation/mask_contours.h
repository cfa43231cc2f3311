// The LV's contours, base and RV insertion from a stack of label maps: what
// pfdm fit reads from a segmentation (docs/segmentation.md).
#ifndef PFDM_SEGMENTATION_MASK_CONTOURS_H_
#define PFDM_SEGMENTATION_MASK_CONTOURS_H_

#include <string>
#include <vector>

#include "Eigen/Core"
#include "pfdm/segmentation/label_volume.h"
#include "pfdm/util/point_data.h"

namespace pfdm {

// One slice of one frame, as far as the LV goes.
struct SliceRing {
  int slice = 0, frame = 0;
  int cavity_voxels = 0, myocardium_voxels = 0;
  // The cavity's voxel centroid, world (has_cavity only).
  bool has_cavity = false;
  Eigen::Vector3d cavity_centroid = Eigen::Vector3d::Zero();
  // The myocardium encloses the cavity (or the slice is an apical cap of
  // myocardium alone).
  bool closed = false;
  // The share of the cavity's boundary that borders the myocardium (1 for
  // a closed ring; a basal slice through the outflow tract has less).
  double myocardial_cover = 0.0;
  bool kept = false;  // Between the apex and the base: its contours fitted.
  // Kept above the frame's most basal closed ring (kPartialRingCover): only
  // its walls that border the myocardium are fitted, none across the
  // opening (the outflow tract).
  bool partial = false;
};

// A slice whose LV cavity centre lies off the line of its neighbours'
// (slice_alignment.h).
struct MisalignedSlice {
  int slice = 0;
  std::vector<int> frames;  // Where it is off.
  double max_offset_mm = 0;  // The largest, over those frames.
  // Per frame of `frames`: its cavity centre minus the point of its
  // neighbours' line, across the slices (world mm).  The slice's contours
  // (and RV insertion) were moved back by it.
  std::vector<Eigen::Vector3d> shifts;
};

struct MaskContours {
  // Per frame: the endocardium (boundary of the cavity label) and the
  // epicardium (outer boundary of cavity and myocardium) of the kept
  // slices, the base's also at its slab's basal face (half a slice toward
  // the base), world mm, layer set, ids unique; contour_types
  // SAX_LV_ENDOCARDIAL and SAX_LV_EPICARDIAL.
  PointSequence points;
  std::vector<SliceRing> rings;  // Per frame, per slice: rings[t * nz + k].
  // The slice at the apex's end (0 or nz - 1), and per frame the most
  // basal slice kept: with a closed myocardial ring, or a partial one
  // above it (SliceRing::partial).
  int apex_slice = 0;
  std::vector<int> base_slice;
  // Frame 0's RV insertion: per kept slice where the RV touches the
  // myocardium, the two ends of the contact arc (unlabelled, world; which
  // is anterior is rv_insertion.h's business).
  std::vector<Eigen::Vector3d> rv_insertion;
  double slice_thickness_mm = 0.0;
  std::vector<MisalignedSlice> misaligned;
  // One line each: what the user should know (misaligned slices).
  std::vector<std::string> warnings;
};

// A slice above the most basal closed ring is still the LV's, as the
// clinical (Simpson's) convention counts it, while the myocardium borders
// at least half its cavity; kept while its cavity is also at least a third
// of the closed base's (a smaller one is the tilted rim's tip, which a
// model whose rim is one ring cannot follow).
inline constexpr double kPartialRingCover = 0.5;
inline constexpr double kPartialRingArea = 0.5;

// Throws InputError naming the source when no voxel carries the LV cavity
// label, or a frame has no closed myocardial ring.
MaskContours ExtractMaskContours(const LabelVolume& volume,
                                 const LabelMap& labels);

}  // namespace pfdm

#endif  // PFDM_SEGMENTATION_MASK_CONTOURS_H_
