#include "pfdm/segmentation/segmentation_record.h"

#include <cstdio>

namespace pfdm {

SegmentationRecord RecordSegmentation(const LabelVolume& volume,
                                      const LabelMap& labels,
                                      const MaskContours& contours) {
  SegmentationRecord r;
  r.source = volume.source;
  r.labels = labels;
  r.slices = volume.nz;
  r.frames = volume.nt;
  r.voxel_mm = {volume.Spacing(0), volume.Spacing(1), volume.Spacing(2)};
  r.geometry = volume.geometry;
  r.apex_slice = contours.apex_slice;
  r.base_slice = contours.base_slice;
  r.slices_fitted.assign(volume.nt, 0);
  for (const SliceRing& ring : contours.rings) {
    if (ring.kept) ++r.slices_fitted[ring.frame];
  }
  r.rv_insertion_slices = static_cast<int>(contours.rv_insertion.size() / 2);
  r.misaligned = contours.misaligned;
  return r;
}

std::vector<Verdict> SliceAlignmentVerdicts(
    const std::vector<MisalignedSlice>& misaligned, int num_frames) {
  std::vector<Verdict> verdicts(num_frames);
  for (const MisalignedSlice& slice : misaligned) {
    char text[200];
    std::snprintf(text, sizeof(text),
                  "slice %d of the segmentation lay off its neighbours' line "
                  "(up to %.1f mm; a breath-hold shift?) and was moved back "
                  "onto it",
                  slice.slice, slice.max_offset_mm);
    for (int t : slice.frames) {
      if (t >= 0 && t < num_frames) verdicts[t].Warn("misaligned_slice", text);
    }
  }
  return verdicts;
}

}  // namespace pfdm
