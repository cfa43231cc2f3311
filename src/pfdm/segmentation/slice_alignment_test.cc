#include "pfdm/segmentation/slice_alignment.h"

#include "gtest/gtest.h"

namespace pfdm {
namespace {

// Cavity centres on an oblique line, 10 mm apart along z; slice 3 moved
// 5 mm across in frame 1 only.
TEST(SliceAlignmentTest, NamesTheShiftedSliceOnly) {
  const int nz = 7, nt = 2;
  std::vector<SliceRing> rings;
  for (int t = 0; t < nt; ++t) {
    for (int k = 0; k < nz; ++k) {
      SliceRing ring;
      ring.slice = k;
      ring.frame = t;
      ring.kept = ring.has_cavity = k < 6;
      ring.cavity_centroid = Eigen::Vector3d(1.5 * k, -0.5 * k, 10.0 * k);
      if (t == 1 && k == 3) ring.cavity_centroid.x() += 5.0;
      rings.push_back(ring);
    }
  }
  const std::vector<MisalignedSlice> found =
      FindMisalignedSlices(rings, nz, nt, Eigen::Vector3d::UnitZ());
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].slice, 3);
  EXPECT_EQ(found[0].frames, std::vector<int>{1});
  EXPECT_NEAR(found[0].max_offset_mm, 5.0, 1e-9);
  ASSERT_EQ(found[0].shifts.size(), 1u);
  EXPECT_LT((found[0].shifts[0] - Eigen::Vector3d(5, 0, 0)).norm(), 1e-9);
  // 2.9 mm is within the shape's own variation.
  rings[nz + 3].cavity_centroid.x() -= 2.1;
  EXPECT_TRUE(
      FindMisalignedSlices(rings, nz, nt, Eigen::Vector3d::UnitZ()).empty());
}

}  // namespace
}  // namespace pfdm
