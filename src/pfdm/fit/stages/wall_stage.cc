#include "pfdm/fit/stages/wall_stage.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "pfdm/fit/correspondence/held_depths.h"
#include "pfdm/fit/correspondence/neighbour_noise.h"
#include "pfdm/fit/correspondence/tangential_stretch.h"
#include "pfdm/fit/correspondence/transmural.h"
#include "pfdm/fit/stages/frame_summary.h"
#include "pfdm/util/error.h"

namespace pfdm {
namespace {

// Which walls a frame's contours name.
struct WallsSeen {
  bool endo = false;
  bool epi = false;
  bool unlabelled = false;  // Tags, or points of no named wall.
};

WallsSeen WallsIn(const Frame& frame) {
  WallsSeen seen;
  for (const DataPoint& p : frame.points) {
    seen.endo = seen.endo || p.layer == WallLayer::kEndocardium;
    seen.epi = seen.epi || p.layer == WallLayer::kEpicardium;
    seen.unlabelled = seen.unlabelled || p.layer == WallLayer::kAnywhere;
  }
  return seen;
}

// --surface: the user's word for the wall the points lie on, one surface
// there.  Points labelled with the other wall contradict it.
WallDecision DeclaredSurface(const WallsSeen& walls, const FitOptions& options,
                             const std::string& source) {
  const SurfaceChoice surface = options.surface;
  const std::string flag =
      std::string("--surface ") +
      (surface == SurfaceChoice::kEndocardium  ? "endo"
       : surface == SurfaceChoice::kEpicardium ? "epi"
                                               : "midwall");
  if (options.wall == WallModel::kSolid) {
    throw InputError(flag + " declares one surface; --wall solid fits two");
  }
  if ((surface == SurfaceChoice::kEndocardium && walls.epi) ||
      (surface == SurfaceChoice::kEpicardium && walls.endo)) {
    throw InputError(source + ": " + flag + ", but frame 0 has points of the " +
                     (walls.epi ? "epicardium" : "endocardium") +
                     " (keep one wall's contours, e.g. --contours lv-cavity)");
  }
  WallDecision decision;
  decision.decided = true;
  decision.reason = flag;
  decision.surface =
      surface == SurfaceChoice::kEndocardium  ? WallLayer::kEndocardium
      : surface == SurfaceChoice::kEpicardium ? WallLayer::kEpicardium
                                              : WallLayer::kAnywhere;
  return decision;
}

std::string FormatMm(double mm) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.1f", mm);
  return text;
}

// "1,234": counts of tags read more easily so.
std::string FormatCount(size_t count) {
  std::string digits = std::to_string(count);
  for (int at = static_cast<int>(digits.size()) - 3; at > 0; at -= 3) {
    digits.insert(static_cast<size_t>(at), ",");
  }
  return digits;
}

// "tags spread 1.7 mm across the wall, 97 of 2,000 (4.9 %) left out as
// outliers (more than 2.3 mm off their neighbours)"; "of 10,000 sampled"
// where only every step-th tag was examined.
std::string SpreadReason(const RobustWallSpread& spread) {
  const size_t tags = spread.inlier.size();
  char percent[32];
  std::snprintf(percent, sizeof(percent), "%.1f",
                tags == 0 ? 0.0 : 100.0 * spread.outliers / tags);
  return "tags spread " + FormatMm(spread.spread_mm) + " mm across the wall, " +
         FormatCount(spread.outliers) + " of " + FormatCount(tags) +
         (spread.step > 1 ? " sampled" : "") + " (" + percent +
         " %) left out as outliers (more than " + FormatMm(spread.fence_mm) +
         " mm off their neighbours)";
}

// Makes *model a solid whose thickness is the one frame 0's tags span
// (distances and tag_u: those that are no outliers), tags beyond the wall
// left out of it; says how thick and how many.
std::string MakeSolidOfTags(const std::vector<double>& distances,
                            const std::vector<double>& tag_u, Model* model) {
  const std::vector<bool> inside = InsideTheWall(tag_u, distances);
  const std::vector<double> kept = KeptEntries(distances, inside);
  const double h = std::max(
      0.0, ThicknessFromDepths(
               kept, QuantileDepths(KeptEntries(tag_u, inside), kept)));
  model->config.MakeSolid();
  model->state.globals[kH] = h;
  for (FunctionValues& knot : model->state.knots) knot[kH] = h;
  return ", " + FormatMm(h) + " mm thick to start (" +
         FormatCount(distances.size() - kept.size()) +
         " beyond the wall left out)";
}

}  // namespace

