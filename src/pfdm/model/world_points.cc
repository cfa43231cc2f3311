#include "pfdm/model/world_points.h"

#include <algorithm>

#include "pfdm/model/model_point.h"
#include "pfdm/model/shape_jacobian.h"
#include "pfdm/util/batch_trig.h"

namespace pfdm {

void WorldPoints(const Model& model, size_t n, const double* u, const double* v,
                 const double* w, size_t stride, Eigen::Vector3d* out) {
  const bool unit_exponents = model.UnitExponents();
  const bool local = !model.state.local.empty();
  FunctionValues f[kShapeBatch];
  Angles<double> angles[kShapeBatch];
  double point_w[kShapeBatch];
  double uv[2 * kShapeBatch], uv_sines[2 * kShapeBatch],
      uv_cosines[2 * kShapeBatch];
  double last_u = 0.0;
  FunctionValues last_f;
  for (size_t first = 0; first < n; first += kShapeBatch) {
    const int count =
        static_cast<int>(std::min<size_t>(kShapeBatch, n - first));
    for (int i = 0; i < count; ++i) {
      uv[2 * i] = u[(first + i) * stride];
      uv[2 * i + 1] = v[(first + i) * stride];
      point_w[i] = w[(first + i) * stride];
    }
    SinCosMany(uv, 2 * count, uv_sines, uv_cosines);
    for (int i = 0; i < count; ++i) {
      // Surfaces and grids come ring by ring: a ring's points share u.
      if (first + i == 0 || uv[2 * i] != last_u) {
        last_u = uv[2 * i];
        last_f = model.FunctionsAt(last_u);
      }
      f[i] = last_f;
      angles[i] = {uv_cosines[2 * i], uv_sines[2 * i], uv_cosines[2 * i + 1],
                   uv_sines[2 * i + 1]};
    }
    ShapesOfBatch(count, f, angles, point_w, unit_exponents, false,
                  [&](int i, const Eigen::Vector3d& s, const ShapeJacobian&) {
                    Eigen::Vector3d p = s;
                    if (local) {
                      p += model.state.local.Displacement(
                          uv[2 * i], uv[2 * i + 1], point_w[i]);
                    }
                    out[first + i] =
                        WorldFromModel(model.state.center.data(),
                                       model.state.quaternion.data(), p);
                  });
  }
}

}  // namespace pfdm
