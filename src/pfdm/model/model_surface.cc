#include "pfdm/model/model_surface.h"

#include <cmath>

namespace pfdm {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Ring and meridian counts for volumes: chord errors shrink as the square
// of the step, 0.07 % of a sphere's volume at this resolution.
constexpr int kVolumeRings = 97;
constexpr int kVolumeMeridians = 128;

}  // namespace

ModelSurface MakeModelSurface(const Model& model, int rings, int meridians,
                              std::optional<double> u_end, double w) {
  ModelSurface surface;
  auto add = [&](double u, double v) {
    surface.mesh.points.push_back(model.WorldPoint(u, v, w));
    surface.u.push_back(u);
    surface.v.push_back(v);
    return static_cast<int>(surface.mesh.points.size()) - 1;
  };
  const double u_min = model.config.u_min;
  const double u_max = u_end.value_or(model.config.u_max);
  // first[i]: index of ring i's vertex at v = -pi; a pole ring has one.
  std::vector<int> first(rings);
  std::vector<bool> pole(rings);
  for (int i = 0; i < rings; ++i) {
    const double u = u_min + (u_max - u_min) * i / (rings - 1);
    pole[i] = std::abs(std::cos(u)) < 1e-9;
    first[i] = static_cast<int>(surface.mesh.points.size());
    for (int j = 0; j < (pole[i] ? 1 : meridians); ++j) {
      add(u, -kPi + 2.0 * kPi * j / meridians);
    }
  }
  auto at = [&](int i, int j) {
    return pole[i] ? first[i] : first[i] + j % meridians;
  };
  for (int i = 0; i + 1 < rings; ++i) {
    for (int j = 0; j < meridians; ++j) {
      // With v turning counter-clockwise about +z and u running up the
      // axis, (a, b, c) faces outward.
      const int a = at(i, j), b = at(i, j + 1);
      const int c = at(i + 1, j + 1), d = at(i + 1, j);
      if (!pole[i]) surface.mesh.triangles.push_back({a, b, c});
      if (!pole[i + 1]) surface.mesh.triangles.push_back({a, c, d});
    }
  }
  return surface;
}

double CavityVolumeMl(const Model& model, const BasePlane* base, double w) {
  if (base == nullptr) {
    const ModelSurface surface =
        MakeModelSurface(model, kVolumeRings, kVolumeMeridians, {}, w);
    return EnclosedVolume(CapBoundaryLoops(surface.mesh)) / 1000.0;
  }
  // Closed at both poles; twice the rings for twice the range of u.
  const ModelSurface closed =
      MakeModelSurface(model, 2 * kVolumeRings, kVolumeMeridians, kPi / 2, w);
  Eigen::Vector3d normal = base->normal.normalized();
  if (normal.dot(model.Rotation().col(2)) < 0.0) normal = -normal;
  return VolumeBelowPlane(closed.mesh, base->point, normal) / 1000.0;
}

}  // namespace pfdm
