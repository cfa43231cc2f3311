#include "pfdm/segmentation/slice_alignment.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace pfdm {

namespace {

// Per slice of one frame, the cavity centre's offset across the normal
// from its neighbours' line; NaN where it has no neighbours on both sides.
std::vector<Eigen::Vector3d> FrameOffsets(const std::vector<SliceRing>& rings,
                                          int num_slices, int frame,
                                          const Eigen::Vector3d& normal) {
  std::vector<int> slices;
  for (int k = 0; k < num_slices; ++k) {
    const SliceRing& ring = rings[frame * num_slices + k];
    // A partial ring's cavity centre lies toward its opening.
    if (ring.kept && !ring.partial && ring.has_cavity) slices.push_back(k);
  }
  std::vector<Eigen::Vector3d> offsets(num_slices,
                                       Eigen::Vector3d::Constant(std::nan("")));
  for (size_t n = 1; n + 1 < slices.size(); ++n) {
    const int a = slices[n - 1], k = slices[n], b = slices[n + 1];
    const Eigen::Vector3d& ca = rings[frame * num_slices + a].cavity_centroid;
    const Eigen::Vector3d& cb = rings[frame * num_slices + b].cavity_centroid;
    const Eigen::Vector3d& ck = rings[frame * num_slices + k].cavity_centroid;
    const double s = static_cast<double>(k - a) / (b - a);
    Eigen::Vector3d off = ck - (ca + s * (cb - ca));
    off -= normal * normal.dot(off);
    offsets[k] = off;
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
    const std::vector<Eigen::Vector3d> offsets =
        FrameOffsets(rings, num_slices, t, normal);
    // NaN (no neighbours) compares false: never named, never beaten.
    const auto size = [&](int k) {
      return k >= 0 && k < num_slices && offsets[k].allFinite()
                 ? offsets[k].norm()
                 : -1.0;
    };
    for (int k = 0; k < num_slices; ++k) {
      if (size(k) <= kMisalignedMm) continue;
      if (size(k) < std::max(size(k - 1), size(k + 1))) continue;
      MisalignedSlice& slice = found[k];
      slice.slice = k;
      slice.frames.push_back(t);
      slice.shifts.push_back(offsets[k]);
      slice.max_offset_mm = std::max(slice.max_offset_mm, size(k));
    }
  }
  std::vector<MisalignedSlice> slices;
  for (const auto& [k, slice] : found) slices.push_back(slice);
  return slices;
}

}  // namespace pfdm
