// Damping for the correspondence rounds (fitter.cc) when they oscillate.
//
// A round finds each sliding point's closest material point on the model,
// then solves for the model with those points pulling along the surface's
// normals there.  The normals stay put while the solve tilts and moves the
// model, and on biv-me's contours the rounds fell into a 2-cycle: the pose
// swung by a degree and a millimetre and back, every point sliding 1-3 mm
// each round, the volume alternating by 1 %, and the frame's answer
// depended on whether the rounds ran out on an even or an odd count.  When
// a solve moves the surface back against the way the previous solve moved
// it, the model goes halfway (the fixed point of a 2-cycle lies between its
// two states), and the rounds go on from there.  Rounds that converge,
// each change along the last or unrelated to it, are left alone.
#ifndef PFDM_FIT_ROUND_RELAXATION_H_
#define PFDM_FIT_ROUND_RELAXATION_H_

#include <vector>

#include "Eigen/Core"
#include "pfdm/fit/correspondence.h"
#include "pfdm/model/model.h"

namespace pfdm {

// The state a share t of the way from `from` to `to`: every function's knots
// and globals, the centre and the quaternion (normalized) alike; the local
// field is `to`'s.
ModelState BlendStates(const ModelState& from, const ModelState& to, double t);

class RoundRelaxation {
 public:
  // The surface is watched at a grid of material points over the model's
  // range of u.
  explicit RoundRelaxation(const ModelConfig& config);

  // Called after each round's solve, from the model the solve started on
  // to the one it found (*after).  Returns whether it moved *after halfway
  // back, which it does when the surface moved against the previous
  // round's move: the cosine of the two moves, over the grid, below
  // kReversal.
  bool AfterSolve(const Model& before, Model* after);

 private:
  std::vector<MaterialPoint> samples_;
  std::vector<Eigen::Vector3d> last_move_;  // Empty before the first solve.
};

}  // namespace pfdm

#endif  // PFDM_FIT_ROUND_RELAXATION_H_
