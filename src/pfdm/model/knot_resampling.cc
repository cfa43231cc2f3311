#include "pfdm/model/knot_resampling.h"

#include <vector>

namespace pfdm {

Model ResampleKnots(const Model& model, const ModelConfig& config) {
  // Config's knots first: KnotGrid's reference is valid only until the
  // thread asks for another configuration's grid, which FunctionsAt does.
  std::vector<double> knot_u(config.num_knots);
  for (int k = 0; k < config.num_knots; ++k) {
    knot_u[k] = config.Grid().KnotU(k);
  }
  Model resampled{config, model.state};
  // As Model::Uniform: what is not free reads as the globals.
  resampled.state.knots.assign(config.num_knots, model.state.globals);
  for (int k = 0; k < config.num_knots; ++k) {
    const FunctionValues values = model.FunctionsAt(knot_u[k]);
    for (int f = 0; f < kNumFunctions; ++f) {
      if (config.modes[f] == FunctionMode::kFree) {
        resampled.state.knots[k][f] = values[f];
      }
    }
  }
  return resampled;
}

}  // namespace pfdm
