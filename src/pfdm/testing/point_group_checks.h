// Checks of a PointGroupResidual against its points one by one, shared by
// the tests of its rows (point_group_residual_test.cc) and of its Gram
// matrices (point_group_gram_test.cc).
#ifndef PFDM_TESTING_POINT_GROUP_CHECKS_H_
#define PFDM_TESTING_POINT_GROUP_CHECKS_H_

#include <array>
#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include "gtest/gtest.h"
#include "pfdm/fit/residuals/point_group_residual.h"
#include "pfdm/fit/residuals/square_root_form.h"
#include "pfdm/model/model.h"

namespace pfdm {

constexpr int kGroupBlockSizes[5] = {3, 4, kNumFunctions, kNumFunctions,
                                     kNumFunctions};

// Which blocks a group varies, and the free functions of the globals
// (empty: the whole block) and of each knot.
struct GroupCase {
  std::array<bool, 5> varied;
  std::vector<int> globals_free, knot0_free, knot1_free;
  bool point_to_plane = true;  // Every fourth point against a plane.
  int mid_wall_first = 0;      // The first this many points at w = 0.
};

// A group against its points one by one: the square-root form must give
// the stacked rows' cost, gradient and J^T J.
inline void ExpectStackedNormalEquations(const GroupCase& group_case) {
  std::mt19937 random(5);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const FunctionMask mask = ModelConfig::Paper(17).FreeMask();
  FunctionValues globals = DefaultFunctionValues(), knot0, knot1;
  globals[kA0] = 60.0;
  knot0 = knot1 = globals;
  knot0[kA1] = 0.4, knot1[kA1] = 0.45, knot0[kB0] = 2.0, knot1[kTau] = 0.1;
  knot1[kB2] = -1.5, knot1[kB3] = 0.7;
  knot0[kH] = knot1[kH] = 8.0;  // Off the mid-wall, ds/df fills in.
  const std::vector<int>* lists[3] = {
      &group_case.globals_free, &group_case.knot0_free, &group_case.knot1_free};
  FunctionValues* values[3] = {&globals, &knot0, &knot1};
  std::unique_ptr<FreeEntries> entries[3];
  std::array<const FreeEntries*, 3> compact_entries = {};
  for (int b = 0; b < 3; ++b) {
    if (lists[b]->empty()) continue;
    entries[b] = std::make_unique<FreeEntries>(values[b]->data(), *lists[b]);
    compact_entries[b] = entries[b].get();
  }
  double center[3] = {1, 2, 3};
  double quaternion[4] = {0.9, 0.1, -0.3, 0.2};
  Eigen::Map<Eigen::Vector4d>(quaternion).normalize();

  std::vector<PointSample> samples;
  for (int i = 0; i < 60; ++i) {
    const Eigen::Vector3d data(30 * unit(random), 30 * unit(random),
                               30 * unit(random));
    const double u = 1.2 * unit(random), v = 3.1 * unit(random);
    const double w =
        i < group_case.mid_wall_first ? 0.0 : 0.5 + 0.5 * unit(random);
    samples.push_back(
        group_case.point_to_plane && i % 4 == 0
            ? PointSample(data, u, v, w, Eigen::Vector3d(0, 0.6, 0.8))
            : PointSample(data, u, v, w));
  }
  const PointGroupResidual group(samples, mask, true, compact_entries,
                                 group_case.varied);
  ASSERT_TRUE(group.compressed());

  // The columns of each varied block: the whole block's columns it keeps.
  std::vector<std::vector<int>> kept(5);
  for (int b = 0; b < 5; ++b) {
    if (!group_case.varied[b]) continue;
    if (b >= 2 && compact_entries[b - 2]) {
      kept[b] = *lists[b - 2];
    } else {
      for (int c = 0; c < kGroupBlockSizes[b]; ++c) kept[b].push_back(c);
    }
  }
  int n = 0;
  for (const auto& columns : kept) n += static_cast<int>(columns.size());
  ASSERT_EQ(group.num_residuals(), n + 1);

  // The stacked rows, from the per-point residual on whole blocks.
  int rows = 0;
  for (const PointSample& sample : samples) rows += sample.num_residuals();
  Eigen::MatrixXd j(rows, n);
  Eigen::VectorXd r(rows);
  int row = 0;
  const double* whole[] = {center, quaternion, globals.data(), knot0.data(),
                           knot1.data()};
  for (const PointSample& sample : samples) {
    const int m = sample.num_residuals();
    std::vector<double> residual(m);
    std::vector<std::vector<double>> blocks(5);
    double* jacobians[5];
    for (int b = 0; b < 5; ++b) {
      blocks[b].resize(m * kGroupBlockSizes[b]);
      jacobians[b] = blocks[b].data();
    }
    EvaluatePointSample(sample, mask, true, whole, residual.data(), jacobians);
    for (int i = 0; i < m; ++i) {
      r[row + i] = residual[i];
      int column = 0;
      for (int b = 0; b < 5; ++b) {
        for (int c : kept[b]) {
          j(row + i, column++) = blocks[b][i * kGroupBlockSizes[b] + c];
        }
      }
    }
    row += m;
  }

  const double* compact[5] = {center, quaternion, globals.data(), knot0.data(),
                              knot1.data()};
  for (int b = 0; b < 3; ++b) {
    if (entries[b]) compact[2 + b] = entries[b]->parameters();
  }
  std::vector<double> z(n + 1);
  ASSERT_TRUE(group.Evaluate(compact, z.data(), nullptr));
  EXPECT_NEAR(z[0], r.norm(), 1e-12 * r.norm());
  for (int i = 1; i <= n; ++i) EXPECT_EQ(z[i], 0.0);

  std::vector<RowMajorMatrix> jacobian_blocks(5);
  double* jacobians[5] = {};
  for (int b = 0; b < 5; ++b) {
    if (!group_case.varied[b]) continue;
    jacobian_blocks[b].resize(n + 1, group.parameter_block_sizes()[b]);
    jacobians[b] = jacobian_blocks[b].data();
  }
  ASSERT_TRUE(group.Evaluate(compact, z.data(), jacobians));
  Eigen::MatrixXd jc(n + 1, n);
  int column = 0;
  for (int b = 0; b < 5; ++b) {
    if (!group_case.varied[b]) continue;
    jc.middleCols(column, jacobian_blocks[b].cols()) = jacobian_blocks[b];
    column += static_cast<int>(jacobian_blocks[b].cols());
  }
  const Eigen::VectorXd rc = Eigen::Map<Eigen::VectorXd>(z.data(), n + 1);
  const double scale = j.squaredNorm();
  EXPECT_LT((jc.transpose() * jc - j.transpose() * j).norm(), 1e-11 * scale);
  EXPECT_LT((jc.transpose() * rc - j.transpose() * r).norm(),
            1e-11 * std::sqrt(scale) * r.norm());
  EXPECT_NEAR(rc.squaredNorm(), r.squaredNorm(), 1e-11 * r.squaredNorm());
}

inline std::vector<int> FreeFunctions() {
  const FunctionMask mask = ModelConfig::Paper(17).FreeMask();
  std::vector<int> free;
  for (int f = 0; f < kNumFunctions; ++f) {
    if ((mask >> f) & 1u) free.push_back(f);
  }
  return free;
}

}  // namespace pfdm

#endif  // PFDM_TESTING_POINT_GROUP_CHECKS_H_
