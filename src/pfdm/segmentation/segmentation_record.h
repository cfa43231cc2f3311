// What a fit keeps of the label map its points came from: which file and
// labels, what was found in it, and what the user should distrust (the
// misaligned slices, as warnings in the frames' verdicts).  fit.json's
// "segmentation" (docs/segmentation.md).
#ifndef PFDM_SEGMENTATION_SEGMENTATION_RECORD_H_
#define PFDM_SEGMENTATION_SEGMENTATION_RECORD_H_

#include <string>
#include <vector>

#include "Eigen/Core"
#include "pfdm/segmentation/label_volume.h"
#include "pfdm/segmentation/mask_contours.h"
#include "pfdm/util/verdict.h"

namespace pfdm {

struct SegmentationRecord {
  std::string source;  // The file or folder.
  LabelMap labels;     // rv -1: none.
  int slices = 0, frames = 0;
  Eigen::Vector3d voxel_mm = Eigen::Vector3d::Zero();  // i, j, slice.
  std::string geometry;                                // "sform", ...
  int apex_slice = 0;
  std::vector<int> base_slice;  // Per frame.
  // Per frame, the slices between apex and base whose contours were
  // fitted.
  std::vector<int> slices_fitted;
  int rv_insertion_slices = 0;  // Frame 0's slices with an RV contact.
  std::vector<MisalignedSlice> misaligned;
};

SegmentationRecord RecordSegmentation(const LabelVolume& volume,
                                      const LabelMap& labels,
                                      const MaskContours& contours);

// Per frame (num_frames of them): a warning "misaligned_slice" for each
// slice that lies off its neighbours' line in that frame.  Its contours
// were moved back onto the line (MisalignedSlice::shifts), which assumes
// the centre of a true LV follows its neighbours': the user should look.
std::vector<Verdict> SliceAlignmentVerdicts(
    const std::vector<MisalignedSlice>& misaligned, int num_frames);

}  // namespace pfdm

#endif  // PFDM_SEGMENTATION_SEGMENTATION_RECORD_H_
