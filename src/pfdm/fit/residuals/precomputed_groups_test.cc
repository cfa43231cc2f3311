#include "pfdm/fit/residuals/precomputed_groups.h"

#include <memory>
#include <random>
#include <vector>

#include "gtest/gtest.h"
#include "pfdm/fit/stages/fitter.h"
#include "pfdm/model/model.h"
#include "pfdm/testing/test_models.h"

namespace pfdm {
namespace {

constexpr int kSizes[5] = {3, 4, kNumFunctions, kNumFunctions, kNumFunctions};

// Groups of different sizes over the same five whole blocks, enough points
// in all (6,500) for PrecomputedGroups to use its threads.
struct Groups {
  Groups() {
    globals = knot0 = knot1 = DefaultFunctionValues();
    globals[kA0] = 60.0;
    knot0[kA1] = 0.4, knot1[kA1] = 0.45, knot1[kTau] = 0.1;
    Eigen::Map<Eigen::Vector4d>(quaternion).normalize();
    std::mt19937 random(3);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const FunctionMask mask = ModelConfig::Paper(17).FreeMask();
    for (int size : {400, 3000, 900, 700, 1500}) {
      std::vector<PointSample> samples;
      for (int i = 0; i < size; ++i) {
        samples.emplace_back(
            Eigen::Vector3d(30 * unit(random), 30 * unit(random),
                            30 * unit(random)),
            1.2 * unit(random), 3.1 * unit(random), 0.5 + 0.5 * unit(random));
      }
      residuals.push_back(
          std::make_unique<PointGroupResidual>(std::move(samples), mask, true));
    }
  }
  // A PrecomputedGroups over every group.
  std::unique_ptr<PrecomputedGroups> Precomputed(int num_threads,
                                                 bool speculate) {
    auto precomputed =
        std::make_unique<PrecomputedGroups>(num_threads, speculate);
    for (const auto& group : residuals) precomputed->Add(group.get(), blocks());
    return precomputed;
  }
  std::vector<double*> blocks() {
    return {center, quaternion, globals.data(), knot0.data(), knot1.data()};
  }
  // Residuals then Jacobians of group g, evaluated by `group`.
  std::vector<double> Evaluate(const PointGroupResidual& group,
                               bool with_jacobians) {
    const std::vector<double*> parameters = blocks();
    const int m = group.num_residuals();
    std::vector<double> out(m * (1 + 3 + 4 + 3 * kNumFunctions));
    double* jacobians[5];
    for (int b = 0, at = m; b < 5; at += m * kSizes[b], ++b) {
      jacobians[b] = out.data() + at;
    }
    EXPECT_TRUE(group.Evaluate(parameters.data(), out.data(),
                               with_jacobians ? jacobians : nullptr));
    if (!with_jacobians) out.resize(m);
    return out;
  }

