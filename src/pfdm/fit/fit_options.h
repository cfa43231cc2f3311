// How a sequence is fitted: regularizer, loss, correspondence, solver.
#ifndef PFDM_FIT_FIT_OPTIONS_H_
#define PFDM_FIT_FIT_OPTIONS_H_

#include <optional>
#include <string>

#include "Eigen/Core"
#include "pfdm/fit/correspondence/transmural.h"
#include "pfdm/fit/residuals/data_cost.h"
#include "pfdm/solvers/damping_groups.h"
#include "pfdm/solvers/solver.h"

namespace pfdm {

// Optional hint of the long axis: the user's, or landmarks in the data.
struct AxisHint {
  Eigen::Vector3d apex;
  Eigen::Vector3d base_center;
  // Where it came from, as SequenceFit::axis_source records it.
  std::string source = "--apex/--base";
};

// Local deformations (local_fit.h, docs/local_deformations.md).
struct LocalOptions {
  bool enabled = true;
  // Nodes along u, the apex pole's row included (10 degrees of u apart),
  // and around v (15 degrees apart): 9 x 16 smeared the lesion phantom's
  // segment over its edges (Ecc 4.7 points off), 13 x 24 does not.
  int rows = 13;
  int cols = 24;
  // Membrane plus thin-plate energy of the nodal field, relative to one
  // node's share of the data (N / nodes points), as smoothness_weight is to
  // a knot's.
  // 0.02 finds the lesion phantom's segment (Ecc within 1.9 points; 0.1:
  // 5) and keeps the normal phantom's segments uniform within 2 points
  // (0.01: 2.1, noise shows).
  double stiffness = 0.02;
};

// Which wall the points lie on, as the user declares it (--surface): kAuto
// takes it from the points' walls (contour types, a mesh's surface column),
// else the mid-wall.  A declared wall makes the fit one surface there; the
// endocardium's encloses the cavity, which gives an ejection fraction.
enum class SurfaceChoice { kAuto, kEndocardium, kMidwall, kEpicardium };
// Its --surface word: auto, endo, midwall or epi.
inline const char* SurfaceChoiceName(SurfaceChoice surface) {
  switch (surface) {
    case SurfaceChoice::kEndocardium:
      return "endo";
    case SurfaceChoice::kMidwall:
      return "midwall";
    case SurfaceChoice::kEpicardium:
      return "epi";
    default:
      return "auto";
  }
}

struct FitOptions {
  // Regularizer weights, each relative to one knot's share of the data
  // (N / K points).  Smoothness: 1 penalizes a knot bent 1 mm off the line
  // through its neighbours like one more data point 1 mm off; it mostly
  // steers knots the data barely see (the apex, where cos u = 0).
  double smoothness_weight = 1.0;
  double prior_weight = 0.001;
  // Frames without tracked points pull toward frame 0's state instead, with
  // this weight: contours fix the surface, not where its material points
  // are, so what they leave free should read as frame 0's, not drift from
  // frame to frame (on biv-me's contours the functions then come back to
  // frame 0's at the end of the cycle; 0.001 leaves them 4-25 % off).
  double untracked_prior_weight = 0.01;
  // "none", "huber" or "cauchy" (fit/residuals/robust_loss.h).  Its scale
  // is measured by the fit (fit/stages/loss_scale.h, recorded in
  // SequenceFit::loss_scale_mm) unless loss_scale_auto is false; then it is
  // loss_scale_mm.
  std::string loss = "none";
  bool loss_scale_auto = true;
  double loss_scale_mm = 1.0;
  int max_correspondence_rounds = 10;
  // The rounds of a frame with untracked points may run to this many while
  // the points still move, the rounds past max_correspondence_rounds
  // mixing the last rounds' solutions (round_acceleration.h): on biv-me's
  // contours 12 of the 15 frames that ran out of 10 rounds then settle.
  int max_accelerated_rounds = 20;
  // Rounds stop when no material point's model position moves more.
  double correspondence_tolerance_mm = 0.05;
  SolverOptions solver;
  DampingGroups damping_groups;
  JacobianKind jacobian = JacobianKind::kAnalytic;
  std::optional<AxisHint> hint;
  int min_points = 10;
  WallModel wall = WallModel::kAuto;
  SurfaceChoice surface = SurfaceChoice::kAuto;
  // End-diastole: the frame the ejection fraction's EDV is read at
  // (SequenceFit::ed_frame); the fit itself starts at frame 0.
  int ed_frame = 0;
  // Model states kept along each frame's solver path, log-spaced in the
  // iteration count at this many per decade, plus the start and the end;
  // 0 keeps none (FrameFit::trajectory).
  int trajectory_per_decade = 0;
  // Each frame's covariance of its global parameters at the solution
  // (FrameFit::covariance, fit/problem/frame_covariance.h).  Off by
  // default: it cost 46 % of the frames' fits at 2,000 tags and 26 % at
  // 20,000 (15 and 28 ms a tracked frame of 176 parameters, one thread),
  // over the 25 % it may cost to be on by default.
  bool uncertainty = false;
  LocalOptions local;
};

}  // namespace pfdm

#endif  // PFDM_FIT_FIT_OPTIONS_H_
