#include "pfdm/report/mesh_motion.h"

#include "gtest/gtest.h"
#include "pfdm/model/model_surface.h"
#include "pfdm/util/error.h"

namespace pfdm {
namespace {

// An open, capped-ellipsoid-like surface: apex at (0, 0, -40), rim at z = 20.
TriangleMesh Cavity() {
  FunctionValues values = DefaultFunctionValues();
  values[kA0] = 50.0;
  values[kA1] = values[kA2] = 0.5;
  values[kA3] = 0.8;
  return MakeModelSurface(Model::Uniform(ModelConfig::Paper(17), values), 33,
                          48)
      .mesh;
}

TEST(MeshMotionTest, ScaledCopyReadsAsItsScales) {
  const TriangleMesh ed = Cavity();
  TriangleMesh es = ed;
  const Eigen::Vector3d apex(0, 0, -40);
  for (Eigen::Vector3d& p : es.points) {
    const Eigen::Vector3d d = p - apex;
    // 20 % radially about the axis, 10 % along it towards the apex.
    p = apex + Eigen::Vector3d(0.8 * d.x(), 0.8 * d.y(), 0.9 * d.z()) +
        Eigen::Vector3d(3, -2, 1);  // And moved: measures are relative.
  }
  const std::vector<MeshFrameMotion> motion = MeasureMeshMotion({ed, es});
  ASSERT_EQ(motion.size(), 2u);
  EXPECT_NEAR(motion[0].length_mm, 60.0, 1e-9);
  EXPECT_NEAR(motion[1].length_mm, 54.0, 1e-9);
  EXPECT_EQ(motion[0].longitudinal_shortening_percent, 0.0);
  EXPECT_NEAR(motion[1].longitudinal_shortening_percent, 10.0, 1e-9);
  EXPECT_NEAR(motion[1].radial_contraction_percent, 20.0, 1e-9);
  EXPECT_NEAR(motion[1].volume_ml, 0.8 * 0.8 * 0.9 * motion[0].volume_ml, 1e-9);
  // Triangles of latitude rings: e_c nearly horizontal, (0.8^2 - 1) / 2;
  // along the meridians a mix of 0.8 (radial) and 0.9 (axial).
  EXPECT_NEAR(motion[0].gcs_percent, 0.0, 1e-12);
  EXPECT_NEAR(motion[1].gcs_percent, -18.0, 0.3);
  EXPECT_LT(motion[1].gls_percent, 100 * (0.81 - 1) / 2);
  EXPECT_GT(motion[1].gls_percent, -18.0);
}

// A twist about the axis growing toward the rim shears but barely
// stretches: |GCS| and |GLS| well under the shear.
TEST(MeshMotionTest, TwistBarelyStrains) {
  const TriangleMesh ed = Cavity();
  TriangleMesh twisted = ed;
  for (Eigen::Vector3d& p : twisted.points) {
    const double angle = 0.002 * (p.z() + 40.0);  // 0.12 rad at the rim.
    p = Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ()) * p;
  }
  const std::vector<MeshFrameMotion> motion = MeasureMeshMotion({ed, twisted});
  EXPECT_NEAR(motion[1].gcs_percent, 0.0, 0.2);
  EXPECT_NEAR(motion[1].gls_percent, 0.0, 0.5);
}

TEST(MeshMotionTest, ClosedMeshHasNoRimToMeasureFrom) {
  const TriangleMesh closed = CapBoundaryLoops(Cavity());
  EXPECT_THROW(MeasureMeshMotion({closed}), InputError);
}

}  // namespace
}  // namespace pfdm
