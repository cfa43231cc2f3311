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
  // A solid's field varies through the wall, d(u, v, w) = S (q + w q_w +
  // k(w) q_k) (local_field.h), so that a segment's endocardium can move
  // unlike its epicardium and its inner half unlike its outer one.  Its tags
  // keep frame 0's depths (held, the default), or, ranked in every frame
  // (hold_tag_depths false), are ranked among their nearest tags rather than
  // their ring (NeighbourhoodDepths), so that a segment moving unlike its ring
  // keeps them.  Off by default: on the phantoms' normal walls
  // (lv_layer_strain_test) and biv-me's contours d(u, v) reads closer to the
  // truth (docs/local_deformations.md). But a ring's ranks leave frame 0's
  // section shape about the axis (a1 - a2) where the rounds start it
  // (lv_wall_rank_shape_test.cc), which its intervals miss.
  bool transmural = false;
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
  // Whether that pull (and the temporal one) holds a3, the length, too;
  // FitFrame lets it go where the data reach the apex (ApexInData), since
  // the apical data and the base rim's residual then say how long the
  // model is (fit/stages/frame_fit.cc).  The meridian gauge keeps a3 equal
  // at every knot, so the length is all it frees.
  bool untracked_prior_holds_length = true;
  // Its (and the temporal pull's) scale on a1 and a2 at knots the points
  // cover all round (CoveredKnots, fit/problem/knot_coverage.h): there the
  // ring's radii are the data's.  Held fully, the LV phantom's short- and
  // long-axis contours read radial contraction at end-systole 20.3 % against
  // 21.9; at 0.3, 21.7; at 0, 21.8, but biv-me's strain then jumps 3.5
  // points between frames and, without the temporal pull, its frame 8's
  // closest points still move after 20 rounds.
  double untracked_prior_covered_radii_scale = 0.3;
  // And toward the frame before, with this weight (fit/stages/
  // temporal_prior.h says what it does); 0: off.
  double temporal_prior_weight = 0.05;
  // A solid's wall keeps frame 0's volume with this weight (fit/residuals/
  // incompressibility_residual.h: a 1 % change costs like every point
  // 1 % of the wall thickness off, times the weight); 0: off.
  double incompressible_weight = 0.0;
  // The rings between which it holds the wall's volume: frame 0's data's
  // lowest and highest u (FitFrame sets them after frame 0); equal: the
  // model's whole length.
  double incompressible_u_low = 0.0, incompressible_u_high = 0.0;
  // A solid's tags keep frame 0's depth across the wall in every tracked
  // frame, as they keep its (u, v) (held_depths.h; --tag_depths held, the
  // default), rather than being ranked anew in each (ranked): ranks take up
  // a segment's own motion, so that a hypokinetic one through the wall
  // reads like its ring (docs/gauge.md).  A transmural local field
  // (LocalOptions::transmural) ranks its tags among their neighbours in
  // every frame instead.
  bool hold_tag_depths = true;
  // Frame 0's pose spins toward `reference`'s (the start's) about the long
  // axis with this weight, relative to the data's N points
  // (SpinGaugeResidual): where the section is round the data leave that
  // spin free (docs/gauge.md).  FitFrame sets it for frame 0 of tags; 0:
  // off.
  double reference_spin_weight = 0.0;
  // Frame 0's apex is pulled toward the start's height along the long axis
  // with this weight, relative to the data's N points (ApexGaugeResidual):
  // where no data reach the apex they leave it free.  FitFrame sets it for
  // frame 0 of tags without data near the start's apex; 0: off.
  double reference_apex_weight = 0.0;
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
  // A later frame's contour rounds that swing back and forth are each
  // pulled toward the state they start from with this weight (one knot's
  // share of the points, as the priors'), until they settle
  // (fit/stages/global_rounds.cc, kSwingCosine); 0: never.
  double swing_pull_weight = 1.0;
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
  // default so far; it cost 46 % of a tracked frame's fit at 2,000 tags
  // until its normal matrix was scaled before the Cholesky, 8-11 % of the
  // sequence fit's CPU since (docs/uncertainty.md, Cost).
  bool uncertainty = false;
  LocalOptions local;
};

}  // namespace pfdm

#endif  // PFDM_FIT_FIT_OPTIONS_H_
