#include "pfdm/model/model_surface.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "pfdm/model/world_points.h"
#include "pfdm/util/angles.h"

namespace pfdm {
namespace {

// Ring and meridian counts for volumes: chord errors shrink as the square
// of the step, 0.07 % of a sphere's volume at this resolution.
constexpr int kVolumeRings = 97;
constexpr int kVolumeMeridians = 128;

// A ring at u is the apex (or top) pole, one vertex.
bool IsPole(double u) { return std::abs(std::cos(u)) < 1e-9; }

// The volume (mm^3) of a MakeModelSurface mesh with its open rings (the
// base rim; the apex ring too when it is not a pole) closed by fans about
// their centroids, facing outward as the surface does: EnclosedVolume of
// the closed mesh, summed in its order, without building it (the delta
// method measures it some thousand times).  The rims are known from the
// layout: found from the edges (CapBoundaryLoops) they cost more than the
// surface.
double CappedVolume(const TriangleMesh& mesh, int meridians, bool apex_pole,
                    bool top_pole) {
  if (mesh.points.empty()) return 0.0;
  const Eigen::Vector3d origin = mesh.points.front();
  auto six_volume = [&](const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                        const Eigen::Vector3d& c) {
    return (a - origin).dot((b - origin).cross(c - origin));
  };
  double six = 0.0;
  for (const auto& t : mesh.triangles) {
    six += six_volume(mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]]);
  }
  const int n = static_cast<int>(mesh.points.size());
  auto cap = [&](int first, bool reversed) {
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (int j = 0; j < meridians; ++j) centroid += mesh.points[first + j];
    centroid = centroid / meridians;
    for (int j = 0; j < meridians; ++j) {
      const Eigen::Vector3d& a = mesh.points[first + j];
      const Eigen::Vector3d& b = mesh.points[first + (j + 1) % meridians];
      six += reversed ? six_volume(b, a, centroid) : six_volume(a, b, centroid);
    }
  };
  // The surface runs j -> j + 1 along its first ring and back along its
  // last: each lid runs the other way.
  if (!apex_pole) cap(0, true);
  if (!top_pole) cap(n - meridians, false);
  return std::abs(six) / 6.0;
}

}  // namespace

ModelSurface MakeModelSurface(const Model& model, int rings, int meridians,
                              std::optional<double> u_end, double w) {
  ModelSurface surface;
  auto add = [&](double u, double v) {
    surface.u.push_back(u);
    surface.v.push_back(v);
    return static_cast<int>(surface.u.size()) - 1;
  };
  const double u_min = model.config.u_min;
  const double u_max = u_end.value_or(model.config.u_max);
  // first[i]: index of ring i's vertex at v = -pi; a pole ring has one.
  std::vector<int> first(rings);
  std::vector<bool> pole(rings);
  for (int i = 0; i < rings; ++i) {
    const double u = u_min + (u_max - u_min) * i / (rings - 1);
    pole[i] = IsPole(u);
    first[i] = static_cast<int>(surface.u.size());
    for (int j = 0; j < (pole[i] ? 1 : meridians); ++j) {
      add(u, -kPi + 2.0 * kPi * j / meridians);
    }
  }
  // In batches (WorldPoints, round-off from WorldPoint's): a cavity
  // volume's 25,000 points one at a time were a tenth of a contour job.
  const std::vector<double> ws(surface.u.size(), w);
  surface.mesh.points.resize(surface.u.size());
  WorldPoints(model, surface.u.size(), surface.u.data(), surface.v.data(),
              ws.data(), 1, surface.mesh.points.data());
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

ModelSurface CavitySurface(const Model& model, const BasePlane* base,
                           double w) {
  if (base == nullptr) {
    return MakeModelSurface(model, kVolumeRings, kVolumeMeridians, {}, w);
  }
  // Closed at both poles; twice the rings for twice the range of u.
  return MakeModelSurface(model, 2 * kVolumeRings, kVolumeMeridians, kPi / 2,
                          w);
}

void ReplaceVertices(const Model& model, double u_low, double u_high, double w,
                     ModelSurface* surface) {
  std::vector<double> u, v;
  std::vector<size_t> which;
  // A vertex past the rim (u > u_max) has the functions at u_max.
  const double u_max = model.config.u_max;
  for (size_t i = 0; i < surface->u.size(); ++i) {
    const double at = std::min(surface->u[i], u_max);
    if (at < u_low || at > u_high) continue;
    which.push_back(i);
    u.push_back(surface->u[i]);
    v.push_back(surface->v[i]);
  }
  const std::vector<double> ws(u.size(), w);
  std::vector<Eigen::Vector3d> points(u.size());
  WorldPoints(model, u.size(), u.data(), v.data(), ws.data(), 1, points.data());
  for (size_t k = 0; k < which.size(); ++k) {
    surface->mesh.points[which[k]] = points[k];
  }
}

double CavityVolumeMl(const Model& model, const ModelSurface& surface,
                      const BasePlane* base) {
  if (base == nullptr) {
    return CappedVolume(surface.mesh, kVolumeMeridians,
                        IsPole(model.config.u_min),
                        IsPole(model.config.u_max)) /
           1000.0;
  }
  Eigen::Vector3d normal = base->normal.normalized();
  if (normal.dot(model.Rotation().col(2)) < 0.0) normal = -normal;
  return VolumeBelowPlane(surface.mesh, base->point, normal) / 1000.0;
}

double CavityVolumeMl(const Model& model, const BasePlane* base, double w) {
  return CavityVolumeMl(model, CavitySurface(model, base, w), base);
}

}  // namespace pfdm
