#include "pfdm/fit/data_cost.h"

#include "ceres/numeric_diff_cost_function.h"
#include "pfdm/fit/analytic_point_residual.h"
#include "pfdm/fit/point_residual.h"
#include "pfdm/util/error.h"

namespace pfdm {

JacobianKind JacobianFromName(const std::string& name) {
  if (name == "analytic") return JacobianKind::kAnalytic;
  if (name == "autodiff") return JacobianKind::kAutodiff;
  if (name == "numeric") return JacobianKind::kNumeric;
  throw InputError("unknown --jacobian '" + name +
                   "' (expected analytic, autodiff or numeric)");
}

const char* JacobianName(JacobianKind kind) {
  switch (kind) {
    case JacobianKind::kAnalytic:
      return "analytic";
    case JacobianKind::kAutodiff:
      return "autodiff";
    case JacobianKind::kNumeric:
      return "numeric";
  }
  return "";
}

ceres::CostFunction* MakePointCost(const Eigen::Vector3d& data, double u,
                                   double v, double knot_weight,
                                   FunctionMask free_mask, bool unit_exponents,
                                   JacobianKind kind) {
  switch (kind) {
    case JacobianKind::kAnalytic:
      return new AnalyticPointResidual(PointSample(data, u, v, knot_weight),
                                       free_mask, unit_exponents);
    case JacobianKind::kAutodiff:
      return PointResidual::Create(data, u, v, knot_weight, free_mask,
                                   unit_exponents);
    case JacobianKind::kNumeric:
      return new ceres::NumericDiffCostFunction<PointResidual, ceres::CENTRAL,
                                                3, 3, 4, kNumFunctions,
                                                kNumFunctions, kNumFunctions>(
          new PointResidual(data, u, v, knot_weight, free_mask,
                            unit_exponents));
  }
  return nullptr;
}

ceres::CostFunction* MakeSurfaceCost(const Eigen::Vector3d& data, double u,
                                     double v, double knot_weight,
                                     FunctionMask free_mask,
                                     bool unit_exponents,
                                     const Eigen::Vector3d& normal,
                                     JacobianKind kind) {
  switch (kind) {
    case JacobianKind::kAnalytic:
      return new AnalyticSurfaceResidual(
          PointSample(data, u, v, knot_weight, normal), free_mask,
          unit_exponents);
    case JacobianKind::kAutodiff:
      return SurfaceResidual::Create(data, u, v, knot_weight, free_mask,
                                     unit_exponents, normal);
    case JacobianKind::kNumeric:
      return new ceres::NumericDiffCostFunction<SurfaceResidual, ceres::CENTRAL,
                                                1, 3, 4, kNumFunctions,
                                                kNumFunctions, kNumFunctions>(
          new SurfaceResidual(
              PointResidual(data, u, v, knot_weight, free_mask, unit_exponents),
              normal, data));
  }
  return nullptr;
}

}  // namespace pfdm
