#include "pfdm/fit/problem/gauss_newton_step.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include "Eigen/Dense"
#include "Eigen/SparseCore"
#include "ceres/crs_matrix.h"
#include "ceres/manifold.h"
#include "pfdm/solvers/normal_matrix.h"

namespace pfdm {
namespace {

// Ceres' Solver::Options::min_relative_decrease: a step is kept when the
// cost falls by at least this share of what its linear model predicts.
constexpr double kMinRelativeDecrease = 1e-3;

// The step d in the free blocks' tangent coordinates, in their order, and
// the decrease of the cost its linear model predicts, -(g.d + |J d|^2 / 2).
struct Step {
  double cost = 0.0;
  Eigen::VectorXd d;
  double predicted_decrease = 0.0;
};

bool SolveStep(double radius, ceres::Problem* problem,
               const std::vector<double*>& blocks, Step* step) {
  ceres::Problem::EvaluateOptions options;
  options.parameter_blocks = blocks;
  std::vector<double> gradient;
  ceres::CRSMatrix jacobian;
  if (!problem->Evaluate(options, &step->cost, nullptr, &gradient, &jacobian)) {
    return false;
  }
  const auto j = SparseView(jacobian);
  Eigen::MatrixXd normal = GaussNewtonMatrix(jacobian);
  for (int i = 0; i < normal.rows(); ++i) {
    const double diagonal = normal(i, i);
    const double root = 1.0 + std::sqrt(std::max(0.0, diagonal));
    normal(i, i) += std::max(diagonal, 1e-6 * root * root) / radius;
  }
  const Eigen::LDLT<Eigen::MatrixXd> factor(normal);
  if (factor.info() != Eigen::Success) return false;
  const Eigen::Map<const Eigen::VectorXd> g(gradient.data(), gradient.size());
  step->d = factor.solve(-g);
  step->predicted_decrease =
      -(g.dot(step->d) + 0.5 * (j * step->d).squaredNorm());
  return step->d.allFinite();
}

// x [+] d by the block's manifold (plain addition without one), clamped to
// the block's bounds.
void MoveBlock(const double* tangent_step, double* block,
               ceres::Problem* problem) {
  const int size = problem->ParameterBlockSize(block);
  std::vector<double> moved(size);
  const ceres::Manifold* manifold = problem->GetManifold(block);
  if (manifold != nullptr) {
    manifold->Plus(block, tangent_step, moved.data());
  } else {
    for (int i = 0; i < size; ++i) moved[i] = block[i] + tangent_step[i];
  }
  for (int i = 0; i < size; ++i) {
    block[i] = std::clamp(moved[i], problem->GetParameterLowerBound(block, i),
                          problem->GetParameterUpperBound(block, i));
  }
}

}  // namespace

bool TakeGaussNewtonStep(double radius, ceres::Problem* problem,
                         const std::function<bool()>& verify) {
  std::vector<double*> all, blocks;
  problem->GetParameterBlocks(&all);
  for (double* block : all) {
    if (!problem->IsParameterBlockConstant(block)) blocks.push_back(block);
  }
  if (blocks.empty()) return false;
  Step step;
  if (!SolveStep(radius, problem, blocks, &step) ||
      !(step.predicted_decrease > 0.0)) {
    return false;
  }
  std::vector<std::vector<double>> before;
  int at = 0;
  for (double* block : blocks) {
    before.emplace_back(block, block + problem->ParameterBlockSize(block));
    MoveBlock(step.d.data() + at, block, problem);
    at += problem->ParameterBlockTangentSize(block);
  }
  if (verify && !verify()) return true;
  // Kept only where Ceres would keep it: a step the problem's nonlinearity
  // turns into a rise of the cost is not taken.
  double cost = 0.0;
  ceres::Problem::EvaluateOptions options;
  options.parameter_blocks = blocks;
  if (problem->Evaluate(options, &cost, nullptr, nullptr, nullptr) &&
      (step.cost - cost) >= kMinRelativeDecrease * step.predicted_decrease) {
    return true;
  }
  for (size_t b = 0; b < blocks.size(); ++b) {
    std::copy(before[b].begin(), before[b].end(), blocks[b]);
  }
  return false;
}

}  // namespace pfdm
