// Fits a model to every frame of a point sequence: the loop over frames and
// correspondence rounds (one frame's problem: frame_problem.h; which entries
// each frame holds: gauge.h).
#ifndef PFDM_FIT_FITTER_H_
#define PFDM_FIT_FITTER_H_

#include <optional>
#include <string>
#include <vector>

#include "Eigen/Core"
#include "pfdm/fit/correspondence.h"
#include "pfdm/fit/fit_options.h"
#include "pfdm/model/model.h"
#include "pfdm/solvers/solver.h"
#include "pfdm/util/point_data.h"

namespace pfdm {

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
  // Closest material points of the untracked points, over the rounds.
  double correspondence_seconds = 0.0;
  // The local field's solve (FitOptions::local), within solve_seconds.
  double local_seconds = 0.0;
  int local_iterations = 0;
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

// Gauge: see gauge.h and README "Gauge conventions".  Throws InputError
// naming the frame when a frame has too few points or the solver fails.
SequenceFit FitSequence(const PointSequence& sequence,
                        const ModelConfig& config, const FitOptions& options);

}  // namespace pfdm

#endif  // PFDM_FIT_FITTER_H_
