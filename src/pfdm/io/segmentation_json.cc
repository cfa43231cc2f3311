#include "pfdm/io/segmentation_json.h"

namespace pfdm {

using json = nlohmann::ordered_json;

json SegmentationJson(const SegmentationRecord& r) {
  json misaligned = json::array();
  for (const MisalignedSlice& slice : r.misaligned) {
    misaligned.push_back({{"slice", slice.slice},
                          {"frames", slice.frames},
                          {"max_offset_mm", slice.max_offset_mm}});
  }
  const json rv = r.labels.rv < 0 ? json(nullptr) : json(r.labels.rv);
  return {{"source", r.source},
          {"labels", {{"lv", r.labels.lv}, {"myo", r.labels.myo}, {"rv", rv}}},
          {"slices", r.slices},
          {"frames", r.frames},
          {"voxel_mm", {r.voxel_mm.x(), r.voxel_mm.y(), r.voxel_mm.z()}},
          {"geometry", r.geometry},
          {"apex_slice", r.apex_slice},
          {"base_slice", r.base_slice},
          {"slices_fitted", r.slices_fitted},
          {"rv_insertion_slices", r.rv_insertion_slices},
          {"misaligned", misaligned}};
}

}  // namespace pfdm
