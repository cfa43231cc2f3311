// Chooses how the data residuals are differentiated.
#ifndef PFDM_FIT_RESIDUALS_DATA_COST_H_
#define PFDM_FIT_RESIDUALS_DATA_COST_H_

#include <string>

#include "Eigen/Core"
#include "ceres/cost_function.h"
#include "pfdm/model/model_point.h"

namespace pfdm {

enum class JacobianKind { kAnalytic, kAutodiff, kNumeric };

// "analytic", "autodiff" or "numeric"; throws InputError otherwise.
JacobianKind JacobianFromName(const std::string& name);
const char* JacobianName(JacobianKind kind);

// The 3-vector residual of a tracked point (PointResidual) on surface w.
ceres::CostFunction* MakePointCost(const Eigen::Vector3d& data, double u,
                                   double v, double knot_weight,
                                   FunctionMask free_mask, bool unit_exponents,
                                   JacobianKind kind, double w = 0.0);

// The point-to-plane residual (SurfaceResidual).
ceres::CostFunction* MakeSurfaceCost(const Eigen::Vector3d& data, double u,
                                     double v, double knot_weight,
                                     FunctionMask free_mask,
                                     bool unit_exponents,
                                     const Eigen::Vector3d& normal,
                                     JacobianKind kind, double w = 0.0);

}  // namespace pfdm

#endif  // PFDM_FIT_RESIDUALS_DATA_COST_H_
