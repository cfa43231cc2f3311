#include "pfdm/model/wall_volume.h"

#include <algorithm>

namespace pfdm {

double ModelWallVolume(const Model& model, double u_low, double u_high,
                       int u_steps, int v_steps) {
  if (!model.config.Solid()) return 0.0;
  const KnotGrid& grid = model.config.Grid();
  double volume = 0.0;
  for (int k = 0; k + 1 < grid.num_knots(); ++k) {
    const double low = std::max(grid.KnotU(k), u_low);
    const double high = std::min(grid.KnotU(k + 1), u_high);
    if (low >= high) continue;
    const FunctionValues f_low = model.FunctionsAt(low);
    const FunctionValues f_high = model.FunctionsAt(high);
    volume += WallVolume(f_low.data(), f_high.data(), low, high,
                         model.UnitExponents(), u_steps, v_steps);
  }
  return volume;
}

}  // namespace pfdm
