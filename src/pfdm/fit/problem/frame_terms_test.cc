#include "pfdm/fit/problem/frame_terms.h"

#include <cmath>
#include <vector>

#include "gtest/gtest.h"
#include "pfdm/fit/correspondence/correspondence.h"
#include "pfdm/testing/test_models.h"

namespace pfdm {
namespace {

// A tracked frame of the spheroid's own points moved 0.8 mm along their
// normals (signs alternating) and 0.3 mm across, solved without
// regularizers.  Its covariance with the wall's normals weighs the data's
// rows by the sd across them, the frame's pooled one without: the two
// differ by the ratio of their squares where the data alone fix a
// parameter.
TEST(FrameTermsTest, ATrackedFramesRowsAreWeighedByTheirSdAcrossTheWall) {
  Model model = TestSpheroid(5);
  std::vector<MaterialPoint> material;
  for (double u = -1.3; u < 0.5; u += 0.1) {
    for (double v = -M_PI; v < M_PI; v += 0.2) material.push_back({u, v});
  }
  std::vector<Eigen::Vector3d> at;
  const std::vector<Eigen::Vector3d> normals =
      SurfaceNormals(model, material, &at);
  std::vector<Eigen::Vector3d> points;
  for (size_t i = 0; i < at.size(); ++i) {
    const double sign = i % 2 == 0 ? 1.0 : -1.0;
    const Eigen::Vector3d across =
        normals[i].cross(Eigen::Vector3d::UnitZ()).normalized();
    points.push_back(at[i] + sign * (0.8 * normals[i] + 0.3 * across));
  }
  FitOptions options;
  options.prior_weight = 0.0;
  options.smoothness_weight = 0.0;
  const std::vector<Eigen::Vector3d> no_normals(points.size(),
                                                Eigen::Vector3d::Zero());
  const ModelState start = model.state;
  const FrameInputs frame{
      points, material, no_normals, std::nullopt, FrameKind::kTracked,
      start,  start};
  FrameProblem problem(FrameKind::kTracked, options, &model);
  BuildFrameProblem(frame, &problem);
  ASSERT_TRUE(problem.Solve().usable);

  const FrameCovariance pooled = problem.Covariance(frame);
  const FrameCovariance split = problem.Covariance(frame, &normals);
  ASSERT_TRUE(pooled.computed && split.computed);
  EXPECT_EQ(pooled.tangent_sigma_mm, 0.0);
  EXPECT_EQ(pooled.NoiseSigma(), pooled.sigma_mm);
  // The fit takes little of either: the offsets alternate point by point.
  EXPECT_NEAR(split.normal_sigma_mm, 0.8, 0.08);
  EXPECT_NEAR(split.tangent_sigma_mm, 0.3 / std::sqrt(2.0), 0.03);
  EXPECT_EQ(split.NoiseSigma(), split.tangent_sigma_mm);
  EXPECT_EQ(split.sigma_mm, pooled.sigma_mm);
  const double ratio = split.tangent_sigma_mm * split.tangent_sigma_mm /
                       (pooled.sigma_mm * pooled.sigma_mm);
  EXPECT_LT(ratio, 0.2);
  // The knots' radii and twist, which the data alone fix; the pose and the
  // axis offsets share their variance with the spin and axis gauges.
  int checked = 0;
  for (int i = 0; i < split.covariance.rows(); ++i) {
    const CovarianceEntry& e = pooled.entries[i];
    if (e.kind != CovarianceEntry::Kind::kKnot ||
        (e.function != kA1 && e.function != kA2 && e.function != kTau)) {
      continue;
    }
    ++checked;
    EXPECT_NEAR(split.covariance(i, i), ratio * pooled.covariance(i, i),
                0.01 * ratio * pooled.covariance(i, i))
        << e.Name();
  }
  EXPECT_EQ(checked, 15);
}

}  // namespace
}  // namespace pfdm