WallDecision DecideWallFromContours(const Frame& first, bool has_tags,
                                    const FitOptions& options,
                                    const std::string& source,
                                    ModelConfig* config) {
  const WallsSeen walls = WallsIn(first);
  if (options.surface != SurfaceChoice::kAuto) {
    return DeclaredSurface(walls, options, source);
  }
  WallDecision decision;
  const bool one_wall = walls.endo != walls.epi && !walls.unlabelled;
  if (options.wall == WallModel::kMidwall) {
    decision.reason = "--wall midwall";
  } else if (walls.endo && walls.epi) {
    config->MakeSolid();
    decision.reason = "endocardial and epicardial contours";
  } else if (!has_tags) {
    if (options.wall == WallModel::kSolid) {
      throw InputError(source +
                       ": --wall solid needs tags tracked through the wall "
                       "or contours of both walls (lv-cavity,lv-epi)");
    }
    decision.reason = "no tracked tags and no contours of both walls";
  } else if (one_wall && options.wall != WallModel::kSolid) {
    // Tracked points all named as one wall's (a mesh's surface column):
    // that wall, not tags through the wall.
    decision.reason = std::string("tracked points of the ") +
                      (walls.endo ? "endocardium" : "epicardium") + " only";
  }
  decision.decided = !decision.reason.empty();
  if (!config->Solid() && walls.endo != walls.epi) {
    decision.surface =
        walls.endo ? WallLayer::kEndocardium : WallLayer::kEpicardium;
  }
  return decision;
}

bool DecideWallFromTags(const FramePoints& frame,
                        const std::vector<MaterialPoint>& material,
                        bool converged, WallModel wall, WallDecision* decision,
                        Model* model) {
  std::vector<Eigen::Vector3d> tag_points;
  std::vector<MaterialPoint> tag_material;
  std::vector<double> tag_u;
  for (size_t i = 0; i < frame.positions.size(); ++i) {
    if (!frame.assign_depth[i]) continue;
    tag_points.push_back(frame.positions[i]);
    tag_material.push_back(material[i]);
    tag_u.push_back(material[i].u);
  }
  std::vector<Eigen::Vector3d> midwall_points;
  const std::vector<double> distances =
      MidwallDistances(*model, tag_points, tag_material, &midwall_points);
  // Outliers would read as a wall, and widen the solid's start.
  const RobustWallSpread spread = RobustWallSpreadMm(midwall_points, distances);
  decision->decided = true;
  decision->reason = SpreadReason(spread);
  // An unfinished solve leaves tags far from the surface too: only a
  // converged one tells a wall from a fit that stopped early.
  const bool wall_seen = spread.spread_mm >= kMinWallSpreadMm && converged;
  if (wall == WallModel::kSolid || wall_seen) {
    decision->reason +=
        wall == WallModel::kSolid
            ? ": a solid (--wall solid)"
            : ": a solid (at least " + FormatMm(kMinWallSpreadMm) + " mm)";
    const std::vector<bool> inlier =
        TagInliers(spread, midwall_points, distances);
    decision->reason += MakeSolidOfTags(KeptEntries(distances, inlier),
                                        KeptEntries(tag_u, inlier), model);
    return true;
  }
  decision->reason +=
      converged
          ? ": one surface (under " + FormatMm(kMinWallSpreadMm) + " mm)"
          : ", but frame 0's mid-wall solve did not converge: one surface";
  return false;
}

Model GlobalModelOf(const ModelConfig& config, const FrameFit& frame) {
  Model global{config, frame.state};
  global.state.local = LocalField();
  return global;
}

