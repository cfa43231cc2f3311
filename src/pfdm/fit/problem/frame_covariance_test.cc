#include "pfdm/fit/problem/frame_covariance.h"

#include <random>

#include "Eigen/Dense"
#include "ceres/ceres.h"
#include "gtest/gtest.h"
#include "pfdm/model/parameter_function.h"

namespace pfdm {
namespace {

// r = c0 + c1 x - y, or with `sum` only c0 + c1 seen: r = (c0 + c1) x - y.
struct LineResidual {
  LineResidual(double x, double y, bool sum) : x(x), y(y), sum(sum) {}
  template <typename T>
  bool operator()(const T* c, T* r) const {
    r[0] = sum ? (c[0] + c[1]) * x - y : c[0] + c[1] * x - y;
    return true;
  }
  double x, y;
  bool sum;
};

struct LineProblem {
  std::array<double, 2> c{0.0, 0.0};
  ceres::Problem problem;
  Eigen::MatrixXd design;
  std::vector<ceres::ResidualBlockId> data;
};

// y = 1 + 2 x + noise of 0.3 at 200 x in [-1, 1], solved.
void MakeLine(bool sum, LineProblem* line) {
  std::mt19937 random(7);
  std::normal_distribution<double> noise(0.0, 0.3);
  line->design.resize(200, 2);
  for (int i = 0; i < 200; ++i) {
    const double x = -1.0 + 2.0 * i / 199.0;
    line->design.row(i) << 1.0, x;
    line->data.push_back(line->problem.AddResidualBlock(
        new ceres::AutoDiffCostFunction<LineResidual, 1, 2>(
            new LineResidual(x, 1.0 + 2.0 * x + noise(random), sum)),
        nullptr, line->c.data()));
  }
  ceres::Solver::Options options;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &line->problem, &summary);
}

// ceres::Covariance's DENSE_SVD pseudo-inverse of the line's J'J, times
// sigma^2: what BlockCovariance must give.
Eigen::Matrix2d CeresCovariance(LineProblem* line, double sigma) {
  ceres::Covariance::Options options;
  options.algorithm_type = ceres::DENSE_SVD;
  options.null_space_rank = -1;
  options.min_reciprocal_condition_number = kMinReciprocalCondition;
  ceres::Covariance covariance(options);
  const std::vector<const double*> blocks = {line->c.data()};
  Eigen::Matrix2d values;
  EXPECT_TRUE(covariance.Compute(blocks, &line->problem));
  EXPECT_TRUE(covariance.GetCovarianceMatrix(blocks, values.data()));
  return sigma * sigma * values;
}

std::vector<CovarianceBlock> LineBlocks(LineProblem* line) {
  using Kind = CovarianceEntry::Kind;
  return {
      {line->c.data(), {{Kind::kGlobal, -1, kA0}, {Kind::kGlobal, -1, kA1}}}};
}

// The length draws' mean and sample variance (n - 1), 0 where too few.
TEST(FrameCovarianceTest, LengthDrawsGiveTheirMeanAndSampleVariance) {
  FrameCovariance covariance;
  EXPECT_EQ(covariance.LengthNoiseMean(), 0.0);
  EXPECT_EQ(covariance.LengthNoiseVariance(), 0.0);
  covariance.length_noise = {0.02};
  EXPECT_EQ(covariance.LengthNoiseMean(), 0.02);
  EXPECT_EQ(covariance.LengthNoiseVariance(), 0.0);
  covariance.length_noise = {0.01, -0.01, 0.03};
  EXPECT_NEAR(covariance.LengthNoiseMean(), 0.01, 1e-15);
  EXPECT_NEAR(covariance.LengthNoiseVariance(), 4e-4, 1e-15);
}

// The apex's variance along the axis is the centre's there, and adds to
// the length draws' as a share of the squared length.
TEST(FrameCovarianceTest, ApexVarianceIsTheCentresAlongTheAxis) {
  using Kind = CovarianceEntry::Kind;
  Model model;
  // A quarter turn about x: the long axis along -y.
  model.state.quaternion = {std::sqrt(0.5), std::sqrt(0.5), 0.0, 0.0};
  ASSERT_NEAR(model.Rotation().col(2).y(), -1.0, 1e-15);
  FrameCovariance covariance;
  covariance.computed = true;
  covariance.entries = {{Kind::kCenter, -1, 0},
                        {Kind::kCenter, -1, 1},
                        {Kind::kCenter, -1, 2},
                        {Kind::kGlobal, -1, kA0}};
  Eigen::Matrix4d sigma;
  sigma << 1.0, 0.5, 0.2, 0.1,  //
      0.5, 4.0, 0.3, 0.7,       //
      0.2, 0.3, 9.0, 0.4,       //
      0.1, 0.7, 0.4, 2.0;
  covariance.covariance = sigma;
  EXPECT_NEAR(ApexAxialVariance(covariance, model), 4.0, 1e-12);
  // Tilted: axis' S axis over the centre's block.
  model.state.quaternion = {std::cos(0.3), 0.0, std::sin(0.3), 0.0};
  const Eigen::Vector3d axis = model.Rotation().col(2);
  EXPECT_NEAR(ApexAxialVariance(covariance, model),
              axis.dot(sigma.topLeftCorner<3, 3>() * axis), 1e-12);
  // The pose held: nothing moves the apex.
  covariance.entries = {{Kind::kGlobal, -1, kA0}};
  covariance.covariance = Eigen::Matrix<double, 1, 1>(2.0);
  EXPECT_EQ(ApexAxialVariance(covariance, model), 0.0);
  covariance.length_noise = {0.01, -0.01, 0.03};
  covariance.apex_length_variance = 1e-4;
  EXPECT_NEAR(covariance.LengthNoiseVariance(), 5e-4, 1e-15);
}

// A full-rank linear problem: sigma^2 (X'X)^-1, to round-off, and what
// ceres::Covariance gives.
TEST(FrameCovarianceTest, LinearProblemGivesTheTextbookCovariance) {
  LineProblem line;
  MakeLine(false, &line);
  const FrameCovariance covariance =
      BlockCovariance(&line.problem, LineBlocks(&line), 0.3, 198.0);
  ASSERT_TRUE(covariance.computed);
  EXPECT_EQ(covariance.rank_deficiency, 0);
  const Eigen::Matrix2d expected =
      0.09 * (line.design.transpose() * line.design).inverse();
  EXPECT_LT((covariance.covariance - expected).norm(), 1e-10 * expected.norm());
  EXPECT_LT((covariance.covariance - CeresCovariance(&line, 0.3)).norm(),
            1e-10 * expected.norm());
  EXPECT_EQ(covariance.IndexOf(CovarianceEntry::Kind::kGlobal, -1, kA1), 1);
}

// Only c0 + c1 is seen: no crash, the difference reported as the deficient
// direction and left out (c0 - c1 has variance 0 in the pseudo-inverse),
// the sum's variance what the data give it.
TEST(FrameCovarianceTest, RankDeficientProblemReportsTheDirection) {
  LineProblem line;
  MakeLine(true, &line);
  const FrameCovariance covariance =
      BlockCovariance(&line.problem, LineBlocks(&line), 0.3, 199.0);
  ASSERT_TRUE(covariance.computed);
  EXPECT_EQ(covariance.rank_deficiency, 1);
  ASSERT_EQ(covariance.deficient_directions.size(), 1u);
  const std::string& direction = covariance.deficient_directions[0];
  EXPECT_NE(direction.find("a0 "), std::string::npos) << direction;
  EXPECT_NE(direction.find("a1 "), std::string::npos) << direction;
  const Eigen::Vector2d sum(1.0, 1.0), difference(1.0, -1.0);
  const double sum_x2 = line.design.col(1).squaredNorm();
  EXPECT_NEAR(sum.dot(covariance.covariance * sum), 0.09 / sum_x2,
              1e-9 / sum_x2);
  EXPECT_NEAR(difference.dot(covariance.covariance * difference), 0.0, 1e-12);
  const Eigen::Matrix2d ceres_covariance = CeresCovariance(&line, 0.3);
  EXPECT_LT((covariance.covariance - ceres_covariance).norm(),
            1e-8 * ceres_covariance.norm());
}

// r = s (c[index] - target): a prior on one coefficient, or with a large s
// a stiff gauge-like constraint.
struct CoefficientPrior {
  CoefficientPrior(double s, int index, double target)
      : s(s), index(index), target(target) {}
  template <typename T>
  bool operator()(const T* c, T* r) const {
    r[0] = s * (c[index] - target);
    return true;
  }
  double s;
  int index;
  double target;
};

void AddPrior(double s, int index, LineProblem* line) {
  line->problem.AddResidualBlock(
      new ceres::AutoDiffCostFunction<CoefficientPrior, 1, 2>(
          new CoefficientPrior(s, index, line->c[index])),
      nullptr, line->c.data());
}

// x is symmetric about 0, so the design's columns are orthogonal and a
// prior s on c1 leaves the data's hat matrix a trace of
// 1 + x'x / (x'x + s^2); without it, 2, the parameters' count.
TEST(FrameCovarianceTest, EffectiveParametersAreTheDataHatMatrixTrace) {
  LineProblem line;
  MakeLine(false, &line);
  const double x2 = line.design.col(1).squaredNorm();
  EXPECT_NEAR(
      BlockCovariance(&line.problem, LineBlocks(&line), 1.0, 0.0, line.data)
          .effective_parameters,
      2.0, 1e-9);
  AddPrior(std::sqrt(x2), 1, &line);
  const FrameCovariance covariance =
      BlockCovariance(&line.problem, LineBlocks(&line), 1.0, 0.0, line.data);
  EXPECT_NEAR(covariance.effective_parameters, 1.5, 1e-9);
  EXPECT_NEAR(covariance.covariance(1, 1), 1.0 / (2.0 * x2), 1e-12 / x2);
}

// A constraint 1e6 times stiffer than the data (as the gauge residuals
// are) is no rank deficiency: the unit diagonal scaling keeps the Cholesky
// path, whose result is the textbook (X'X + s^2 e0 e0')^-1 and what
// ceres::Covariance gives.
TEST(FrameCovarianceTest, StiffConstraintIsNotADeficiency) {
  LineProblem line;
  MakeLine(false, &line);
  const double s = 1e6 * std::sqrt(line.design.col(0).squaredNorm());
  AddPrior(s, 0, &line);
  const FrameCovariance covariance =
      BlockCovariance(&line.problem, LineBlocks(&line), 0.3, 198.0);
  ASSERT_TRUE(covariance.computed);
  EXPECT_EQ(covariance.rank_deficiency, 0);
  Eigen::Matrix2d normal = line.design.transpose() * line.design;
  normal(0, 0) += s * s;
  const Eigen::Matrix2d expected = 0.09 * normal.inverse();
  EXPECT_NEAR(covariance.covariance(1, 1), expected(1, 1),
              1e-9 * expected(1, 1));
  EXPECT_NEAR(covariance.covariance(0, 0), expected(0, 0),
              1e-6 * expected(0, 0));
}

TEST(FrameCovarianceTest, KnotSdReadsTheKnotOrTheGlobalEntry) {
  using Kind = CovarianceEntry::Kind;
  ModelConfig config = ModelConfig::Paper(5);
  FrameCovariance covariance;
  covariance.computed = true;
  covariance.entries = {{Kind::kGlobal, -1, kA0}, {Kind::kKnot, 2, kTau}};
  covariance.covariance = Eigen::Vector2d(4.0, 0.25).asDiagonal();
  ASSERT_EQ(config.modes[kTau], FunctionMode::kFree);
  ASSERT_NE(config.modes[kA0], FunctionMode::kFree);
  EXPECT_DOUBLE_EQ(covariance.KnotSd(config, kA0, 3), 2.0);
  EXPECT_DOUBLE_EQ(covariance.KnotSd(config, kTau, 2), 0.5);
  EXPECT_DOUBLE_EQ(covariance.KnotSd(config, kTau, 1), 0.0);  // Held.
  EXPECT_EQ(covariance.entries[1].Name(), "tau[2]");
}

// The data's sigma: point-to-plane points count one coordinate, the others
// three; sum of squares over (count - parameters).
TEST(FrameCovarianceTest, DataSigmaCountsEachPointsCoordinates) {
  Model model = Model::Uniform(ModelConfig::Paper(5), DefaultFunctionValues());
  const std::vector<MaterialPoint> material = {{0.1, 0.2, 0.0},
                                               {-0.3, 1.0, 0.0}};
  const std::vector<Eigen::Vector3d> at = WorldPoints(model, material);
  const Eigen::Vector3d normal = Eigen::Vector3d(0, 0, 1);
  const std::vector<Eigen::Vector3d> points = {
      at[0] + Eigen::Vector3d(1.0, 2.0, 2.0), at[1] + Eigen::Vector3d(5, 5, 3)};
  double sigma = 0.0, dof = 0.0;
  DataSigma(model, points, material, {Eigen::Vector3d::Zero(), normal}, "none",
            1.0, 1, &sigma, &dof);
  EXPECT_DOUBLE_EQ(dof, 3.0);  // 3 + 1 - 1.
  EXPECT_NEAR(sigma, std::sqrt((9.0 + 9.0) / 3.0), 1e-9);
}

}  // namespace
}  // namespace pfdm
