#include "pfdm/fit/stages/round_acceleration.h"

#include <cmath>
#include <utility>

#include "Eigen/QR"
#include "glog/logging.h"

namespace pfdm {
namespace {

// A round whose change grows past this many times the smallest so far
// restarts the history (RoundAcceleration::Next).
constexpr double kRestartGrowth = 2.0;

// Rounds whose change shrinks to under this share of the round before's
// are not mixed: the plain rounds converge (the LV phantom's contours).
constexpr double kMixAbove = 0.5;

}  // namespace

Eigen::VectorXd StateVector(const ModelState& state) {
  const int knots = static_cast<int>(state.knots.size());
  Eigen::VectorXd vector(7 + (1 + knots) * kNumFunctions);
  int at = 0;
  for (double c : state.center) vector[at++] = c;
  for (double q : state.quaternion) vector[at++] = q;
  for (double g : state.globals) vector[at++] = g;
  for (const FunctionValues& knot : state.knots) {
    for (double f : knot) vector[at++] = f;
  }
  return vector;
}

void SetStateVector(const Eigen::VectorXd& vector, ModelState* state) {
  CHECK_EQ(vector.size(), StateVector(*state).size());
  int at = 0;
  for (double& c : state->center) c = vector[at++];
  double norm = 0.0;
  for (double& q : state->quaternion) {
    q = vector[at++];
    norm += q * q;
  }
  for (double& q : state->quaternion) q /= std::sqrt(norm);
  for (double& g : state->globals) g = vector[at++];
  for (FunctionValues& knot : state->knots) {
    for (double& f : knot) f = vector[at++];
  }
}

Eigen::VectorXd ProbePoints(const Model& model,
                            const std::vector<MaterialPoint>& probes) {
  const std::vector<Eigen::Vector3d> points = WorldPoints(model, probes);
  Eigen::VectorXd stacked(3 * points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    stacked.segment<3>(3 * i) = points[i];
  }
  return stacked;
}

void RoundAcceleration::Restart() {
  solutions_.clear();
  changes_.clear();
  ++restarts_;
}

Eigen::VectorXd RoundAcceleration::Next(Eigen::VectorXd change,
                                        Eigen::VectorXd solution) {
  const double size = change.norm();
  if (!changes_.empty() && size > kRestartGrowth * smallest_change_) {
    Restart();
  }
  if (changes_.empty() || size < smallest_change_) smallest_change_ = size;
  solutions_.push_back(std::move(solution));
  changes_.push_back(std::move(change));
  if (static_cast<int>(changes_.size()) > memory_ + 1) {
    solutions_.pop_front();
    changes_.pop_front();
  }
  const int m = static_cast<int>(changes_.size()) - 1;
  if (m == 0) return solutions_.back();
  // Rounds that contract well are left as they are: far from the fixed
  // point the map is too far from linear for the mix.
  if (size < kMixAbove * changes_[m - 1].norm()) return solutions_.back();
  // gamma = argmin |f_k - dF gamma|, dF's columns the differences of
  // successive rounds' changes; the mix is G(q_k) - dG gamma.
  Eigen::MatrixXd d_change(changes_.back().size(), m);
  Eigen::MatrixXd d_solution(solutions_.back().size(), m);
  for (int j = 0; j < m; ++j) {
    d_change.col(j) = changes_[j + 1] - changes_[j];
    d_solution.col(j) = solutions_[j + 1] - solutions_[j];
  }
  const Eigen::VectorXd gamma =
      d_change.colPivHouseholderQr().solve(changes_.back());
  return solutions_.back() - d_solution * gamma;
}

}  // namespace pfdm