  double center[3] = {1.0, 2.0, 3.0};
  double quaternion[4] = {0.9, 0.1, -0.3, 0.2};
  FunctionValues globals, knot0, knot1;
  std::vector<std::unique_ptr<PointGroupResidual>> residuals;
};

TEST(PrecomputedGroupsTest, HandsOutWhatEachGroupWouldCompute) {
  for (bool with_jacobians : {true, false}) {
    Groups reference, groups;
    const auto precomputed = groups.Precomputed(3, false);
    precomputed->PrepareForEvaluation(with_jacobians, true);
    for (size_t g = 0; g < groups.residuals.size(); ++g) {
      EXPECT_EQ(groups.Evaluate(*groups.residuals[g], with_jacobians),
                reference.Evaluate(*reference.residuals[g], with_jacobians))
          << "group " << g << (with_jacobians ? " with" : " without")
          << " Jacobians";
    }
  }
}

// Speculating, a candidate is evaluated with its Jacobians, which serve
// Ceres' next request once it accepts the step; its residuals are the
// square-root form's norm, the same cost to round-off.  A rejected
// candidate, or a step that lowered the cost by under kSpeculateAbove,
// ends the speculation.
TEST(PrecomputedGroupsTest, SpeculatesWhileStepsAreAcceptedAndLarge) {
  Groups reference, groups;
  const auto precomputed = groups.Precomputed(2, true);
  // Smaller a1 lowers these groups' cost (2 % from 0.45 to 0.35).
  auto move_to = [&](double a1) {
    groups.knot1[kA1] = reference.knot1[kA1] = a1;
  };
  precomputed->PrepareForEvaluation(true, true);  // The start.
  move_to(0.35);                                  // A candidate,
  precomputed->PrepareForEvaluation(false, true);
  EXPECT_EQ(precomputed->jacobian_evaluations(), 2);
  for (size_t g = 0; g < groups.residuals.size(); ++g) {
    const double norm = groups.Evaluate(*groups.residuals[g], false)[0];
    EXPECT_NEAR(norm, reference.Evaluate(*reference.residuals[g], false)[0],
                1e-12 * norm)
        << "group " << g;
  }
  precomputed->PrepareForEvaluation(true, false);  // accepted.
  EXPECT_EQ(precomputed->jacobian_evaluations(), 2);
  for (size_t g = 0; g < groups.residuals.size(); ++g) {
    EXPECT_EQ(groups.Evaluate(*groups.residuals[g], true),
              reference.Evaluate(*reference.residuals[g], true))
        << "group " << g;
  }
  move_to(0.3);  // A candidate, then another: the first was rejected.
  precomputed->PrepareForEvaluation(false, true);
  move_to(0.32);
  precomputed->PrepareForEvaluation(false, true);
  EXPECT_EQ(precomputed->jacobian_evaluations(), 3);
  EXPECT_EQ(precomputed->residual_evaluations(), 1);
  precomputed->PrepareForEvaluation(true, false);  // Accepted at last,
  EXPECT_EQ(precomputed->jacobian_evaluations(), 4);
  move_to(0.32 - 1e-9);  // so the next candidate speculates; it lowers
  precomputed->PrepareForEvaluation(false, true);  // the cost by a hair,
  precomputed->PrepareForEvaluation(true, false);
  move_to(0.32 - 2e-9);  // and the one after does not speculate.
  precomputed->PrepareForEvaluation(false, true);
  EXPECT_EQ(precomputed->jacobian_evaluations(), 5);
  EXPECT_EQ(precomputed->residual_evaluations(), 2);
}

// Asked at other values than it precomputed (no PrepareForEvaluation in
// between), a group computes afresh rather than hand out a stale result.
TEST(PrecomputedGroupsTest, OtherParameterValuesAreComputedAfresh) {
  Groups groups;
  const auto precomputed = groups.Precomputed(2, false);
  precomputed->PrepareForEvaluation(true, true);
  groups.knot1[kA1] += 0.01;
  groups.center[2] -= 0.5;
  Groups fresh;
  fresh.knot1[kA1] += 0.01;
  fresh.center[2] -= 0.5;
  for (size_t g = 0; g < groups.residuals.size(); ++g) {
    EXPECT_EQ(groups.Evaluate(*groups.residuals[g], true),
              fresh.Evaluate(*fresh.residuals[g], true))
        << "group " << g;
  }
}

// A whole fit with two threads, whose groups are precomputed, against one
// thread, whose are not: the same frames to round-off (Ceres sums the
// blocks' gradients in another order).
TEST(PrecomputedGroupsTest, TwoThreadsFitWhatOneFits) {
  const Phantom phantom = MakeTestPhantom(6000, 2);
  FitOptions options;
  const SequenceFit one =
      FitSequence(phantom.points, ModelConfig::Paper(17), options);
  options.solver.num_threads = 2;
  const SequenceFit two =
      FitSequence(phantom.points, ModelConfig::Paper(17), options);
  for (int frame = 0; frame < 2; ++frame) {
    EXPECT_NEAR(two.frames[frame].rms_mm, one.frames[frame].rms_mm, 1e-9);
    for (int k = 0; k < 17; ++k) {
      for (int f = 0; f < kNumFunctions; ++f) {
        EXPECT_NEAR(two.frames[frame].state.knots[k][f],
                    one.frames[frame].state.knots[k][f], 1e-7)
            << "frame " << frame << " knot " << k << " f " << f;
      }
    }
  }
}

}  // namespace
}  // namespace pfdm
