#include "pfdm/model/world_points.h"

#include <algorithm>

#include "pfdm/model/model_point.h"
#include "pfdm/model/shape_jacobian.h"
#include "pfdm/util/batch_trig.h"

namespace pfdm {

void WorldPoints(const Model& model, size_t n, const double* u, const double* v,
                 const double* w, size_t stride, Eigen::Vector3d* out) {
  constexpr int kBatch = 32;
  const bool unit_exponents = model.UnitExponents();
  const bool local = !model.state.local.empty();
  FunctionValues f[kBatch];
  ShapePrelude preludes[kBatch];
  double uv[2 * kBatch], uv_sines[2 * kBatch], uv_cosines[2 * kBatch];
  double angles[kBatch * kNumShapeAngles];
  double sines[kBatch * kNumShapeAngles], cosines[kBatch * kNumShapeAngles];
  for (size_t first = 0; first < n; first += kBatch) {
    const int count = static_cast<int>(std::min<size_t>(kBatch, n - first));
    for (int i = 0; i < count; ++i) {
      uv[2 * i] = u[(first + i) * stride];
      uv[2 * i + 1] = v[(first + i) * stride];
    }
    SinCosMany(uv, 2 * count, uv_sines, uv_cosines);
    for (int i = 0; i < count; ++i) {
      f[i] = model.FunctionsAt(uv[2 * i]);
      const Angles<double> point_angles{uv_cosines[2 * i], uv_sines[2 * i],
                                        uv_cosines[2 * i + 1],
                                        uv_sines[2 * i + 1]};
      preludes[i] = PrepareShape(f[i].data(), point_angles, unit_exponents,
                                 w[(first + i) * stride]);
      std::copy(preludes[i].angles, preludes[i].angles + kNumShapeAngles,
                angles + i * kNumShapeAngles);
    }
    SinCosMany(angles, count * kNumShapeAngles, sines, cosines);
    for (int i = 0; i < count; ++i) {
      const int at = i * kNumShapeAngles;
      Eigen::Vector3d p = ShapeAndJacobian(f[i].data(), preludes[i], sines + at,
                                           cosines + at, nullptr);
      if (local) p += model.state.local.Displacement(uv[2 * i], uv[2 * i + 1]);
      out[first + i] = WorldFromModel(model.state.center.data(),
                                      model.state.quaternion.data(), p);
    }
  }
}

}  // namespace pfdm
