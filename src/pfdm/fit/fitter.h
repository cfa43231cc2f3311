// Fits a model to every frame of a point sequence (the direct Ceres solve).
#ifndef PFDM_FIT_FITTER_H_
#define PFDM_FIT_FITTER_H_

#include <optional>
#include <string>
#include <vector>

#include "Eigen/Core"
#include "pfdm/fit/correspondence.h"
#include "pfdm/fit/data_cost.h"
#include "pfdm/fit/initialization.h"
#include "pfdm/model/model.h"
#include "pfdm/solvers/damping_groups.h"
#include "pfdm/solvers/solver.h"
#include "pfdm/util/point_data.h"

namespace pfdm {

struct FitOptions {
  // Regularizer weights, each relative to one knot's share of the data
  // (N / K points).  Smoothness: 1 penalizes a knot bent 1 mm off the line
  // through its neighbours like one more data point 1 mm off; it mostly
  // steers knots the data barely see (the apex, where cos u = 0).
  double smoothness_weight = 1.0;
  double prior_weight = 0.001;
  // "none", "huber" or "cauchy"; scale in mm.
  std::string loss = "none";
  double loss_scale_mm = 1.0;
  int max_correspondence_rounds = 10;
  // Rounds stop when no material point's model position moves more.
  double correspondence_tolerance_mm = 0.05;
  SolverOptions solver;
  DampingGroups damping_groups;
  JacobianKind jacobian = JacobianKind::kAnalytic;
  std::optional<AxisHint> hint;
  int min_points = 10;
  // Model states kept along each frame's solver path, log-spaced in the
  // iteration count at this many per decade, plus the start and the end;
  // 0 keeps none (FrameFit::trajectory).
  int trajectory_per_decade = 0;
};

// The model at one point of a frame's solver path.
struct TrajectoryPoint {
  int iteration = 0;  // As numbered in FrameFit::trace.
  double pseudo_time = 0.0;
  ModelState state;
};

struct FrameFit {
  int frame = 0;
  ModelState state;
  std::vector<MaterialPoint> material;     // One per data point.
  std::vector<Eigen::Vector3d> residuals;  // Model minus data, mm.
  double rms_mm = 0.0;
  double mean_distance_mm = 0.0;
  double max_distance_mm = 0.0;
  int iterations = 0;
  int correspondence_rounds = 0;
  double solve_seconds = 0.0;
  int residual_evaluations = 0;  // Summed over the rounds.
  int jacobian_evaluations = 0;
  double jacobian_seconds = 0.0;       // Summed over the solver's iterations.
  double linear_solver_seconds = 0.0;  // Likewise.
  double minimizer_seconds = 0.0;      // Likewise; see SolverReport.
  std::string termination;
  // Every solver iteration of every correspondence round, numbered on.
  std::vector<SolverTracePoint> trace;
  std::vector<TrajectoryPoint> trajectory;  // See trajectory_per_decade.
};

struct SequenceFit {
  ModelConfig config;
  std::vector<FrameFit> frames;
  Model ModelAt(int frame) const { return {config, frames[frame].state}; }
};

// Gauge (see README "Gauge conventions"): a0 is set by initialization and
// held; frame 0 fits the pose with tau = 0, no bending, and e1o = e2o = 0 at
// the apex and base knots; later frames hold the pose.  Throws InputError
// naming the frame when a frame has too few points or the solver fails.
SequenceFit FitSequence(const PointSequence& sequence,
                        const ModelConfig& config, const FitOptions& options);

}  // namespace pfdm

#endif  // PFDM_FIT_FITTER_H_
