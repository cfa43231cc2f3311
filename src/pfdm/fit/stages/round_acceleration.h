// Anderson acceleration of a frame's correspondence rounds: the rounds are
// a fixed-point iteration q -> G(q) (search the closest points on q, solve
// for them), and where plain iteration swings between two poses or creeps
// along a nearly free slide, a mix of the last few rounds' solutions
// reaches the fixed point in a few rounds (Anderson, J. ACM 12, 1965; for
// closest-point fits, Zhang, Yao and Deng, "Fast and robust iterative
// closest point", TPAMI 2022).
#ifndef PFDM_FIT_STAGES_ROUND_ACCELERATION_H_
#define PFDM_FIT_STAGES_ROUND_ACCELERATION_H_

#include <deque>
#include <vector>

#include "Eigen/Core"
#include "pfdm/fit/correspondence/correspondence.h"
#include "pfdm/model/model.h"

namespace pfdm {

// A model state as one vector (centre, quaternion, globals, knots; not the
// local field) and back.
Eigen::VectorXd StateVector(const ModelState& state);
// Writes `vector` into *state (shaped as StateVector's), the quaternion
// normalized.
void SetStateVector(const Eigen::VectorXd& vector, ModelState* state);

class RoundAcceleration {
 public:
  // The mix uses the last `memory` rounds.
  explicit RoundAcceleration(int memory = 3) : memory_(memory) {}

  // Records a round whose solution is `solution` (the solved parameters as
  // one vector) and which moved the model by `change` (G(q) - q, measured
  // where the model puts some probe points, stacked, in mm: so poses,
  // lengths and shape functions weigh by what they move) and returns the
  // parameters the next round should start from: the solution itself on
  // the first round and after a restart, else the Anderson mix (type II)
  // of the recorded rounds' solutions, unless the change shrank to under
  // half the round before's (then the solution).  The history restarts when a
  // round's change grows past twice the smallest so far: the mix then left the
  // region where it models the map.
  Eigen::VectorXd Next(Eigen::VectorXd change, Eigen::VectorXd solution);

  // Forgets the recorded rounds (after a mix that was not taken).
  void Restart();

  int restarts() const { return restarts_; }

 private:
  int memory_;
  std::deque<Eigen::VectorXd> solutions_, changes_;
  double smallest_change_ = 0.0;
  int restarts_ = 0;
};

// The model's points at `probes`, stacked (RoundAcceleration's change is
// the difference of two rounds').
Eigen::VectorXd ProbePoints(const Model& model,
                            const std::vector<MaterialPoint>& probes);

}  // namespace pfdm

#endif  // PFDM_FIT_STAGES_ROUND_ACCELERATION_H_
