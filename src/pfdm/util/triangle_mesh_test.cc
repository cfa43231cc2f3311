#include "pfdm/util/triangle_mesh.h"

#include <cmath>

#include "gtest/gtest.h"
#include "pfdm/util/angles.h"
#include "pfdm/util/error.h"

namespace pfdm {
namespace {

// The cube [0, 2]^3 shifted by `offset`, triangles facing outward; without
// its top face (z = 2) when `open`.
TriangleMesh Cube(const Eigen::Vector3d& offset, bool open) {
  TriangleMesh mesh;
  for (int i = 0; i < 8; ++i) {
    mesh.points.push_back(
        offset + 2.0 * Eigen::Vector3d(i & 1, (i >> 1) & 1, (i >> 2) & 1));
  }
  const std::vector<std::array<int, 3>> faces = {
      {0, 2, 1}, {1, 2, 3},  // z = 0, facing -z.
      {4, 5, 6}, {5, 7, 6},  // z = 2, facing +z.
      {0, 1, 4}, {1, 5, 4},  // y = 0.
      {2, 6, 3}, {3, 6, 7},  // y = 2.
      {0, 4, 2}, {2, 4, 6},  // x = 0.
      {1, 3, 5}, {3, 7, 5},  // x = 2.
  };
  for (size_t f = 0; f < faces.size(); ++f) {
    if (open && (f == 2 || f == 3)) continue;
    mesh.triangles.push_back(faces[f]);
  }
  return mesh;
}

TEST(TriangleMeshTest, ClosedCubeHasItsVolumeWherever) {
  EXPECT_NEAR(EnclosedVolume(Cube({0, 0, 0}, false)), 8.0, 1e-12);
  EXPECT_NEAR(EnclosedVolume(Cube({100, -50, 7}, false)), 8.0, 1e-9);
  EXPECT_TRUE(BoundaryLoops(Cube({0, 0, 0}, false)).empty());
}

TEST(TriangleMeshTest, OpenTopIsOneLoopAndItsCapClosesTheCube) {
  const TriangleMesh open = Cube({1, 2, 3}, true);
  const auto loops = BoundaryLoops(open);
  ASSERT_EQ(loops.size(), 1u);
  EXPECT_EQ(loops[0].size(), 4u);
  const TriangleMesh closed = CapBoundaryLoops(open);
  EXPECT_EQ(closed.points.size(), 9u);      // One centroid.
  EXPECT_EQ(closed.triangles.size(), 14u);  // Four lid triangles.
  EXPECT_TRUE(BoundaryLoops(closed).empty());
  EXPECT_NEAR(closed.points.back().z(), 5.0, 1e-12);
  EXPECT_NEAR(EnclosedVolume(closed), 8.0, 1e-9);
  // Without the lid the sum is not the volume: the cap matters.
  EXPECT_GT(std::abs(EnclosedVolume(open) - 8.0), 1.0);
}

TEST(TriangleMeshTest, NonManifoldBoundaryIsAnInputError) {
  // A flap hanging off the open cube's rim at a corner: two boundary edges
  // leave vertex 4.
  TriangleMesh mesh = Cube({0, 0, 0}, true);
  mesh.points.push_back({-1, -1, 3});
  mesh.points.push_back({-1, 0, 3});
  mesh.triangles.push_back({4, 8, 9});
  EXPECT_THROW(BoundaryLoops(mesh), InputError);
}

TEST(TriangleMeshTest, VolumeBelowPlaneCutsTheCube) {
  const TriangleMesh cube = Cube({0, 0, 0}, false);
  EXPECT_NEAR(VolumeBelowPlane(cube, {0, 0, 0.5}, {0, 0, 1}), 2.0, 1e-12);
  EXPECT_NEAR(VolumeBelowPlane(cube, {0, 0, 0.5}, {0, 0, -1}), 6.0, 1e-12);
  // Any plane through the centre halves it.
  EXPECT_NEAR(
      VolumeBelowPlane(cube, {1, 1, 1}, Eigen::Vector3d(1, 2, 3).normalized()),
      4.0, 1e-12);
  EXPECT_NEAR(VolumeBelowPlane(cube, {0, 0, 5}, {0, 0, 1}), 8.0, 1e-12);
  EXPECT_NEAR(VolumeBelowPlane(cube, {0, 0, -1}, {0, 0, 1}), 0.0, 1e-12);
}

}  // namespace
}  // namespace pfdm

namespace pfdm {
namespace {

// A sphere of radius r about the origin, ring by ring from the south pole
// (one vertex) to the north pole, triangles facing outward.
TriangleMesh Sphere(double r, int rings, int meridians) {
  TriangleMesh mesh;
  mesh.points.push_back({0, 0, -r});
  for (int i = 1; i < rings; ++i) {
    const double polar = kPi * i / rings;
    for (int j = 0; j < meridians; ++j) {
      const double around = 2.0 * kPi * j / meridians;
      mesh.points.push_back(r *
                            Eigen::Vector3d(std::sin(polar) * std::cos(around),
                                            std::sin(polar) * std::sin(around),
                                            -std::cos(polar)));
    }
  }
  mesh.points.push_back({0, 0, r});
  const int top = static_cast<int>(mesh.points.size()) - 1;
  auto at = [&](int ring, int j) {
    return 1 + (ring - 1) * meridians + j % meridians;
  };
  for (int j = 0; j < meridians; ++j) {
    mesh.triangles.push_back({0, at(1, j + 1), at(1, j)});
    mesh.triangles.push_back({top, at(rings - 1, j), at(rings - 1, j + 1)});
    for (int i = 1; i + 1 < rings; ++i) {
      mesh.triangles.push_back({at(i, j), at(i, j + 1), at(i + 1, j + 1)});
      mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i + 1, j)});
    }
  }
  return mesh;
}

// Kept block by block, the volume below a plane is the one summed anew, to
// the bit; moved in a range of vertices, only the blocks that use them are
// summed again, and the moved volume is the new mesh's, to the bit.
TEST(PlaneVolumeTest, SumsAgainOnlyTheBlocksOfTheMovedVertices) {
  const TriangleMesh sphere = Sphere(10.0, 60, 64);
  const Eigen::Vector3d point(0, 0, 2), normal(0, 0, 1);
  const PlaneVolume kept(sphere, point, normal);
  EXPECT_EQ(kept.volume(), VolumeBelowPlane(sphere, point, normal));
  // The ball's below z = 2: pi (r + h)^2 (2 r - h) / 3 with h = 2, within
  // the mesh's facets.
  EXPECT_NEAR(kept.volume(), kPi * 12.0 * 12.0 * 18.0 / 3.0, 0.01 * 2714.3);
  // Rings 20-29 pushed out by a tenth.
  TriangleMesh moved = sphere;
  const size_t first = 1 + 19 * 64, last = 1 + 29 * 64;
  for (size_t k = first; k < last; ++k) moved.points[k] *= 1.1;
  const double fresh = VolumeBelowPlane(moved, point, normal);
  EXPECT_EQ(kept.Moved(moved, first, last), fresh);
  EXPECT_GT(fresh, kept.volume() + 50.0);
  // Told that nothing moved, it keeps every block: the range is what it
  // sums again.
  EXPECT_EQ(kept.Moved(moved, 0, 0), kept.volume());
}

}  // namespace
}  // namespace pfdm
