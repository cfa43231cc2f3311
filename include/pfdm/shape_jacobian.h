// The reference shape s(f; u, v) and its Jacobian ds/df in closed form: the
// chain J = dT_o/dt dT_twist/db dT_b/de de/df of the paper, term by term.
#ifndef PFDM_SHAPE_JACOBIAN_H_
#define PFDM_SHAPE_JACOBIAN_H_

#include "Eigen/Core"
#include "pfdm/parameter_function.h"
#include "pfdm/superellipsoid.h"

namespace pfdm {

using ShapeJacobian = Eigen::Matrix<double, 3, kNumFunctions>;

// Returns s = T_o(T_twist(T_b(e))) for the function values f at the
// material point with the given angles and, when jacobian is not null,
// ds/df (3 x 14, one column per function).  Matches ReferenceShape.
Eigen::Vector3d ShapeAndJacobian(const double* f, const Angles<double>& angles,
                                 bool unit_exponents, ShapeJacobian* jacobian);

}  // namespace pfdm

#endif  // PFDM_SHAPE_JACOBIAN_H_
