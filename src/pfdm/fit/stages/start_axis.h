// Frame 0's starting model, and where its long axis came from: what the
// data say, before the points' largest spread (which lies across a squat
// segment of a ventricle without its apex).
#ifndef PFDM_FIT_STAGES_START_AXIS_H_
#define PFDM_FIT_STAGES_START_AXIS_H_

#include <string>
#include <vector>

#include "Eigen/Core"
#include "pfdm/fit/fit_options.h"
#include "pfdm/model/model.h"
#include "pfdm/util/point_data.h"

namespace pfdm {

struct StartAxis {
  Model model;
  // "--apex/--base", the landmarks' AxisHint::source, "normal of 3
  // parallel planes", "point cloud, best of 3 candidate axes" (with " and
  // the normal of 7 parallel planes across its length" where they
  // competed).
  std::string source;
};

// In this order: options.hint (--apex/--base, or landmarks in the data);
// the normal of the parallel planes most of frame 0's points lie on
// (parallel_planes.h: short-axis slices, tag planes), unless it lies
// across the cloud's length (cloud_length.h), where it only competes; else
// the point cloud's candidate axes (CandidateAxes), each tried by fitting
// frame 0's global rounds to a subset of its points (a whole ventricle's
// three on 5 knots, the close calls on the model's), the lowest cost kept:
// the principal axis as it is, another along the axis its fit turned to.
// Every model but the hint's is InitializeModelAlong its axis, on all of
// frame 0's points: the principal axis gives InitializeModel's.
StartAxis ChooseStartAxis(const Frame& first, const ModelConfig& config,
                          const FitOptions& options, const std::string& source);

// The cloud's principal axes, largest spread first; where the cloud is
// squat (not CloudLength::Elongated), also the six directions halfway
// between two of them.
std::vector<Eigen::Vector3d> CandidateAxes(
    const std::vector<Eigen::Vector3d>& points);

struct CandidateFit {
  // Of frame 0's converged global rounds: the data term's mean squared
  // distance over the points, mm^2.
  double cost = 0.0;
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();  // Fitted, apex to base.
  Model model;                                      // Fitted.
};

// Frame 0's global rounds on `points` (untracked, their layers kept) from
// `model`, at most `max_rounds` of them, with the direct solve; an unusable
// solve costs infinity.
CandidateFit FitCandidate(const std::vector<DataPoint>& points,
                          const Model& model, const FitOptions& options,
                          const std::string& source, int max_rounds);

}  // namespace pfdm

#endif  // PFDM_FIT_STAGES_START_AXIS_H_
