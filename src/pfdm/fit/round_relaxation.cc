#include "pfdm/fit/round_relaxation.h"

#include <cmath>
#include <utility>

namespace pfdm {
namespace {

constexpr double kPi = 3.14159265358979323846;
// The grid: 12 rings by 24 meridians, the local field's spacing.
constexpr int kRings = 12;
constexpr int kMeridians = 24;
// A move whose cosine with the last is below this goes back: a 2-cycle
// reverses at -0.9 to -1.0 (biv-me's contours); a round that overshoots a
// little and settles, near 0.
constexpr double kReversal = -0.5;

std::vector<Eigen::Vector3d> Moves(const std::vector<Eigen::Vector3d>& from,
                                   const std::vector<Eigen::Vector3d>& to) {
  std::vector<Eigen::Vector3d> moves(from.size());
  for (size_t i = 0; i < from.size(); ++i) moves[i] = to[i] - from[i];
  return moves;
}

}  // namespace

ModelState BlendStates(const ModelState& from, const ModelState& to, double t) {
  ModelState blend = to;
  auto mix = [t](double a, double b) { return a + t * (b - a); };
  for (int i = 0; i < 3; ++i)
    blend.center[i] = mix(from.center[i], to.center[i]);
  // q and -q are one rotation: blend within one hemisphere.
  double dot = 0.0;
  for (int i = 0; i < 4; ++i) dot += from.quaternion[i] * to.quaternion[i];
  const double sign = dot < 0.0 ? -1.0 : 1.0;
  double norm = 0.0;
  for (int i = 0; i < 4; ++i) {
    blend.quaternion[i] = mix(from.quaternion[i], sign * to.quaternion[i]);
    norm += blend.quaternion[i] * blend.quaternion[i];
  }
  for (double& q : blend.quaternion) q /= std::sqrt(norm);
  for (int f = 0; f < kNumFunctions; ++f) {
    blend.globals[f] = mix(from.globals[f], to.globals[f]);
  }
  for (size_t k = 0; k < blend.knots.size(); ++k) {
    for (int f = 0; f < kNumFunctions; ++f) {
      blend.knots[k][f] = mix(from.knots[k][f], to.knots[k][f]);
    }
  }
  return blend;
}

RoundRelaxation::RoundRelaxation(const ModelConfig& config) {
  for (int ring = 0; ring < kRings; ++ring) {
    const double u =
        config.u_min + (config.u_max - config.u_min) * (ring + 0.5) / kRings;
    for (int meridian = 0; meridian < kMeridians; ++meridian) {
      samples_.push_back({u, -kPi + 2.0 * kPi * meridian / kMeridians, 0.0});
    }
  }
}

bool RoundRelaxation::AfterSolve(const Model& before, Model* after) {
  const std::vector<Eigen::Vector3d> start = WorldPoints(before, samples_);
  std::vector<Eigen::Vector3d> move =
      Moves(start, WorldPoints(*after, samples_));
  double dot = 0.0, last_norm = 0.0, norm = 0.0;
  for (size_t i = 0; i < last_move_.size(); ++i) {
    dot += move[i].dot(last_move_[i]);
    last_norm += last_move_[i].squaredNorm();
    norm += move[i].squaredNorm();
  }
  const bool reversed =
      !last_move_.empty() && dot < kReversal * std::sqrt(last_norm * norm);
  if (reversed) {
    after->state = BlendStates(before.state, after->state, 0.5);
    move = Moves(start, WorldPoints(*after, samples_));
  }
  last_move_ = std::move(move);
  return reversed;
}

}  // namespace pfdm
