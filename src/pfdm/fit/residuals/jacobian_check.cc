#include "pfdm/fit/residuals/jacobian_check.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "ceres/gradient_checker.h"
#include "ceres/manifold.h"
#include "pfdm/model/model.h"

namespace pfdm {
namespace {

constexpr double kHalfPi = 1.57079632679489661923;

struct State {
  double center[3] = {4.0, -7.0, 12.0};
  double quaternion[4] = {0.9, 0.1, -0.3, 0.2};
  FunctionValues globals;
  FunctionValues knot0;
  FunctionValues knot1;
  double u = 0.3, v = 1.1;
  double w = 0.0;  // The mid-wall unless a state says.
  bool unit_exponents = false;
  FunctionMask free_mask = (1u << kNumFunctions) - 1;
};

State General() {
  State s;
  const double norm = std::sqrt(0.81 + 0.01 + 0.09 + 0.04);
  for (double& q : s.quaternion) q /= norm;
  FunctionValues f = DefaultFunctionValues();
  f[kA0] = 60.0;
  f[kA1] = 0.4;
  f[kA2] = 0.35;
  f[kA3] = 0.8;
  f[kEps1] = 0.8;
  f[kEps2] = 1.2;
  f[kB0] = 1.5;
  f[kB1] = 0.4;
  f[kB2] = -0.7;
  f[kB3] = -1.0;
  f[kTau] = 0.2;
  f[kE1o] = 1.0;
  f[kE2o] = -2.0;
  f[kE3o] = 0.5;
  f[kH] = 9.0;
  f[kDtau] = 0.05;
  f[kWallShift] = 0.7;
  f[kWallSqueeze] = -0.6;
  s.globals = s.knot0 = s.knot1 = f;
  for (int i = 1; i < kNumFunctions; ++i) s.knot1[i] *= 1.1;
  return s;
}

void ForEachBlock(State* s, void (*edit)(FunctionValues*)) {
  edit(&s->globals);
  edit(&s->knot0);
  edit(&s->knot1);
}

std::vector<std::pair<std::string, State>> States() {
  std::vector<std::pair<std::string, State>> states;
  auto add = [&](const std::string& name, double u, double v) -> State& {
    State s = General();
    s.u = u;
    s.v = v;
    states.emplace_back(name, s);
    return states.back().second;
  };
  add("general", 0.3, 1.1);
  add("apex pole", -kHalfPi, 0.7);
  add("v on +x axis", -0.4, 0.0);
  add("v on +y axis", -0.4, kHalfPi);
  add("v on -x axis", -0.4, -2.0 * kHalfPi);
  add("equator", 0.0, 2.0);
  ForEachBlock(&add("eps = 1", -0.6, 0.8),
               [](FunctionValues* f) { (*f)[kEps1] = (*f)[kEps2] = 1.0; });
  ForEachBlock(&add("eps = 1 at the pole", -kHalfPi, 0.0),
               [](FunctionValues* f) { (*f)[kEps1] = (*f)[kEps2] = 1.0; });
  State& fixed_unit = add("eps = 1 held (LV set-up)", -0.9, 2.5);
  ForEachBlock(&fixed_unit,
               [](FunctionValues* f) { (*f)[kEps1] = (*f)[kEps2] = 1.0; });
  fixed_unit.unit_exponents = true;
  fixed_unit.free_mask = ModelConfig::Paper(17).FreeMask();
  ForEachBlock(&add("zero bending", 0.2, -2.2),
               [](FunctionValues* f) { (*f)[kB0] = (*f)[kB2] = 0.0; });
  ForEachBlock(&add("zero bending on an axis", 0.2, kHalfPi),
               [](FunctionValues* f) { (*f)[kB0] = (*f)[kB2] = 0.0; });
  // Cups: the ring-mean term J0(pi/2 r) cos(pi/2 b) at its largest.
  ForEachBlock(&add("cup bends", -0.5, 1.3), [](FunctionValues* f) {
    (*f)[kB1] = 0.0;
    (*f)[kB3] = 2.0;
  });
  State& identity = add("identity pose", -1.0, 0.5);
  identity.quaternion[0] = 1.0;
  identity.quaternion[1] = identity.quaternion[2] = identity.quaternion[3] = 0;
  identity.center[0] = identity.center[1] = identity.center[2] = 0.0;
  add("constant functions", 0.1, -0.3).free_mask = 0;
  // The solid's surfaces (model/transmural.h).
  add("endocardium", 0.3, 1.1).w = -1.0;
  add("epicardium", -0.4, -2.0).w = 1.0;
  add("endocardium at the apex pole", -kHalfPi, 0.7).w = -1.0;
  add("epicardium on +x axis", -0.4, 0.0).w = 1.0;
  State& cup_wall = add("epicardium, cup bends", -0.5, 1.3);
  cup_wall.w = 1.0;
  ForEachBlock(&cup_wall, [](FunctionValues* f) {
    (*f)[kB1] = 0.0;
    (*f)[kB3] = 2.0;
  });
  State& unit_wall = add("endocardium, eps = 1 held", -0.9, 2.5);
  ForEachBlock(&unit_wall,
               [](FunctionValues* f) { (*f)[kEps1] = (*f)[kEps2] = 1.0; });
  unit_wall.unit_exponents = true;
  unit_wall.w = -1.0;
  State& solid = add("inside the wall, solid LV set-up", -1.2, -0.3);
  ModelConfig solid_config = ModelConfig::Paper(17);
  solid_config.MakeSolid();
  ForEachBlock(&solid,
               [](FunctionValues* f) { (*f)[kEps1] = (*f)[kEps2] = 1.0; });
  solid.unit_exponents = true;
  solid.free_mask = solid_config.FreeMask();
  solid.w = 0.4;
  // The squeeze moves only the layers inside the wall: a state where its
  // column is live, and the middle layer (w = 0) and zero transmural
  // functions, where the wall's columns vanish.
  add("inside the wall, squeezed", 0.2, 2.2).w = -0.6;
  State& middle = add("middle layer, no wall functions", -0.6, -1.4);
  ForEachBlock(&middle, [](FunctionValues* f) {
    (*f)[kWallShift] = (*f)[kWallSqueeze] = (*f)[kDtau] = 0.0;
  });
  middle.free_mask = solid_config.FreeMask();
  State& unshaped = add("inside the wall, no shift or squeeze", 0.1, 0.5);
  ForEachBlock(&unshaped, [](FunctionValues* f) {
    (*f)[kWallShift] = (*f)[kWallSqueeze] = 0.0;
  });
  unshaped.w = 0.7;
  return states;
}

JacobianCheck Check(const std::string& name, const std::string& residual,
                    JacobianKind kind, const ceres::CostFunction& cost,
                    const State& s) {
  ceres::QuaternionManifold quaternion_manifold;
  const std::vector<const ceres::Manifold*> manifolds = {
      nullptr, &quaternion_manifold, nullptr, nullptr, nullptr};
  ceres::NumericDiffOptions numeric;
  numeric.relative_step_size = 1e-7;
  ceres::GradientChecker checker(&cost, &manifolds, numeric);
  const double* parameters[] = {s.center, s.quaternion, s.globals.data(),
                                s.knot0.data(), s.knot1.data()};
  ceres::GradientChecker::ProbeResults results;
  checker.Probe(parameters, 1e-5, &results);
  JacobianCheck check;
  check.state = name;
  check.residual = residual;
  check.jacobian = kind;
  check.finite = results.return_value;
  for (size_t i = 0; i < results.local_jacobians.size(); ++i) {
    const Eigen::MatrixXd& analytic = results.local_jacobians[i];
    const Eigen::MatrixXd& numeric_jacobian =
        results.local_numeric_jacobians[i];
    check.finite = check.finite && analytic.allFinite();
    const double scale = std::max(1e-3, numeric_jacobian.cwiseAbs().maxCoeff());
    check.block_error[i] =
        (analytic - numeric_jacobian).cwiseAbs().maxCoeff() / scale;
    check.worst = std::max(check.worst, check.block_error[i]);
  }
  if (!check.finite) check.worst = INFINITY;
  return check;
}

}  // namespace

std::vector<JacobianCheck> CheckJacobians() {
  std::vector<JacobianCheck> checks;
  const Eigen::Vector3d data(1.0, 2.0, 3.0), normal(0.6, 0.0, 0.8);
  for (const auto& [name, s] : States()) {
    for (JacobianKind kind :
         {JacobianKind::kAnalytic, JacobianKind::kAutodiff}) {
      std::unique_ptr<ceres::CostFunction> point(MakePointCost(
          data, s.u, s.v, 0.3, s.free_mask, s.unit_exponents, kind, s.w));
      checks.push_back(Check(name, "point", kind, *point, s));
      std::unique_ptr<ceres::CostFunction> surface(
          MakeSurfaceCost(data, s.u, s.v, 0.3, s.free_mask, s.unit_exponents,
                          normal, kind, s.w));
      checks.push_back(Check(name, "surface", kind, *surface, s));
    }
  }
  return checks;
}

}  // namespace pfdm
