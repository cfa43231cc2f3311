#include "pfdm/fit/stages/local_stage.h"

#include <algorithm>
#include <limits>
#include <utility>
#include <vector>

#include "Eigen/Core"
#include "pfdm/fit/correspondence/frame_correspondence.h"
#include "pfdm/fit/problem/local_fit.h"
#include "pfdm/fit/stages/round_acceleration.h"
#include "pfdm/util/error.h"
#include "pfdm/util/stopwatch.h"

namespace pfdm {
namespace {

// The local field's contour rounds end when one lowers the field's cost by
// less than this share.  With the nodes held to the surface's normal
// (node_normals.h) the farthest point's slide about halves each round;
// running on to 0.01 mm moved biv-me's segment numbers no less under a
// 1e-5 mm perturbation of the data (docs/local_deformations.md).
constexpr double kMinLocalRoundGain = 0.01;

// Stalled or not, the contours' material points are then the closest on
// the final model, as their distances are reported.  Returns how far (mm)
// the farthest one's model point moved.
double UpdateContours(const FramePoints& frame,
                      const std::vector<size_t>& contours,
                      const FitOptions& options, const Model& model,
                      SurfaceGrid* grid, FrameFit* fit) {
  const std::vector<Eigen::Vector3d> before =
      WorldPoints(model, Listed(fit->material, contours));
  std::vector<Eigen::Vector3d> found;
  std::vector<Eigen::Vector3d> normals(frame.positions.size());
  UpdateClosest(model, frame.positions, contours, options.solver.num_threads,
                frame.layer_w, std::vector<bool>(frame.positions.size(), false),
                /*warm=*/true, &fit->material, &normals, &found, DepthRanking(),
                grid);
  return MaxDistance(before, found);
}

// The field's displacements at the probes in world directions, stacked:
// two rounds' difference is how far the field moved the model there, the
// global part, held through the stage, cancelling (the probes' world
// points, twice a round, were 1 % of biv-me's both-walls job).
Eigen::VectorXd FieldAtProbes(const Model& model,
                              const std::vector<MaterialPoint>& probes) {
  const Eigen::Matrix3d rotation = model.Rotation();
  Eigen::VectorXd stacked(3 * probes.size());
  for (size_t i = 0; i < probes.size(); ++i) {
    const MaterialPoint& at = probes[i];
    stacked.segment<3>(3 * i) =
        rotation * model.state.local.Displacement(at.u, at.v, at.w);
  }
  return stacked;
}

// The next round's field: the mix of the last rounds' fields
// (round_acceleration.h).  The field's rounds swing as the global rounds
// did; mixed, each lowers the field's cost further before it stalls (biv-me
// patient 1's contours: pooled RMS 0.78 mm against 0.79).
// Returns whether the field changed.
bool MixField(Eigen::VectorXd change, RoundAcceleration* acceleration,
              Model* model) {
  const std::vector<double> coefficients = model->state.local.Coefficients();
  const Eigen::Map<const Eigen::VectorXd> solution(coefficients.data(),
                                                   coefficients.size());
  const Eigen::VectorXd next = acceleration->Next(std::move(change), solution);
  if (next == solution) return false;
  model->state.local.SetCoefficients(next.data());
  return true;
}

}  // namespace

std::vector<bool> LocalSlidingPoints(const FramePoints& frame) {
  std::vector<bool> sliding(frame.positions.size(), false);
  for (size_t i : frame.untracked) sliding[i] = !frame.is_tag[i];
  return sliding;
}

void FitLocalStage(const FramePoints& frame, const FitOptions& options,
                   const std::string& source, Model* model, FrameFit* fit,
                   LocalDirectSolver* direct, SurfaceGrid* grid) {
  const std::vector<bool> sliding = LocalSlidingPoints(frame);
  std::vector<size_t> contours;
  for (size_t i : frame.untracked) {
    if (sliding[i]) contours.push_back(i);
  }
  const auto start = Clock::now();
  const std::vector<MaterialPoint> probes = Listed(fit->material, contours);
  RoundAcceleration acceleration;
  double last_cost = std::numeric_limits<double>::infinity();
  for (int round = 0; round < options.max_correspondence_rounds; ++round) {
    const Eigen::VectorXd before = FieldAtProbes(*model, probes);
    const SolverReport local = FitLocalField(frame.positions, fit->material,
                                             sliding, options, model, direct);
    fit->local_iterations += local.iterations;
    if (!local.usable) {
      throw InputError(source + ": frame " + std::to_string(frame.index) +
                       ": local deformations: solver failed: " + local.message);
    }
    const double cost = local.trace.empty() ? 0.0 : local.trace.back().cost;
    const bool stalled = cost > (1.0 - kMinLocalRoundGain) * last_cost;
    last_cost = cost;
    if (contours.empty()) break;
    const double moved =
        UpdateContours(frame, contours, options, *model, grid, fit);
    if (stalled || moved < options.correspondence_tolerance_mm ||
        round + 1 == options.max_correspondence_rounds) {
      break;
    }
    if (MixField(FieldAtProbes(*model, probes) - before, &acceleration,
                 model)) {
      UpdateContours(frame, contours, options, *model, grid, fit);
    }
  }
  fit->local_seconds = SecondsSince(start);
}

}  // namespace pfdm
