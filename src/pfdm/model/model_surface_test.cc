#include "pfdm/model/model_surface.h"

#include <cmath>

#include "gtest/gtest.h"
#include "pfdm/testing/test_models.h"
#include "pfdm/util/angles.h"

namespace pfdm {
namespace {

// a0 = 50 mm with radii 30 and 25 mm and half-length 40 mm: an ellipsoid cut
// at the base rim, z = 40 sin(pi/6) = 20 mm.
Model Ellipsoid() {
  FunctionValues values = DefaultFunctionValues();
  values[kA0] = 50.0;
  values[kA1] = 0.6;
  values[kA2] = 0.5;
  values[kA3] = 0.8;
  return Model::Uniform(ModelConfig::Paper(17), values);
}

// Volume of the ellipsoid with semi-axes a, b, c below z = s c: the unit
// ball's below z = s, pi (1 + s)^2 (2 - s) / 3, scaled by abc.  ml.
double EllipsoidVolumeBelow(double a, double b, double c, double s) {
  return kPi * a * b * c * (1 + s) * (1 + s) * (2 - s) / 3.0 / 1000.0;
}

TEST(ModelSurfaceTest, ApexIsOneVertexAndTheRimTheOnlyBoundary) {
  const ModelSurface surface = MakeModelSurface(Ellipsoid(), 9, 12);
  EXPECT_EQ(surface.mesh.points.size(), 1u + 8u * 12u);
  const auto loops = BoundaryLoops(surface.mesh);
  ASSERT_EQ(loops.size(), 1u);
  EXPECT_EQ(loops[0].size(), 12u);
  for (int i : loops[0]) EXPECT_NEAR(surface.u[i], kPi / 6, 1e-12);
  // Triangles face outward: the capped surface's signed sum is positive.
  const TriangleMesh closed = CapBoundaryLoops(surface.mesh);
  double six_volume = 0.0;
  for (const auto& t : closed.triangles) {
    six_volume +=
        closed.points[t[0]].dot(closed.points[t[1]].cross(closed.points[t[2]]));
  }
  EXPECT_GT(six_volume, 0.0);
}

TEST(ModelSurfaceTest, CappedEllipsoidMatchesTheAnalyticVolume) {
  const double expected = EllipsoidVolumeBelow(30, 25, 40, 0.5);  // 106.0 ml
  EXPECT_NEAR(CavityVolumeMl(Ellipsoid()), expected, 0.005 * expected);
  // A sphere too (a1 = a2 = a3): 1.125 pi r^3.
  Model sphere = Ellipsoid();
  for (auto& knot : sphere.state.knots) knot[kA1] = knot[kA2] = knot[kA3] = 0.8;
  const double sphere_volume = EllipsoidVolumeBelow(40, 40, 40, 0.5);
  EXPECT_NEAR(CavityVolumeMl(sphere), sphere_volume, 0.005 * sphere_volume);
}

// The rims closed from the layout are the boundary loops the edges give:
// the same volume, with an apex pole and with an open apex ring.
TEST(ModelSurfaceTest, TheVolumeClosesTheRimsTheEdgesFind) {
  for (double u_min : {-kPi / 2, -1.2}) {
    Model model = Ellipsoid();
    model.config.u_min = u_min;
    // model_surface.cc's volume resolution.
    const ModelSurface surface = MakeModelSurface(model, 97, 128);
    const double from_edges =
        EnclosedVolume(CapBoundaryLoops(surface.mesh)) / 1000.0;
    EXPECT_NEAR(CavityVolumeMl(model), from_edges, 1e-12 * from_edges)
        << "u_min " << u_min;
  }
}

TEST(ModelSurfaceTest, TwistOffsetsAndPoseKeepTheVolume) {
  // Twist turns and offsets shift each ring within its own plane, which
  // keeps every cross-section's area (Cavalieri); the pose moves it rigidly.
  const double plain = CavityVolumeMl(Ellipsoid());
  Model moved = Ellipsoid();
  const int k = moved.config.num_knots;
  for (int i = 0; i < k; ++i) {
    moved.state.knots[i][kTau] = 0.3 * i / (k - 1) - 0.1;
    moved.state.knots[i][kE1o] = 3.0 * std::sin(i);
    moved.state.knots[i][kE2o] = -2.0 * i / (k - 1);
  }
  EXPECT_NEAR(CavityVolumeMl(moved), plain, 0.002 * plain);
  moved.state.center = {10.0, -20.0, 30.0};
  const double half = std::sqrt(0.5);
  moved.state.quaternion = {half, half, 0.0, 0.0};
  EXPECT_NEAR(CavityVolumeMl(moved), plain, 0.002 * plain);
}

TEST(ModelSurfaceTest, BasePlaneCutsTheContinuedSurface) {
  const Model model = Ellipsoid();
  // At the rim, across the axis: the flat lid's volume.
  BasePlane rim{{0, 0, 20}, {0, 0, 1}, 3};
  EXPECT_NEAR(CavityVolumeMl(model, &rim), CavityVolumeMl(model),
              0.003 * CavityVolumeMl(model));
  // Through the centre at any tilt: half the whole ellipsoid, the part past
  // the rim being the surface continued with its base values.
  const double half = EllipsoidVolumeBelow(30, 25, 40, 0.0);
  BasePlane tilted{{0, 0, 0}, Eigen::Vector3d(0.3, -0.2, 1).normalized(), 3};
  EXPECT_NEAR(CavityVolumeMl(model, &tilted), half, 0.005 * half);
  // The normal's sign does not matter: the apex side is kept.
  tilted.normal = -tilted.normal;
  EXPECT_NEAR(CavityVolumeMl(model, &tilted), half, 0.005 * half);
  // Above the rim, by 10 mm: more than the flat lid.
  BasePlane high{{0, 0, 30}, {0, 0, 1}, 3};
  EXPECT_NEAR(CavityVolumeMl(model, &high),
              EllipsoidVolumeBelow(30, 25, 40, 0.75), 0.005 * 120.0);
}

// A solid's walls cut by the plane of the mid-wall's rim.  TestShell's
// sphere of radius 30 mm with a 10 mm wall: its walls are spheres of 25 and
// 35 mm, the mid-wall's rim at z = 30 sin(pi/6) = 15 mm, the endocardium's
// own at 12.5 and the epicardium's at 17.5, where their flat lids close
// them.
TEST(ModelSurfaceTest, ASolidsWallsEndAtARimPlane) {
  const Model sphere = TestShell(17);
  const BasePlane rim = RimPlane(sphere);
  EXPECT_NEAR(rim.point.z(), 15.0, 1e-9);
  EXPECT_NEAR(std::abs(rim.normal.z()), 1.0, 1e-12);
  for (double radius : {25.0, 35.0}) {
    const double w = radius < 30.0 ? -1.0 : 1.0;
    const double cut =
        EllipsoidVolumeBelow(radius, radius, radius, 15.0 / radius);
    EXPECT_NEAR(CavityVolumeMl(sphere, &rim, w), cut, 0.002 * cut) << w;
    const double lidded = EllipsoidVolumeBelow(radius, radius, radius, 0.5);
    EXPECT_NEAR(CavityVolumeMl(sphere, nullptr, w), lidded, 0.002 * lidded)
        << w;
  }
  // Each wall's rim on its own sphere at u_max (sin = 0.5): the
  // endocardium's, 2.5 mm below the mid-wall's, is the lowest.
  EXPECT_NEAR(RimPlane(sphere, -1.0).point.z(), 12.5, 1e-9);
  EXPECT_NEAR(RimPlane(sphere, 1.0).point.z(), 17.5, 1e-9);
  EXPECT_NEAR(LowestRimPlane(sphere).point.z(), 12.5, 1e-9);
  EXPECT_NEAR(LowestRimDrop(sphere), 2.5, 1e-9);
}

// Below the equator the walls' rims swap: the epicardium's is the lowest.
// A surface has one rim.
TEST(ModelSurfaceTest, TheLowestRimIsTheWallsWhoseRimDrops) {
  Model sphere = TestShell(17);
  sphere.config.u_max = -kPi / 6;  // The mid-wall's rim at -15 mm.
  EXPECT_NEAR(LowestRimPlane(sphere).point.z(), -17.5, 1e-9);
  EXPECT_NEAR(LowestRimDrop(sphere), 2.5, 1e-9);
  EXPECT_EQ(LowestRimDrop(TestSpheroid(17)), 0.0);
}

// With a base plane the surface stops at the first ring past the rim wholly
// 2 mm above it: the same volume, to the bit, as the surface continued to
// the top pole (the rings after it lie wholly above, where VolumeBelowPlane
// skips them), from fewer vertices.  A move that brings that ring down to
// the plane measures the whole surface again.
TEST(ModelSurfaceTest, TheCavityStopsAtARingWhollyAboveTheBasePlane) {
  const Model model = Ellipsoid();
  const BasePlane tilted{
      {0, 0, 15}, Eigen::Vector3d(0.3, -0.2, 1).normalized(), 3};
  const ModelSurface whole = MakeModelSurface(model, 194, 128, kPi / 2);
  const ModelSurface cut = CavitySurface(model, &tilted);
  ASSERT_GE(cut.cut_ring_first, 0);
  EXPECT_LT(cut.mesh.points.size(), 0.9 * whole.mesh.points.size());
  const Eigen::Vector3d up = tilted.normal;
  for (int k = cut.cut_ring_first; k < cut.cut_ring_first + 128; ++k) {
    EXPECT_GT(up.dot(cut.mesh.points[k] - tilted.point), 2.0);
  }
  EXPECT_EQ(CavityVolumeMl(model, cut, &tilted),
            VolumeBelowPlane(whole.mesh, tilted.point, up) / 1000.0);
  // Down the axis by 5 mm, every vertex re-placed: the cut ring is now
  // below the plane, past which the moved surface goes on.
  Model lowered = model;
  lowered.state.center[2] -= 5.0;
  ModelSurface moved = cut;
  ReplaceVertices(lowered, model.config.u_min, kPi / 2, 0.0, &moved);
  EXPECT_GT(CavityVolumeMl(lowered, &tilted),
            CavityVolumeMl(model, &tilted) + 5.0);
  EXPECT_EQ(CavityVolumeMl(lowered, moved, &tilted),
            CavityVolumeMl(lowered, &tilted));
  // Kept, the moved surface's volume is measured anew where its cut ring
  // went below the plane.
  const KeptCavityVolume kept(model, cut, &tilted);
  EXPECT_EQ(kept.MovedMl(lowered, moved, {0, moved.mesh.points.size()}),
            CavityVolumeMl(lowered, &tilted));
}

// A knot's step re-places the vertices of its span (one range of indices):
// the kept volume sums again only the triangles that use them and reads,
// to the bit, what the moved surface's volume reads, under a base plane
// and with the flat lid (no plane) alike.  A step of the first knot moves
// the apex vertex, about which CavityVolumeMl sums the flat lid's volume
// and the kept one does not: the same within round-off.
TEST(ModelSurfaceTest, AKeptVolumeSumsAgainWhatAKnotsStepMoved) {
  const Model model = Ellipsoid();
  const BasePlane tilted{
      {0, 0, 15}, Eigen::Vector3d(0.3, -0.2, 1).normalized(), 3};
  const KnotGrid& grid = model.config.Grid();
  Model moved_model = model;
  moved_model.state.knots[8][kA1] *= 1.05;
  for (const BasePlane* base : {static_cast<const BasePlane*>(&tilted),
                                static_cast<const BasePlane*>(nullptr)}) {
    const ModelSurface surface = CavitySurface(model, base);
    const KeptCavityVolume kept(model, surface, base);
    EXPECT_EQ(kept.ml(), CavityVolumeMl(model, surface, base));
    ModelSurface moved = surface;
    const VertexRange changed =
        ReplaceVertices(moved_model, grid.KnotU(7), grid.KnotU(9), 0.0, &moved);
    EXPECT_GT(changed.last, changed.first);
    EXPECT_LT(changed.last - changed.first, moved.mesh.points.size() / 4);
    const double fresh = CavityVolumeMl(moved_model, moved, base);
    EXPECT_EQ(kept.MovedMl(moved_model, moved, changed), fresh);
    EXPECT_GT(fresh, kept.ml() + 0.3);  // 0.59 ml more.
    // The same as the moved model's surface taken from scratch.
    EXPECT_NEAR(fresh, CavityVolumeMl(moved_model, base), 1e-9 * fresh);
  }
  Model apex_moved = model;
  apex_moved.state.knots[0][kA3] *= 1.05;
  const ModelSurface surface = CavitySurface(model, nullptr);
  const KeptCavityVolume kept(model, surface, nullptr);
  ModelSurface moved = surface;
  const VertexRange changed = ReplaceVertices(apex_moved, model.config.u_min,
                                              grid.KnotU(1), 0.0, &moved);
  EXPECT_EQ(changed.first, 0u);
  const double fresh = CavityVolumeMl(apex_moved, moved, nullptr);
  EXPECT_NEAR(kept.MovedMl(apex_moved, moved, changed), fresh, 1e-12 * fresh);
  EXPECT_NE(moved.mesh.points.front(), surface.mesh.points.front());
  EXPECT_GT(std::abs(fresh - kept.ml()), 0.01);  // 0.02 ml less.
}

}  // namespace
}  // namespace pfdm
