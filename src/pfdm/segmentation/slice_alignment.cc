#include "pfdm/segmentation/slice_alignment.h"

#include <algorithm>
#include <map>

namespace pfdm {

namespace {

// Per slice of one frame, the cavity centre's distance across the normal
// from its neighbours' line; -1 where it has no neighbours on both sides.
std::vector<double> FrameOffsets(const std::vector<SliceRing>& rings,
                                 int num_slices, int frame,
                                 const Eigen::Vector3d& normal) {
  std::vector<int> slices;
  for (int k = 0; k < num_slices; ++k) {
    const SliceRing& ring = rings[frame * num_slices + k];
    // A partial ring's cavity centre lies toward its opening.
    if (ring.kept && !ring.partial && ring.has_cavity) slices.push_back(k);
  }
  std::vector<double> offsets(num_slices, -1.0);
  for (size_t n = 1; n + 1 < slices.size(); ++n) {
    const int a = slices[n - 1], k = slices[n], b = slices[n + 1];
    const Eigen::Vector3d& ca = rings[frame * num_slices + a].cavity_centroid;
    const Eigen::Vector3d& cb = rings[frame * num_slices + b].cavity_centroid;
    const Eigen::Vector3d& ck = rings[frame * num_slices + k].cavity_centroid;
    const double s = static_cast<double>(k - a) / (b - a);
    Eigen::Vector3d off = ck - (ca + s * (cb - ca));
    off -= normal * normal.dot(off);
    offsets[k] = off.norm();
  }
  return offsets;
}

}  // namespace

std::vector<MisalignedSlice> FindMisalignedSlices(
    const std::vector<SliceRing>& rings, int num_slices, int num_frames,
    const Eigen::Vector3d& slice_normal) {
  const Eigen::Vector3d normal = slice_normal.normalized();
  std::map<int, MisalignedSlice> found;
  for (int t = 0; t < num_frames; ++t) {
    const std::vector<double> offsets =
        FrameOffsets(rings, num_slices, t, normal);
    for (int k = 0; k < num_slices; ++k) {
      if (offsets[k] <= kMisalignedMm) continue;
      const double before = k > 0 ? offsets[k - 1] : -1.0;
      const double after = k + 1 < num_slices ? offsets[k + 1] : -1.0;
      if (offsets[k] < std::max(before, after)) continue;
      MisalignedSlice& slice = found[k];
      slice.slice = k;
      slice.frames.push_back(t);
      slice.max_offset_mm = std::max(slice.max_offset_mm, offsets[k]);
    }
  }
  std::vector<MisalignedSlice> slices;
  for (const auto& [k, slice] : found) slices.push_back(slice);
  return slices;
}

}  // namespace pfdm
