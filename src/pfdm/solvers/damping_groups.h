// Parameter groups of the model for the integrator's damping: which
// multiplier of D each function gets.
#ifndef PFDM_SOLVERS_DAMPING_GROUPS_H_
#define PFDM_SOLVERS_DAMPING_GROUPS_H_

#include <string>

#include "pfdm/model/parameter_function.h"

namespace pfdm {

// Multipliers of the integrator's damping per parameter group
// (SolverOptions::damping_scale): a group with a larger one moves slower.
struct DampingGroups {
  double pose = 1.0;     // Centre and rotation (frame 0 only).
  double shape = 1.0;    // a0..a3, eps1, eps2.
  double twist = 1.0;    // tau.
  double bending = 1.0;  // b0..b3.
  double offsets = 1.0;  // e1o, e2o, e3o.
  double Of(Function f) const;
};

// "group=value,..." with groups pose, shape, twist, bending, offsets;
// throws InputError naming the bad entry.
DampingGroups DampingGroupsFromText(const std::string& text);

}  // namespace pfdm

#endif  // PFDM_SOLVERS_DAMPING_GROUPS_H_
