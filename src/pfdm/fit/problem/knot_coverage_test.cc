#include "pfdm/fit/problem/knot_coverage.h"

#include <cmath>
#include <vector>

#include "gtest/gtest.h"

namespace pfdm {
namespace {

const KnotGrid& Grid() {
  static const KnotGrid grid(5, -M_PI / 2, M_PI / 6);
  return grid;
}

// `count` points evenly around the ring at u.
void AddRing(double u, int count, std::vector<MaterialPoint>* material) {
  for (int i = 0; i < count; ++i) {
    material->push_back({u, -M_PI + 2.0 * M_PI * (i + 0.5) / count, 0.0});
  }
}

TEST(KnotCoverageTest, APointSplitsBetweenItsTwoKnotsByItsHatWeights) {
  const double u = 0.25 * Grid().KnotU(1) + 0.75 * Grid().KnotU(2);
  const KnotSpan span = Grid().Span(u);
  const SectorCounts counts = KnotSectorCounts(Grid(), {{u, 0.1, 0.0}});
  // v = 0.1 lies in sector 4 of 8 ([0, pi/4)).
  EXPECT_NEAR(counts[1][4], 1.0 - span.weight, 1e-12);
  EXPECT_NEAR(counts[2][4], span.weight, 1e-12);
  EXPECT_NEAR(counts[1][4] + counts[2][4], 1.0, 1e-12);
  EXPECT_EQ(counts[0][4] + counts[3][4] + counts[4][4], 0.0);
}

TEST(KnotCoverageTest, RingsAtTheMiddleKnotsCoverThemAndNotTheEnds) {
  std::vector<MaterialPoint> material;
  for (int k = 1; k <= 3; ++k) AddRing(Grid().KnotU(k), 40, &material);
  const std::vector<bool> covered = CoveredKnots(Grid(), material, 0.5, 6);
  EXPECT_EQ(covered, std::vector<bool>({false, true, true, true, false}));
}

// Two long-axis contours cross a ring in four places: four sectors, not
// six, however many points they hold there.
TEST(KnotCoverageTest, LongAxisCrossingsAloneLeaveARingUncovered) {
  std::vector<MaterialPoint> material;
  for (double v : {-M_PI + 0.1, -M_PI / 2 + 0.1, 0.1, M_PI / 2 + 0.1}) {
    for (int i = 0; i < 30; ++i) material.push_back({Grid().KnotU(2), v, 0.0});
  }
  AddRing(Grid().KnotU(1), 30, &material);
  const std::vector<bool> covered = CoveredKnots(Grid(), material, 0.5, 6);
  EXPECT_TRUE(covered[1]);
  EXPECT_FALSE(covered[2]);
  EXPECT_TRUE(CoveredKnots(Grid(), material, 0.5, 4)[2]);
}

// Three long-axis planes 60 degrees apart cross a ring at six angles, one
// in each of six sectors: enough to pin the ring's ellipse, so the ring
// counts as covered (with long-axis contours alone too); two planes'
// crossings (above) do not.
TEST(KnotCoverageTest, ThreeLongAxisPlanesCoverARing) {
  std::vector<MaterialPoint> material;
  for (int plane = 0; plane < 3; ++plane) {
    for (double side : {0.0, M_PI}) {
      const double v = std::remainder(plane * M_PI / 3 + side, 2 * M_PI);
      for (int i = 0; i < 10; ++i) {
        material.push_back({Grid().KnotU(2), v, 0.0});
      }
    }
  }
  const SectorCounts counts = KnotSectorCounts(Grid(), material);
  int filled = 0;
  for (double count : counts[2]) filled += count > 0.0;
  EXPECT_EQ(filled, 6);
  EXPECT_TRUE(CoveredKnots(Grid(), material, 0.5, 6)[2]);
  EXPECT_FALSE(CoveredKnots(Grid(), material, 0.5, 7)[2]);
}

// A knot with points all round but far fewer than its share.
TEST(KnotCoverageTest, AThinRingIsNotCovered) {
  std::vector<MaterialPoint> material;
  AddRing(Grid().KnotU(1), 100, &material);
  AddRing(Grid().KnotU(3), 8, &material);
  const std::vector<bool> covered = CoveredKnots(Grid(), material, 0.5, 6);
  EXPECT_TRUE(covered[1]);
  EXPECT_FALSE(covered[3]);
}

TEST(KnotCoverageTest, OnlyTheCoveredKnotsRadiiAreScaled) {
  std::vector<MaterialPoint> material;
  AddRing(Grid().KnotU(2), 50, &material);
  FunctionValues scales;
  scales.fill(2.0);
  const std::vector<FunctionValues> per_knot =
      CoveredRadiiScales(Grid(), material, scales, 0.25);
  ASSERT_EQ(per_knot.size(), 5u);
  for (int k = 0; k < 5; ++k) {
    for (int f = 0; f < kNumFunctions; ++f) {
      const bool radius = k == 2 && (f == kA1 || f == kA2);
      EXPECT_EQ(per_knot[k][f], radius ? 0.5 : 2.0) << k << " " << f;
    }
  }
}

}  // namespace
}  // namespace pfdm
