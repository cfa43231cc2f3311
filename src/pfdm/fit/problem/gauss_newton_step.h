// One Levenberg-Marquardt step of a whole ceres::Problem, taken outside
// Ceres' minimizer: where the first iteration of a solve would move the
// parameters, from one evaluation with Jacobians.  The minimizer evaluates
// the point it lands on, with Jacobians, to decide whether to keep it;
// here that test is a cost evaluation, made only where the caller needs it
// (the verdict's prior probe: for steps large enough to be a reason).
#ifndef PFDM_FIT_PROBLEM_GAUSS_NEWTON_STEP_H_
#define PFDM_FIT_PROBLEM_GAUSS_NEWTON_STEP_H_

#include <functional>

#include "ceres/problem.h"

namespace pfdm {

// Moves every free parameter block of `problem` by the step d of
//   (J'J + M / radius) d = -J'r
// at their current values: J and r the problem's Jacobian (in each block's
// tangent space) and residuals, M = max(diag(J'J), 1e-6 (1 + sqrt(diag
// J'J))^2), which is Ceres' damping (its scaled diagonal clamped at 1e-6)
// in unscaled coordinates.  Each block moves by its manifold's Plus and is
// clamped to its bounds, as Ceres' candidate is, and the step is kept, as
// Ceres keeps it, only if the cost falls by at least 1e-3 of what the
// linear model predicts.  True if it was kept; false, and nothing moved,
// if it was not, or the evaluation or the factorization failed.
// `verify`, when given, is asked once the blocks have moved whether that
// test is needed (it costs an evaluation of the problem; without
// `verify`, it always is): a caller that only cares about steps of some
// size leaves the others untested.
bool TakeGaussNewtonStep(double radius, ceres::Problem* problem,
                         const std::function<bool()>& verify = nullptr);

}  // namespace pfdm

#endif  // PFDM_FIT_PROBLEM_GAUSS_NEWTON_STEP_H_