std::optional<double> FrameTagNoiseMm(
    const Model& global, const Frame& frame,
    const std::vector<MaterialPoint>& material,
    const FramesPerId& frames_per_id, bool robust, TagNoiseFrom from,
    const Model* reference) {
  // Tracked tags only: a contour point's closest point leaves it no
  // residual along the wall.
  std::vector<size_t> tags;
  for (size_t i = 0; i < material.size(); ++i) {
    if (frames_per_id.at(frame.points[i].id) > 1) tags.push_back(i);
  }
  if (tags.empty()) return std::nullopt;
  const std::vector<Eigen::Vector3d> positions = Positions(frame);
  const std::vector<Eigen::Vector3d> residuals =
      Residuals(global, positions, material);
  // At the tags only: contour points need none.
  std::vector<double> stretch;
  if (reference != nullptr) {
    std::vector<MaterialPoint> tag_material;
    for (size_t i : tags) tag_material.push_back(material[i]);
    stretch = TangentialStretchSquared(*reference, global, tag_material);
  }
  const std::vector<double>* stretched = stretch.empty() ? nullptr : &stretch;
  if (from == TagNoiseFrom::kNeighbours) {
    return NeighbourTangentialNoiseMm(global, positions, residuals, material,
                                      tags, robust, stretched);
  }
  return TangentialNoiseMm(global, residuals, material, tags, robust,
                           stretched);
}

void HoldTagDepths(const Frame& first, const Model& reference, double sigma_mm,
                   TrackedMaterial* tracked_material) {
  std::vector<MaterialPoint*> tags;
  std::vector<MaterialPoint> material;
  std::vector<Eigen::Vector3d> points;
  for (const DataPoint& p : first.points) {
    const auto it = tracked_material->find(p.id);
    if (it == tracked_material->end()) continue;
    tags.push_back(&it->second);
    material.push_back(it->second);
    points.push_back(p.position);
  }
  const std::vector<MaterialPoint> held =
      HeldMaterialPoints(reference, points, material, sigma_mm);
  for (size_t j = 0; j < tags.size(); ++j) *tags[j] = held[j];
}

void ShrinkMeasuredDepths(const Model& reference, double sigma_mm,
                          TrackedMaterial* tracked_material) {
  for (auto& [id, material] : *tracked_material) {
    const double h = reference.FunctionsAt(material.u)[kH];
    if (h > 0.0) material.w = ShrunkDepth(material.w, 2.0 * sigma_mm / h);
  }
}

void TakeOutTagNoise(const PointSequence& sequence,
                     const FramesPerId& frames_per_id, SequenceFit* result,
                     bool robust) {
  if (result->frames.empty()) return;
  const Model reference = GlobalModelOf(result->config, result->frames[0]);
  double sum_squared = 0.0;
  int frames = 0;
  for (size_t t = 1; t < result->frames.size(); ++t) {
    const FrameFit& frame = result->frames[t];
    const std::optional<double> sigma =
        FrameTagNoiseMm(GlobalModelOf(result->config, frame),
                        sequence.frames[t], frame.material, frames_per_id,
                        robust, TagNoiseFrom::kResiduals, &reference);
    if (!sigma) continue;
    sum_squared += *sigma * *sigma;
    ++frames;
  }
  if (frames == 0) return;
  result->tag_noise_mm = std::sqrt(sum_squared / frames);
  for (size_t t = 0; t < result->frames.size(); ++t) {
    FrameFit& frame = result->frames[t];
    if (frame.depths_held || frame.depths_measured) continue;
    Model model{result->config, frame.state};
    // Frame 0 and frames without tracked points hold the squeeze at 0.
    const bool squeezed =
        frame.kind == FrameKind::kTracked &&
        result->config.modes[kWallSqueeze] != FunctionMode::kFixed;
    model.state.globals[kH] = DeconvolvedThickness(
        model.state.globals[kH], result->tag_noise_mm, squeezed);
    for (FunctionValues& knot : model.state.knots) {
      knot[kH] = DeconvolvedThickness(knot[kH], result->tag_noise_mm, squeezed);
    }
    Summarize(model, Positions(sequence.frames[t]), &frame);
  }
}

}  // namespace pfdm
