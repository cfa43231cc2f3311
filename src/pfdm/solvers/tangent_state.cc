// The integrator's state on the problem's free blocks; see tangent_state.h.
#include "pfdm/solvers/tangent_state.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <unordered_set>
#include <vector>

#include "ceres/manifold.h"
#include "pfdm/solvers/normal_matrix.h"

namespace pfdm {
namespace {

// diag(J^T J), floored so that directions the residuals barely see are
// weakly damped instead of dividing by zero.
std::vector<double> JacobiDamping(const ceres::CRSMatrix& j) {
  std::vector<double> d(j.num_cols, 0.0);
  for (size_t k = 0; k < j.values.size(); ++k) {
    d[j.cols[k]] += j.values[k] * j.values[k];
  }
  const double largest = *std::max_element(d.begin(), d.end());
  for (double& x : d) x = std::max(x, 1e-12 * std::max(largest, 1e-300));
  return d;
}

}  // namespace

// The varied blocks in the order the residuals name them.  Not
// GetParameterBlocks's order, which is by address: the integrator's sums
// then ran in an order the allocator chose, and its rest test, which can
// fire on a plateau, fell either way (a 2,000-tag frame after other fits in
// one process rested at 3,367 steps, 1.2 % above the direct solve's RMS;
// alone it ran its 10,000).
State FreeBlocks(const ceres::Problem& problem) {
  State state;
  std::vector<ceres::ResidualBlockId> residuals;
  problem.GetResidualBlocks(&residuals);
  std::vector<double*> all;
  std::unordered_set<double*> seen;
  for (const ceres::ResidualBlockId residual : residuals) {
    std::vector<double*> blocks;
    problem.GetParameterBlocksForResidualBlock(residual, &blocks);
    for (double* block : blocks) {
      if (seen.insert(block).second) all.push_back(block);
    }
  }
  for (double* block : all) {
    if (problem.IsParameterBlockConstant(block)) continue;
    state.blocks.push_back(block);
    state.sizes.push_back(problem.ParameterBlockSize(block));
    state.offsets.push_back(state.tangent_size);
    state.tangent_size += problem.ParameterBlockTangentSize(block);
  }
  return state;
}

// The cost and its tangent-space gradient (and the Jacobian if asked), all
// finite.  Ceres computes the Jacobian blocks for a gradient anyway; asking
// for the CRS matrix only adds its assembly.
bool Evaluate(ceres::Problem* problem, const State& state, int num_threads,
              bool jacobian, Evaluation* evaluation) {
  ceres::Problem::EvaluateOptions options;
  options.parameter_blocks = state.blocks;
  options.num_threads = num_threads;
  if (!problem->Evaluate(options, &evaluation->cost, nullptr,
                         &evaluation->gradient,
                         jacobian ? &evaluation->jacobian : nullptr)) {
    return false;
  }
  return std::isfinite(evaluation->cost) &&
         std::all_of(evaluation->gradient.begin(), evaluation->gradient.end(),
                     [](double g) { return std::isfinite(g); });
}

double Norm(const std::vector<double>& v) {
  double sum = 0.0;
  for (double x : v) sum += x * x;
  return std::sqrt(sum);
}

// The integrator's D: the chosen base times the caller's per-coordinate
// scales.  A scale that is not positive and finite would stop or reverse
// the motion, so it is refused.
std::optional<std::vector<double>> Damping(const ceres::Problem& problem,
                                           const State& state,
                                           const ceres::CRSMatrix& j,
                                           const SolverOptions& options,
                                           std::string* error) {
  std::vector<double> d = options.damping == DampingKind::kJacobi
                              ? JacobiDamping(j)
                              : std::vector<double>(j.num_cols, 1.0);
  for (size_t b = 0; b < state.blocks.size(); ++b) {
    const auto scale = options.damping_scale.find(state.blocks[b]);
    if (scale == options.damping_scale.end()) continue;
    const int tangent_size = problem.ParameterBlockTangentSize(state.blocks[b]);
    if (static_cast<int>(scale->second.size()) != tangent_size) {
      *error = "a damping scale lists " + std::to_string(scale->second.size()) +
               " entries for a block of tangent size " +
               std::to_string(tangent_size);
      return std::nullopt;
    }
    for (int i = 0; i < tangent_size; ++i) {
      const double s = scale->second[i];
      if (!(s > 0.0) || !std::isfinite(s)) {
        *error = "damping scales must be positive and finite, got " +
                 std::to_string(s);
        return std::nullopt;
      }
      d[state.offsets[b] + i] *= s;
    }
  }
  return d;
}

// lambda_max of D^-1/2 J^T J D^-1/2 by power iteration on the CRS Jacobian,
// from a start vector with no symmetry that could hide the top mode.
double LargestEigenvalue(const ceres::CRSMatrix& j,
                         const std::vector<double>& d) {
  std::vector<double> x(j.num_cols), z(j.num_cols);
  for (int c = 0; c < j.num_cols; ++c) x[c] = 1.0 + 0.5 * std::sin(c + 1.0);
  double lambda = 0.0;
  for (int iteration = 0; iteration < 100; ++iteration) {
    const double norm = Norm(x);
    if (norm == 0.0) break;
    for (int c = 0; c < j.num_cols; ++c) x[c] /= norm * std::sqrt(d[c]);
    const Eigen::VectorXd product = GaussNewtonProduct(
        j, Eigen::Map<const Eigen::VectorXd>(x.data(), j.num_cols));
    for (int c = 0; c < j.num_cols; ++c) z[c] = product[c] / std::sqrt(d[c]);
    const double next = Norm(z);
    const bool settled = std::abs(next - lambda) <= 1e-4 * next;
    lambda = next;
    x.swap(z);
    if (settled) break;
  }
  return lambda;
}

// out = x [+] delta through the block's manifold, then into its bounds, as
// Ceres moves a block.
bool PlusInBounds(const ceres::Problem& problem, double* block, int size,
                  const double* x, const double* delta, double* out) {
  if (const ceres::Manifold* manifold = problem.GetManifold(block)) {
    if (!manifold->Plus(x, delta, out)) return false;
  } else {
    for (int i = 0; i < size; ++i) out[i] = x[i] + delta[i];
  }
  for (int i = 0; i < size; ++i) {
    out[i] = std::clamp(out[i], problem.GetParameterLowerBound(block, i),
                        problem.GetParameterUpperBound(block, i));
  }
  return true;
}

// Moves every free block by its part of the tangent step.
bool Move(ceres::Problem* problem, const State& state,
          const std::vector<double>& step) {
  std::vector<double> moved;
  for (size_t b = 0; b < state.blocks.size(); ++b) {
    double* x = state.blocks[b];
    moved.resize(state.sizes[b]);
    if (!PlusInBounds(*problem, x, state.sizes[b], x,
                      step.data() + state.offsets[b], moved.data())) {
      return false;
    }
    std::copy(moved.begin(), moved.end(), x);
  }
  return true;
}

bool Place(ceres::Problem* problem, const State& state,
           const std::vector<double>& base, const std::vector<double>& delta) {
  std::vector<double> moved;
  int from = 0;
  for (size_t b = 0; b < state.blocks.size(); ++b) {
    moved.resize(state.sizes[b]);
    if (!PlusInBounds(*problem, state.blocks[b], state.sizes[b],
                      base.data() + from, delta.data() + state.offsets[b],
                      moved.data())) {
      return false;
    }
    std::copy(moved.begin(), moved.end(), state.blocks[b]);
    from += state.sizes[b];
  }
  return true;
}

void ClipIntoBounds(const ceres::Problem& problem, const State& state,
                    const std::vector<double>& base,
                    std::vector<double>* delta) {
  int from = 0;
  for (size_t b = 0; b < state.blocks.size(); ++b) {
    double* block = state.blocks[b];
    if (problem.GetManifold(block) == nullptr) {
      for (int i = 0; i < state.sizes[b]; ++i) {
        const double x = base[from + i];
        double& d = (*delta)[state.offsets[b] + i];
        // A start outside the box is not pulled in by a jump: the move only
        // stops at a bound it would cross.
        const double lower =
            std::min(x, problem.GetParameterLowerBound(block, i));
        const double upper =
            std::max(x, problem.GetParameterUpperBound(block, i));
        d = std::clamp(x + d, lower, upper) - x;
      }
    }
    from += state.sizes[b];
  }
}

// Only blocks without a manifold: their tangent coordinates are their
// entries, and the model's bounds (0 < a_i <= 1, the exponents' range) are
// on such blocks; the pose quaternion has none.
void HoldAtBounds(const ceres::Problem& problem, const State& state,
                  std::vector<double>* velocity) {
  for (size_t b = 0; b < state.blocks.size(); ++b) {
    const double* x = state.blocks[b];
    if (problem.GetManifold(state.blocks[b]) != nullptr) continue;
    for (int i = 0; i < state.sizes[b]; ++i) {
      double& v = (*velocity)[state.offsets[b] + i];
      if ((v < 0.0 && x[i] <= problem.GetParameterLowerBound(x, i)) ||
          (v > 0.0 && x[i] >= problem.GetParameterUpperBound(x, i))) {
        v = 0.0;
      }
    }
  }
}

// |x - (x [+] -g)| with the bounds applied, Ceres' gradient_norm: the force
// that is free to move the model, so that the three solvers' traces report
// the same quantity.
double ProjectedGradientNorm(const ceres::Problem& problem, const State& state,
                             const std::vector<double>& gradient) {
  std::vector<double> minus_g, moved;
  double sum = 0.0;
  for (size_t b = 0; b < state.blocks.size(); ++b) {
    const double* g = gradient.data() + state.offsets[b];
    const int tangent_size = problem.ParameterBlockTangentSize(state.blocks[b]);
    minus_g.assign(g, g + tangent_size);
    for (double& x : minus_g) x = -x;
    moved.resize(state.sizes[b]);
    if (!PlusInBounds(problem, state.blocks[b], state.sizes[b], state.blocks[b],
                      minus_g.data(), moved.data())) {
      return std::numeric_limits<double>::quiet_NaN();
    }
    for (int i = 0; i < state.sizes[b]; ++i) {
      sum += std::pow(moved[i] - state.blocks[b][i], 2);
    }
  }
  return std::sqrt(sum);
}

std::vector<double> Snapshot(const State& state) {
  std::vector<double> values;
  for (size_t b = 0; b < state.blocks.size(); ++b) {
    values.insert(values.end(), state.blocks[b],
                  state.blocks[b] + state.sizes[b]);
  }
  return values;
}

void Restore(const State& state, const std::vector<double>& values) {
  auto from = values.begin();
  for (size_t b = 0; b < state.blocks.size(); ++b) {
    std::copy(from, from + state.sizes[b], state.blocks[b]);
    from += state.sizes[b];
  }
}

void Fail(const std::string& message, SolverReport* report) {
  report->usable = false;
  report->converged = false;
  report->termination = "FAILURE";
  report->message = message;
}

void RecordStep(const ceres::Problem& problem, const State& state,
                const Evaluation& now, int iteration, double time,
                double wall_seconds, const SolverOptions& options,
                SolverReport* report) {
  report->trace.push_back(
      {iteration, time, wall_seconds, now.cost,
       ProjectedGradientNorm(problem, state, now.gradient)});
  if (options.on_step) options.on_step(report->trace.back());
}

}  // namespace pfdm
