#include "pfdm/model/model.h"

#include <cmath>
#include <utility>

#include "pfdm/util/error.h"

namespace pfdm {

ModelConfig ModelConfig::Paper(int num_knots) {
  ModelConfig config;
  config.name = "paper";
  config.num_knots = num_knots;
  config.modes.fill(FunctionMode::kFree);
  config.modes[kA0] = FunctionMode::kFixed;
  config.modes[kEps1] = FunctionMode::kFixed;
  config.modes[kEps2] = FunctionMode::kFixed;
  config.modes[kE3o] = FunctionMode::kFixed;
  config.modes[kH] = FunctionMode::kFixed;
  config.modes[kDtau] = FunctionMode::kFixed;
  config.modes[kWallShift] = FunctionMode::kFixed;
  config.modes[kWallSqueeze] = FunctionMode::kFixed;
  return config;
}

ModelConfig ModelConfig::Superellipsoid(int num_knots) {
  ModelConfig config = Paper(num_knots);
  config.name = "superellipsoid";
  for (FunctionMode& mode : config.modes) {
    if (mode == FunctionMode::kFree) mode = FunctionMode::kConstant;
  }
  return config;
}

ModelConfig ModelConfig::FromName(const std::string& name, int num_knots) {
  // The cost of a fit grows with the knots (1000 took minutes; 2^31 ran
  // out of memory); a few dozen already resolve more than the data.
  if (num_knots < 2 || num_knots > kMaxKnots) {
    throw InputError("--knots must be between 2 and " +
                     std::to_string(kMaxKnots) + ", got " +
                     std::to_string(num_knots));
  }
  if (name == "paper") return Paper(num_knots);
  if (name == "superellipsoid") return Superellipsoid(num_knots);
  throw InputError("unknown --model '" + name +
                   "' (expected paper or superellipsoid)");
}

void ModelConfig::MakeSolid() {
  modes[kH] = modes[kDtau] = modes[kWallShift] = modes[kWallSqueeze] =
      modes[kA1];
}

const KnotGrid& ModelConfig::Grid() const {
  // Model evaluation asks for the grid at every point; building it costs
  // one asin per knot.
  thread_local KnotGrid grid(num_knots, u_min, u_max);
  if (grid.num_knots() != num_knots || grid.u_min() != u_min ||
      grid.u_max() != u_max) {
    grid = KnotGrid(num_knots, u_min, u_max);
  }
  return grid;
}

FunctionMask ModelConfig::FreeMask() const {
  FunctionMask mask = 0;
  for (int f = 0; f < kNumFunctions; ++f) {
    if (modes[f] == FunctionMode::kFree) mask |= 1u << f;
  }
  return mask;
}

FunctionValues DefaultFunctionValues() {
  FunctionValues values{};
  values[kA0] = 1.0;
  values[kA1] = values[kA2] = values[kA3] = 0.5;
  values[kEps1] = values[kEps2] = 1.0;
  values[kB1] = values[kB3] = 1.0;
  return values;
}

Model Model::Uniform(const ModelConfig& config, const FunctionValues& values) {
  Model model;
  model.config = config;
  model.state.globals = values;
  model.state.knots.assign(config.num_knots, values);
  return model;
}

bool Model::UnitExponents() const {
  return config.modes[kEps1] == FunctionMode::kFixed &&
         config.modes[kEps2] == FunctionMode::kFixed &&
         state.globals[kEps1] == 1.0 && state.globals[kEps2] == 1.0;
}

FunctionValues Model::FunctionsAt(double u) const {
  const KnotSpan span = config.Grid().Span(u);
  const int k1 = std::min(span.k0 + 1, config.num_knots - 1);
  FunctionValues f;
  InterpolateFunctions(config.FreeMask(), state.globals.data(),
                       state.knots[span.k0].data(), state.knots[k1].data(),
                       span.weight, f.data());
  return f;
}

FunctionValues Model::FunctionSlopesAt(double u) const {
  FunctionValues slopes{};
  if (config.num_knots < 2) return slopes;
  const KnotGrid& grid = config.Grid();
  const KnotSpan span = grid.Span(u);
  const int k1 = span.k0 + 1;
  InterpolateFunctionSlopes(
      config.FreeMask(), state.knots[span.k0].data(), state.knots[k1].data(),
      grid.KnotU(k1) - grid.KnotU(span.k0), slopes.data());
  return slopes;
}

double Model::FunctionAt(int function, double u) const {
  return FunctionsAt(u)[function];
}

double Model::ShapeHeight(double u) const {
  return state.globals[kA0] * FunctionAt(kA3, u) * std::sin(u);
}

Eigen::Vector3d Model::ModelPoint(double u, double v, double w) const {
  return ModelPointWith(FunctionsAt(u), u, v, w);
}

Eigen::Vector3d Model::WorldPoint(double u, double v, double w) const {
  return WorldPointWith(FunctionsAt(u), u, v, w);
}

Eigen::Vector3d Model::ModelPointWith(const FunctionValues& f, double u,
                                      double v, double w) const {
  return ReferenceShape(f.data(), MakeAngles(u, v), UnitExponents(), w) +
         state.local.Displacement(u, v, w);
}

Eigen::Vector3d Model::WorldPointWith(const FunctionValues& f, double u,
                                      double v, double w) const {
  return WorldFromModel(state.center.data(), state.quaternion.data(),
                        ModelPointWith(f, u, v, w));
}

namespace {
constexpr std::pair<Function, Function> kBends[2] = {{kB0, kB1}, {kB2, kB3}};
}  // namespace

BendingShift Model::CanonicalizeBending() {
  BendingShift turns{0.0, 0.0};
  for (int i = 0; i < 2; ++i) {
    const Function shape = kBends[i].second;
    if (config.modes[shape] == FunctionMode::kFixed) continue;
    double mean = state.globals[shape];
    if (config.modes[shape] == FunctionMode::kFree) {
      mean = 0.0;
      for (const FunctionValues& knot : state.knots) mean += knot[shape];
      mean /= state.knots.size();
    }
    turns[i] = std::floor(mean / 2.0);
  }
  ShiftBending(turns);
  return turns;
}

void Model::ShiftBending(const BendingShift& turns) {
  for (int i = 0; i < 2; ++i) {
    if (turns[i] == 0.0) continue;
    const auto [amplitude, shape] = kBends[i];
    const double sign = std::fmod(std::abs(turns[i]), 2.0) == 1.0 ? -1.0 : 1.0;
    auto shift = [&](FunctionValues& values, bool free) {
      if (free == (config.modes[shape] == FunctionMode::kFree)) {
        values[shape] -= 2.0 * turns[i];
      }
      if (free == (config.modes[amplitude] == FunctionMode::kFree)) {
        values[amplitude] *= sign;
      }
    };
    shift(state.globals, false);
    for (FunctionValues& knot : state.knots) shift(knot, true);
  }
}

Eigen::Matrix3d Model::Rotation() const {
  Eigen::Matrix3d rotation;
  ceres::QuaternionToRotation(state.quaternion.data(),
                              ceres::ColumnMajorAdapter3x3(rotation.data()));
  return rotation;
}

}  // namespace pfdm
