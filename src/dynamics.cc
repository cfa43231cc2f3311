#include "pfdm/error.h"
#include "pfdm/solver.h"

namespace pfdm {

// Placeholders until the dynamics land (issue: the physics solvers).
SolverReport SolveDamped(ceres::Problem*, const SolverOptions&) {
  throw InputError("--solver damped is not implemented yet");
}

SolverReport SolveIntegrator(ceres::Problem*, const SolverOptions&) {
  throw InputError("--solver integrator is not implemented yet");
}

}  // namespace pfdm
