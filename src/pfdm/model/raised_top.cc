#include "pfdm/model/raised_top.h"

#include <cmath>

#include "pfdm/model/parameter_function.h"

namespace pfdm {
namespace {

// The u whose ring lies at `height`, clamped to the model's ends.  Heights
// rise with u from the apex to the top.
double UAtHeight(const Model& model, double height) {
  const ModelConfig& config = model.config;
  if (height >= model.ShapeHeight(config.u_max)) return config.u_max;
  if (height <= model.ShapeHeight(config.u_min)) return config.u_min;
  double low = config.u_min, high = config.u_max;
  for (int i = 0; i < 60; ++i) {
    const double middle = 0.5 * (low + high);
    (model.ShapeHeight(middle) < height ? low : high) = middle;
  }
  return 0.5 * (low + high);
}

// A radius at u in units of a0 is a(u) |cos u|^eps1: the factor that keeps
// the radius in mm when the ring at u takes the radius of the ring at
// `from`.
double RadiusFactor(const Model& model, double from, double u) {
  const double at = std::abs(std::cos(u));
  if (at < 1e-9) return 1.0;  // The apex pole: no radius to keep.
  return std::pow(std::abs(std::cos(from)), model.FunctionAt(kEps1, from)) /
         std::pow(at, model.FunctionAt(kEps1, u));
}

}  // namespace

Model RaisedTop(const Model& model, double stretch) {
  const ModelConfig& config = model.config;
  const KnotGrid grid(config.num_knots, config.u_min, config.u_max);
  const double apex = model.ShapeHeight(config.u_min);
  Model raised = model;
  for (int k = 0; k < config.num_knots; ++k) {
    const double u = grid.KnotU(k);
    const double height = model.ShapeHeight(u);
    const double from = UAtHeight(model, height + stretch * (height - apex));
    FunctionValues& knot = raised.state.knots[k];
    for (int f : {kA1, kA2, kE1o, kE2o}) {
      if (config.modes[f] != FunctionMode::kFree) continue;
      knot[f] = model.FunctionAt(f, from) *
                (f == kA1 || f == kA2 ? RadiusFactor(model, from, u) : 1.0);
    }
  }
  raised.state.globals[kA3] *= 1.0 + stretch;
  for (FunctionValues& knot : raised.state.knots) knot[kA3] *= 1.0 + stretch;
  const Eigen::Vector3d axis = model.Rotation().col(2);
  for (int i = 0; i < 3; ++i) {
    raised.state.center[i] -= stretch * apex * axis[i];
  }
  return raised;
}

}  // namespace pfdm
