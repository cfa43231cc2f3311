#include "pfdm/fit/residuals/data_cost.h"

#include "ceres/numeric_diff_cost_function.h"
#include "pfdm/fit/residuals/analytic_point_residual.h"
#include "pfdm/fit/residuals/point_residual.h"
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
                                   JacobianKind kind, double w) {
  switch (kind) {
    case JacobianKind::kAnalytic: {
      PointSample sample(data, u, v, knot_weight);
      sample.w = w;
      return new AnalyticPointResidual(sample, free_mask, unit_exponents);
    }
    case JacobianKind::kAutodiff:
      return PointResidual::Create(data, u, v, knot_weight, free_mask,
                                   unit_exponents, w);
    case JacobianKind::kNumeric:
      return new ceres::NumericDiffCostFunction<PointResidual, ceres::CENTRAL,
                                                3, 3, 4, kNumFunctions,
                                                kNumFunctions, kNumFunctions>(
          new PointResidual(data, u, v, knot_weight, free_mask, unit_exponents,
                            w));
  }
  return nullptr;
}

ceres::CostFunction* MakeSurfaceCost(const Eigen::Vector3d& data, double u,
                                     double v, double knot_weight,
                                     FunctionMask free_mask,
                                     bool unit_exponents,
                                     const Eigen::Vector3d& normal,
                                     JacobianKind kind, double w) {
  switch (kind) {
    case JacobianKind::kAnalytic: {
      PointSample sample(data, u, v, knot_weight, normal);
      sample.w = w;
      return new AnalyticSurfaceResidual(sample, free_mask, unit_exponents);
    }
    case JacobianKind::kAutodiff:
      return SurfaceResidual::Create(data, u, v, knot_weight, free_mask,
                                     unit_exponents, normal, w);
    case JacobianKind::kNumeric:
      return new ceres::NumericDiffCostFunction<SurfaceResidual, ceres::CENTRAL,
                                                1, 3, 4, kNumFunctions,
                                                kNumFunctions, kNumFunctions>(
          new SurfaceResidual(PointResidual(data, u, v, knot_weight, free_mask,
                                            unit_exponents, w),
                              normal, data));
  }
  return nullptr;
}

}  // namespace pfdm
