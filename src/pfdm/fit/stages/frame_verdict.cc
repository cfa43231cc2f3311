#include "pfdm/fit/stages/frame_verdict.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "Eigen/Dense"
#include "pfdm/fit/correspondence/correspondence.h"
#include "pfdm/fit/correspondence/measured_depths.h"
#include "pfdm/fit/problem/frame_problem.h"
#include "pfdm/fit/stages/cloud_length.h"
#include "pfdm/fit/stages/frame_points.h"
#include "pfdm/fit/stages/loss_scale.h"
#include "pfdm/fit/stages/top_slice.h"
#include "pfdm/util/median.h"
#include "pfdm/util/stride.h"

namespace pfdm {
namespace {

std::string Format(const char* format, double a, double b = 0.0,
                   double c = 0.0) {
  char text[256];
  std::snprintf(text, sizeof(text), format, a, b, c);
  return text;
}

// The RMS the verdict judges: over every point, or with a robust loss over
// those it keeps (kKeptWeight), so that outliers it weighed down do not
// read as a model that misses the data (5 % of them at 5-10 mm took the
// LV phantom's RMS from 1.0 to 2.3 mm, its inliers' 1.0 under the loss).
double JudgedRmsMm(const FrameFit& frame) {
  if (frame.loss_weights.size() != frame.residuals.size()) return frame.rms_mm;
  double sum = 0.0;
  size_t kept = 0;
  for (size_t i = 0; i < frame.residuals.size(); ++i) {
    if (frame.loss_weights[i] < kKeptWeight) continue;
    sum += frame.residuals[i].squaredNorm();
    ++kept;
  }
  return kept == 0 ? frame.rms_mm : std::sqrt(sum / kept);
}

void JudgeDownWeighted(const FrameFit& frame, Verdict* verdict) {
  if (frame.loss_weights.empty()) return;
  const double low = static_cast<double>(
      std::count_if(frame.loss_weights.begin(), frame.loss_weights.end(),
                    [](double w) { return w < kKeptWeight; }));
  const double share = low / frame.loss_weights.size();
  if (share <= kDownWeightedWarn) return;
  verdict->Warn("outliers",
                Format("the robust loss weighs %.0f %% of the points below "
                       "%.1f (scale %.2f mm): more outliers than a tracker "
                       "makes, or a model that misses the data",
                       100.0 * share, kKeptWeight, frame.loss_scale_mm));
}

void JudgeSolver(const FrameFit& frame, Verdict* verdict) {
  if (frame.termination == "CONVERGENCE" || frame.termination == "REST") {
    return;
  }
  verdict->Warn("solver", "the solver stopped without converging (" +
                              frame.termination + ")");
}

// A search that moved points by less than the residuals' own scale
// changes nothing the fit reports; by more, the fit rests on
// correspondences that have not settled.
void JudgeUnsettled(const FrameFit& frame, double median_rms,
                    Verdict* verdict) {
  if (frame.unsettled_mm <= median_rms) return;
  const std::string text = Format(
      "closest points still moving (%.2f mm in the last search, the frames' "
      "median RMS %.2f mm)",
      frame.unsettled_mm, median_rms);
  if (frame.unsettled_mm > kUnsettledFailMm) {
    verdict->Fail("unsettled", text);
  } else {
    verdict->Warn("unsettled", text);
  }
}

// Whether one surface was fitted to a frame with both walls' contours: its
// RMS is then about half the wall's thickness, whatever the fit does.
bool BothWallsOnOneSurface(const Frame& points, const ModelConfig& config) {
  return !config.Solid() && HasBothWalls(points);
}

// The RMS against the other frames' and against the data's size: the
// radius (RMS distance from the centroid) of the frame's points.
void JudgeRms(const FrameFit& frame, double median_rms, double radius,
              bool both_walls_on_one_surface, Verdict* verdict) {
  const double rms = JudgedRmsMm(frame);
  const char* which = frame.loss_weights.empty() ? "RMS" : "RMS of the kept";
  if (rms > kRmsFramesRatio * median_rms &&
      rms > median_rms + kRmsFramesMinMm) {
    verdict->Warn("rms_frames",
                  std::string(which) +
                      Format(" %.2f mm, %.1f times the frames' median %.2f mm",
                             rms, rms / median_rms, median_rms));
  }
  const double share = rms / radius;
  if (share <= kRmsSizeWarn) return;
  const std::string text =
      std::string(which) +
      Format(
          " %.2f mm is %.0f %% of the data's radius (%.1f mm): the model does "
          "not describe these points",
          rms, 100.0 * share, radius) +
      (both_walls_on_one_surface
           ? " (one surface through both walls' contours; --wall solid fits "
             "each wall)"
           : "");
  if (share > kRmsSizeFail) {
    verdict->Fail("rms_size", text);
  } else {
    verdict->Warn("rms_size", text);
  }
}

// Whether a step without the prior that moves the points by pull_mm (RMS)
// is the verdict's reason `prior`.
bool PullIsAReason(double pull_mm, const FrameFit& frame) {
  const double share = pull_mm / JudgedRmsMm(frame);
  return share > kPriorPullWarn && pull_mm > kPriorPullFloorMm;
}

// How far the data would take the model without the prior: one solver
// step from the frame's global solution with the prior's weight 0, the
// RMS of the points' model positions' move.  At the solution the data's
// pull balances the prior's, so the step is what the prior holds back.
// Only where tags say where material goes (frame 0 and tracked frames):
// contours fix the surface, not where its material points are, and what
// they leave free is by design the prior's (frame 0's state).
double PriorPullMm(const Frame& points, const FrameFit& frame,
                   const ModelConfig& config, const ModelState& reference,
                   const FitOptions& options) {
  const Model solution{config, frame.state};
  Model probe = solution;
  probe.state.local = LocalField();
  FitOptions step = WithLossScale(options, frame.loss_scale_mm);
  step.prior_weight = 0.0;
  // One Levenberg-Marquardt step whatever the fit's solver (the
  // integrators, without the prior, would integrate the modes only the
  // prior held, rates ~1e-9, to their cap), taken without a solve: a
  // solve's one iteration evaluated the frame twice with Jacobians.
  step.solver.kind = SolverKind::kDirect;
  std::vector<Eigen::Vector3d> positions;
  for (const DataPoint& p : points.points) positions.push_back(p.position);
  const std::vector<Eigen::Vector3d> normals(positions.size(),
                                             Eigen::Vector3d::Zero());
  Model global = solution;
  global.state.local = LocalField();
  double pull = 0.0;
  // A step Ceres would reject moves nothing, so the step is tested (an
  // evaluation of the frame) only where its move would be a reason.
  const bool kept = StepFrame({positions, frame.material, normals, std::nullopt,
                               frame.kind, frame.state, reference},
                              step, &probe, [&](const Model& stepped) {
                                pull =
                                    RmsMoveMm(global, stepped, frame.material);
                                return PullIsAReason(pull, frame);
                              });
  return kept ? pull : 0.0;
}

void JudgePrior(double pull_mm, const FrameFit& frame, Verdict* verdict) {
  if (!PullIsAReason(pull_mm, frame)) return;
  const double share = pull_mm / JudgedRmsMm(frame);
  const std::string text = Format(
      "without the prior (--prior) one step would move the points by "
      "%.2f mm (RMS), %.0f %% of the frame's RMS: the prior, not the "
      "data, holds the model",
      pull_mm, 100.0 * share);
  if (share > kPriorPullFail) {
    verdict->Fail("prior", text);
  } else {
    verdict->Warn("prior", text);
  }
}

// a1..a3 and the exponents at the bounds FrameBlocks gives them.
void JudgeBounds(const ModelConfig& config, const FrameFit& frame,
                 Verdict* verdict) {
  struct Bound {
    int function;
    const char* name;
    double lower, upper;
  };
  const Bound bounds[] = {{kA1, "a1", 1e-3, 1.0},
                          {kA2, "a2", 1e-3, 1.0},
                          {kA3, "a3", 1e-3, 1.0},
                          {kEps1, "eps1", 0.1, 4.0},
                          {kEps2, "eps2", 0.1, 4.0}};
  for (const Bound& bound : bounds) {
    if (config.modes[bound.function] != FunctionMode::kFree) continue;
    int pressed = 0;
    for (const FunctionValues& knot : frame.state.knots) {
      const double value = knot[bound.function];
      if (value <= bound.lower * (1.0 + 1e-6) ||
          value >= bound.upper * (1.0 - 1e-6)) {
        ++pressed;
      }
    }
    if (pressed == 0) continue;
    verdict->Warn("at_bound",
                  std::string(bound.name) +
                      Format(" at its bound (%g or %g) at %.0f knots",
                             bound.lower, bound.upper, pressed));
  }
}

// A solid's thickness h has the floor 0 (FrameBlocks): its walls may meet,
// never cross.  At the top knot they meet where both walls' long-axis
// contours end together at the valve's hinge: biv-me's both walls
// (--contours lv-cavity,lv-epi) hold h at 0 there in frames 2-12, where the
// data put the endocardium outside the epicardium (h down to -5.0 mm
// before the floor, the fit exiting 0 with nothing said).  Below the top
// knot a wall of no thickness is no heart's: its mass and thickening there
// are the floor's.
void JudgeWallThickness(const ModelConfig& config, const FrameFit& frame,
                        Verdict* verdict) {
  if (!config.Solid() || frame.state.knots.empty()) return;
  const size_t top = frame.state.knots.size() - 1;
  int met = 0;
  for (size_t k = 0; k < top; ++k) {
    if (frame.state.knots[k][kH] <= 0.0) ++met;
  }
  if (met == 0) return;
  verdict->Warn("walls_meet",
                Format("the wall's thickness h at its floor 0 at %.0f knots "
                       "below the top one: the data put the endocardium on "
                       "or outside the epicardium there, where the mass and "
                       "thickening are the floor's, no wall's",
                       met));
}

// Knots between the lowest and the highest data point's with no point in
// the span on either side: their values are the regularizer's, not the
// data's.  (A span alone may fall between two short-axis slices.)
void JudgeRings(const ModelConfig& config, const FrameFit& frame,
                Verdict* verdict) {
  const KnotGrid grid = config.Grid();
  std::vector<int> count(config.num_knots - 1, 0);
  for (const MaterialPoint& m : frame.material) ++count[grid.Span(m.u).k0];
  int first = 0, last = static_cast<int>(count.size()) - 1;
  while (first <= last && count[first] == 0) ++first;
  while (last >= first && count[last] == 0) --last;
  int empty = 0;
  for (int k = first + 1; k <= last; ++k) {
    empty += count[k - 1] < kMinRingPoints && count[k] < kMinRingPoints;
  }
  if (empty == 0) return;
  verdict->Warn("sparse_rings",
                Format("%.0f knots inside the data have fewer than %.0f "
                       "points in the spans on either side",
                       empty, kMinRingPoints));
}

// The data's span along the model's long axis in mm, from their material
// points' places on the model: a length, not a share of u, since an
// untracked frame's prior lets the length (a3) follow the data, and then a
// frame that lost its basal slice spans all of its shorter model.
double AxialSpanMm(const Model& model, const std::vector<MaterialPoint>& at) {
  if (at.empty()) return 0.0;
  const std::vector<double> heights = AxialHeights(model, at);
  const auto [low, high] = std::minmax_element(heights.begin(), heights.end());
  return *high - *low;
}

// A later frame of contours whose data span much less of the axis than
// frame 0's (a short-axis slice the heart moved out of): the ventricle
// beyond the data is not in them, and the volume is either the model's
// continuation (on the LV phantom's three slices, while the length was
// held at frame 0's, 137 ml against 83 at an RMS of 0.16 mm) or a cavity
// that ends at the highest slice left, under the base.  Not asked of
// tracked frames: their points keep their material points, so they span
// the same stretch of the model however far it shortens.
void JudgeSpan(const SequenceFit& fit, int t, double reference,
               Verdict* verdict) {
  if (fit.frames[t].tracked || reference <= 0.0) return;
  const double share =
      AxialSpanMm(fit.ModelAt(t), fit.frames[t].material) / reference;
  if (share >= kMinSpanShare) return;
  verdict->Warn(kShortSpanCode,
                Format("the data span %.0f %% of frame 0's along the axis "
                       "(under %.0f %%): the ventricle beyond them is not "
                       "in the data, nor is the volume",
                       100.0 * share, 100.0 * kMinSpanShare));
}

// Frame 0 starts from the initialized model, far from the data: a solve
// that leaves its cost where it was took no step.  Its end is the state it
// kept: where the rounds ran out, the best of them (GlobalRounds::
// BackToBest), whose cost the last round's may exceed many times (the LV
// phantom's mid-ventricular slices of both walls, seed 2: 6,063 to 63,030
// in the trace, the kept state's 86, RMS 0.94 mm).
void JudgeMoved(const FrameFit& frame, Verdict* verdict) {
  if (frame.trace.empty()) return;
  const double first = frame.trace.front().cost;
  const double last = std::min(frame.trace.back().cost, frame.costs.Total());
  if (frame.iterations > 0 && last < 0.999 * first) return;
  verdict->Fail("not_moved",
                Format("frame 0's fit never left its start (cost %.4g to "
                       "%.4g in %.0f iterations)",
                       first, last, frame.iterations));
}

// Without data near the apex the apical rings, the cap's volume and mass
// are the model's continuation of the data above them.
void JudgeApex(const SequenceFit& fit, Verdict* verdict) {
  if (fit.apex_in_data) return;
  verdict->Warn("extrapolated",
                Format("no data near the apex (the nearest %.0f %% of the "
                       "model's length from it, u above %.2f): the apical "
                       "rings, the apex cap's volume and mass are extrapolated",
                       100.0 * fit.apex_data_distance, fit.lowest_data_u));
}

// The model ends at the highest data; when they are one short-axis slice
// the base may lie anywhere above it.
void JudgeTopSlice(const Frame& points, const Model& model, Verdict* verdict) {
  const Eigen::Vector3d center(model.state.center.data());
  const TopSlice top =
      FindTopSlice(Positions(points), center, model.Rotation().col(2));
  if (!top.found) return;
  verdict->Warn(kTopSliceCode,
                Format("the highest data are one short-axis slice (%.0f "
                       "points all round on a plane %.0f deg from square to "
                       "the axis, %.1f mm rms off it): the base above it is "
                       "not in the data, and the model, its basal rings and "
                       "the volumes end at that slice",
                       top.points, top.tilt_deg, top.rms_mm));
}

// A whole ventricle's points spread most along its long axis; a model
// whose axis lies across that length fits another shape (a squat one, its
// length less than its width) to them.
void JudgeAxis(const Frame& points, const Model& model, Verdict* verdict) {
  const CloudLength length = LengthOf(Positions(points));
  const Eigen::Vector3d axis = model.Rotation().col(2);
  if (!length.Across(axis)) return;
  verdict->Fail(kAxisAcrossCode,
                Format("the model's long axis lies %.0f deg from the data's "
                       "length (their largest spread %.2f times the next): "
                       "it runs across the ventricle, whose numbers these "
                       "are not (give --apex and --base)",
                       length.DegreesFrom(axis), length.ratio));
}

// One surface through tags and contours that lie on two: the tags'
// (points seen in several frames) mean signed distance along the normal
// against the contours' (seen once).
void JudgeTwoSurfaces(const Frame& points, const FramesPerId& frames_per_id,
                      const Model& model, const FrameFit& frame,
                      Verdict* verdict) {
  if (model.config.Solid()) return;
  std::vector<bool> is_tag;
  for (const DataPoint& p : points.points) {
    is_tag.push_back(frames_per_id.at(p.id) > 1);
  }
  const auto num_tags = std::count(is_tag.begin(), is_tag.end(), true);
  if (num_tags == 0 || num_tags == static_cast<long>(is_tag.size())) return;
  const std::vector<Eigen::Vector3d> normals =
      SurfaceNormals(model, frame.material);
  double tags = 0.0, contours = 0.0;
  for (size_t i = 0; i < is_tag.size(); ++i) {
    // Residuals are model minus data: data outward read negative.
    const double outward = -frame.residuals[i].dot(normals[i]);
    (is_tag[i] ? tags : contours) += outward;
  }
  const auto num_contours = static_cast<long>(is_tag.size()) - num_tags;
  const double apart = tags / num_tags - contours / num_contours;
  if (std::abs(apart) <= kTwoSurfacesMm) return;
  verdict->Fail("two_surfaces",
                Format("the tags lie %.1f mm ", std::abs(apart)) +
                    (apart > 0.0 ? "outward" : "inward") +
                    " of the contours, on another surface: one surface "
                    "between them is neither (both walls' contours make a "
                    "solid that places the tags across the wall; or fit "
                    "them apart)");
}

// A solid's frame with no wall's contours whose tags lie near the wall's
// middle: nothing in it places the walls (tags that fill the wall have an
// rms depth of 1/sqrt(3)).
void JudgeWallsUnseen(const Frame& points, const FramesPerId& frames_per_id,
                      const ModelConfig& config, const FrameFit& frame,
                      Verdict* verdict) {
  if (!config.Solid()) return;
  double sum = 0.0;
  int tags = 0;
  for (size_t i = 0; i < points.points.size(); ++i) {
    if (points.points[i].layer != WallLayer::kAnywhere) return;
    if (frames_per_id.at(points.points[i].id) < 2) continue;
    sum += frame.material[i].w * frame.material[i].w;
    ++tags;
  }
  const double rms = tags > 0 ? std::sqrt(sum / tags) : 0.0;
  if (tags == 0 || rms >= kWallSpanningDepthRms) return;
  verdict->Warn(kWallsUnseenCode,
                Format("the tags lie near the wall's middle (rms depth "
                       "%.2f) and the frame has no contours of either wall: "
                       "nothing places its walls, whose volumes, mass and "
                       "thickening are left out",
                       rms));
}

void JudgeShape(const Eigen::Vector3d& spreads, Verdict* verdict) {
  if (spreads[0] >= kFlatDataRatio * spreads[2]) return;
  verdict->Fail("flat_data",
                Format("the points lie nearly in a plane (%.3g mm thick "
                       "against %.3g mm across): no ventricle",
                       spreads[0], spreads[2]));
}

}  // namespace

double RmsMoveMm(const Model& before, const Model& after,
                 const std::vector<MaterialPoint>& material) {
  const size_t step = StrideForAtMost(material.size(), kMoveSamples);
  std::vector<MaterialPoint> sampled;
  for (size_t i = 0; i < material.size(); i += step) {
    sampled.push_back(material[i]);
  }
  if (sampled.empty()) return 0.0;
  const std::vector<Eigen::Vector3d> from = WorldPoints(before, sampled);
  const std::vector<Eigen::Vector3d> to = WorldPoints(after, sampled);
  double sum = 0.0;
  for (size_t i = 0; i < from.size(); ++i)
    sum += (to[i] - from[i]).squaredNorm();
  return std::sqrt(sum / from.size());
}

void JudgeFrames(const PointSequence& sequence,
                 const FramesPerId& frames_per_id, const FitOptions& options,
                 SequenceFit* fit) {
  std::vector<double> rms;
  for (const FrameFit& frame : fit->frames) rms.push_back(JudgedRmsMm(frame));
  const double median_rms = Median(rms);
  const double reference_span =
      fit->frames.empty()
          ? 0.0
          : AxialSpanMm(fit->ModelAt(0), fit->frames[0].material);
  for (size_t t = 0; t < fit->frames.size(); ++t) {
    FrameFit& frame = fit->frames[t];
    const Eigen::Vector3d spreads = PrincipalSpreads(sequence.frames[t]);
    JudgeSolver(frame, &frame.verdict);
    JudgeUnsettled(frame, median_rms, &frame.verdict);
    JudgeRms(frame, median_rms, spreads.norm(),
             BothWallsOnOneSurface(sequence.frames[t], fit->config),
             &frame.verdict);
    JudgeDownWeighted(frame, &frame.verdict);
    // The pull is what the prior holds back only where the data's pull
    // balances it: at rest.  A frame short of rest has the solver's warning.
    const bool at_rest =
        frame.termination == "CONVERGENCE" || frame.termination == "REST";
    if (frame.tracked && options.prior_weight > 0 && at_rest) {
      JudgePrior(PriorPullMm(sequence.frames[t], frame, fit->config,
                             fit->frames[0].state, options),
                 frame, &frame.verdict);
    }
    JudgeBounds(fit->config, frame, &frame.verdict);
    JudgeWallThickness(fit->config, frame, &frame.verdict);
    JudgeRings(fit->config, frame, &frame.verdict);
    if (t == 0) JudgeMoved(frame, &frame.verdict);
    if (t > 0) {
      JudgeSpan(*fit, static_cast<int>(t), reference_span, &frame.verdict);
    }
    JudgeApex(*fit, &frame.verdict);
    if (!sequence.base_from_labels) {
      JudgeTopSlice(sequence.frames[t], fit->ModelAt(t), &frame.verdict);
    }
    JudgeAxis(sequence.frames[t], fit->ModelAt(t), &frame.verdict);
    JudgeShape(spreads, &frame.verdict);
    JudgeTwoSurfaces(sequence.frames[t], frames_per_id, fit->ModelAt(t), frame,
                     &frame.verdict);
    JudgeWallsUnseen(sequence.frames[t], frames_per_id, fit->config, frame,
                     &frame.verdict);
  }
}

}  // namespace pfdm
