#include "pfdm/segmentation/boundary_points.h"

#include <cmath>

#include "gtest/gtest.h"

namespace pfdm {
namespace {

SliceMask Disk(int n, const Eigen::Vector2d& centre, double radius,
               double hole = 0.0) {
  SliceMask mask{n, n, std::vector<std::uint8_t>(n * n, 0)};
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const double r = (Eigen::Vector2d(i, j) - centre).norm();
      mask.inside[j * n + i] = r <= radius && r >= hole;
    }
  }
  return mask;
}

// Shoelace area of the points taken in angle order about the centre.
double AreaByAngle(std::vector<Eigen::Vector2d> points,
                   const Eigen::Vector2d& centre) {
  std::sort(points.begin(), points.end(), [&](const auto& a, const auto& b) {
    return std::atan2(a.y() - centre.y(), a.x() - centre.x()) <
           std::atan2(b.y() - centre.y(), b.x() - centre.x());
  });
  double area = 0.0;
  for (size_t a = 0, b = points.size() - 1; a < points.size(); b = a++) {
    area += points[b].x() * points[a].y() - points[a].x() * points[b].y();
  }
  return 0.5 * std::abs(area);
}

// A disk of radius 15 voxels: the points lie within 0.35 voxels of its
// circle and enclose the voxel count's area within 1 %.
TEST(BoundaryPointsTest, DiskBoundaryIsSubVoxel) {
  const Eigen::Vector2d centre(30.3, 29.6);
  const SliceMask mask = Disk(64, centre, 15.0);
  const std::vector<Eigen::Vector2d> points = BoundaryPoints(mask);
  ASSERT_GT(points.size(), 90u);
  for (const Eigen::Vector2d& p : points) {
    EXPECT_NEAR((p - centre).norm(), 15.0, 0.35);
  }
  const RegionMoments moments = Moments(mask);
  EXPECT_NEAR(AreaByAngle(points, centre), moments.count, 0.01 * moments.count);
  EXPECT_NEAR((moments.centroid - centre).norm(), 0.0, 0.05);
}

// A straight edge stays half-way between the last voxel in and the first
// out.
TEST(BoundaryPointsTest, StraightEdgeStaysPut) {
  SliceMask mask{20, 20, std::vector<std::uint8_t>(400, 0)};
  for (int j = 0; j < 20; ++j) {
    for (int i = 0; i < 8; ++i) mask.inside[j * 20 + i] = 1;
  }
  int on_edge = 0;
  for (const Eigen::Vector2d& p : BoundaryPoints(mask)) {
    if (p.y() < 2.0 || p.y() > 17.0 || p.x() < 0.0) continue;
    EXPECT_NEAR(p.x(), 7.5, 1e-12);
    ++on_edge;
  }
  EXPECT_EQ(on_edge, 16);
}

// A ring closes its hole in; a ring with a gap does not.
TEST(BoundaryPointsTest, ClosedAndOpenRings) {
  const Eigen::Vector2d centre(20, 20);
  SliceMask ring = Disk(40, centre, 12.0, 8.0);
  const SliceMask cavity = Disk(40, centre, 7.5);
  EXPECT_FALSE(ReachableFromBorder(ring, cavity));
  for (int i = 28; i < 34; ++i) {
    for (int j = 19; j <= 21; ++j) ring.inside[j * 40 + i] = 0;
  }
  EXPECT_TRUE(ReachableFromBorder(ring, cavity));
}

}  // namespace
}  // namespace pfdm
