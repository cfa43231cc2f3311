// What a sequence fit gives: every frame's model, material points,
// residuals and solver account (fitter.h makes it).
#ifndef PFDM_FIT_STAGES_SEQUENCE_FIT_H_
#define PFDM_FIT_STAGES_SEQUENCE_FIT_H_

#include <string>
#include <vector>

#include "Eigen/Core"
#include "pfdm/fit/correspondence/correspondence.h"
#include "pfdm/fit/problem/frame_covariance.h"
#include "pfdm/fit/problem/frame_problem.h"
#include "pfdm/model/model.h"
#include "pfdm/solvers/solver.h"
#include "pfdm/util/point_data.h"
#include "pfdm/util/verdict.h"

namespace pfdm {

// The model at one point of a frame's solver path.
struct TrajectoryPoint {
  int iteration = 0;  // As numbered in FrameFit::trace.
  double pseudo_time = 0.0;
  ModelState state;
};

struct FrameFit {
  int frame = 0;
  // Frame 0, a frame whose tags keep earlier material points, or one of
  // contours only (gauge.h).
  FrameKind kind = FrameKind::kReference;
  ModelState state;
  std::vector<MaterialPoint> material;     // One per data point.
  std::vector<Eigen::Vector3d> residuals;  // Model minus data, mm.
  double rms_mm = 0.0;
  double mean_distance_mm = 0.0;
  double max_distance_mm = 0.0;
  int iterations = 0;
  int correspondence_rounds = 0;
  // A solid's tracked frame whose tags kept frame 0's depths
  // (held_depths.h) rather than this frame's ranks.
  bool depths_held = false;
  // A solid's frame whose tags took their depths from where they lie across
  // the walls its contours place (measured_depths.h), not from ranks.
  bool depths_measured = false;
  // A tracked frame with contours beside its tags (HasContoursBesideTags):
  // tags and contours in one fit.
  bool mixed = false;
  // When the rounds ran out (FitOptions::max_correspondence_rounds) with
  // closest points still moving by the tolerance or more: how far the last
  // search moved one (mm), the fit resting on correspondences that had not
  // settled.  0 when they settled.
  double unsettled_mm = 0.0;
  double solve_seconds = 0.0;
  int residual_evaluations = 0;  // Summed over the rounds.
  int jacobian_evaluations = 0;
  double evaluation_seconds = 0.0;     // Summed over the solver's iterations.
  double linear_solver_seconds = 0.0;  // Likewise.
  double minimizer_seconds = 0.0;      // Likewise; see SolverReport.
  // Closest material points of the untracked points, over the rounds.
  double correspondence_seconds = 0.0;
  // The local field's solve (FitOptions::local), within solve_seconds.
  double local_seconds = 0.0;
  int local_iterations = 0;
  std::string termination;
  // Each term's cost at the last global solve's solution.
  TermCosts costs;
  // What the fit itself sees of the frame (frame_verdict.h); the analysis
  // adds what it sees of the clinical numbers (report/plausibility.h).
  Verdict verdict;
  // Whether the frame has tracked points, which alone show a turn about the
  // long axis: frame 0 with tags (ids that later frames see again), or a
  // later frame some of whose points keep a material point from an earlier
  // one (FrameKind::kTracked).  Without them (contours) the gauge holds tau
  // (gauge.h), and the report leaves rotation, twist, torsion and shear out.
  bool tracked = true;
  // Every solver iteration of every correspondence round, numbered on.
  std::vector<SolverTracePoint> trace;
  std::vector<TrajectoryPoint> trajectory;  // See trajectory_per_decade.
  // The robust loss's scale the frame was fitted with (measured for
  // --loss_scale auto: fit/stages/loss_scale.h; else
  // FitOptions::loss_scale_mm); 0 without a loss.
  double loss_scale_mm = 0.0;
  // Per data point, the robust loss's weight at its final residual,
  // rho'(|r|^2) in (0, 1] (fit/residuals/robust_loss.h): near 0 for a
  // point the fit took for an outlier.  Empty without a loss (every point
  // weighs 1).  Filled by FitSequence.
  std::vector<double> loss_weights;
  // The global parameters' covariance at the frame's global solution
  // (before the local field), with FitOptions::uncertainty; computed false
  // without.
  FrameCovariance covariance;
};

struct SequenceFit {
  ModelConfig config;  // config.Solid(): the wall model the fit chose.
  // Why: "--wall midwall", "endocardial and epicardial contours", "tags
  // spread 9.8 mm across the wall", ...
  std::string wall_reason;
  // Of a single surface (not a solid), which wall its data lie on: the
  // endocardium or the epicardium when frame 0 has contours of that wall
  // only, else kAnywhere (tags: the mid-wall).
  WallLayer surface = WallLayer::kAnywhere;
  // A solid of ranked tags: their noise (TangentialNoiseMm over the tracked
  // frames), taken out of every frame's h (DeconvolvedThickness); 0
  // otherwise.
  double tag_noise_mm = 0.0;
  // How frame 0's long axis was found (StartAxis::source): "--apex/--base",
  // "APEX_POINT and MITRAL_VALVE", "normal of 3 parallel planes", "point
  // cloud, best of 3 candidate axes".
  std::string axis_source;
  // Whether frame 0 has data near the apex, where the cup closes: within
  // kApexReach of the fitted length of its apex pole (apex_coverage.h).
  // Without, what the fit says of the apex (apical rings, the cap's volume
  // and mass) is extrapolated.
  bool apex_in_data = true;
  // Frame 0's data point nearest the apex pole: its distance, and the
  // lowest point's height above the pole along the axis, as fractions of
  // the model's length (apex pole to base rim); the least u of frame 0's
  // material points.
  double apex_data_distance = 0.0;
  double lowest_data_height = 0.0;
  // The highest point's height likewise (above 1 where data pass the rim).
  double highest_data_height = 1.0;
  double lowest_data_u = 0.0;
  // End-diastole (FitOptions::ed_frame), and each frame's time from the
  // trigger (ms) when the input gave them (PointSequence::time_ms), else
  // empty.
  int ed_frame = 0;
  std::vector<double> time_ms;
  // The pull toward the previous frame the frames without tracked points
  // were fitted with (fit/stages/temporal_prior.h: 0 for a sequence of
  // fewer than kTemporalPriorMinFrames).
  double temporal_prior_weight = 0.0;
  // The contours the reader left out (PointSequence::left_out).
  std::vector<LeftOutContour> left_out;
  // Wall time outside the frames' solve_seconds: the start (the long axis's
  // candidates, the initialized model: StartSequence) and the checks after
  // the frames (the tags' noise out of a solid, the weights, the apex's
  // coverage, the verdicts' probes).
  double start_seconds = 0.0;
  double checks_seconds = 0.0;
  // The threads the fit was given (--threads): the analysis's intervals
  // (report/number_uncertainty.h) take as many.
  int threads = 1;
  std::vector<FrameFit> frames;
  Model ModelAt(int frame) const { return {config, frames[frame].state}; }
};

// Adds one solve's iterations, evaluations and times to the frame's.
void AddSolverCounts(const SolverReport& report, FrameFit* fit);

// "" for a frame whose correspondences settled, else what to append to its
// termination: "; closest points unsettled (0.94 mm in the last search)".
std::string UnsettledNote(const FrameFit& frame);

// Frame 0's relative length variance (FrameCovariance::LengthNoiseVariance:
// its top's draws and its apex's) for frame 0 and the tracked frames,
// whose material points frame 0 placed: a uniform stretch, frame 0's scale
// gauge.  0 for an untracked later frame (its base rim is held at its own
// highest points by a residual on the last knot, which moves the knots
// below it little: with its draws as a stretch, short-axis contours' a3
// read sd 0.243 mm at knots 2-6 against 0.127 without, both holding the
// noise-free fit in every draw, and its own covariance places its apex).
double LengthVariance(const SequenceFit& fit, size_t t);

}  // namespace pfdm

#endif  // PFDM_FIT_STAGES_SEQUENCE_FIT_H_
