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
// The ring a cavity's surface stops at lies at least this far above the
// base plane: the delta method's steps move a ring by hundredths of a
// millimetre.
constexpr double kCutMarginMm = 2.0;

// A ring at u is the apex (or top) pole, one vertex.
bool IsPole(double u) { return std::abs(std::cos(u)) < 1e-9; }

// Six times the signed volume, about `origin`, of the fans that close a
// MakeModelSurface mesh's open rings (CappedVolume's lids).
double LidsSixVolume(const TriangleMesh& mesh, int meridians, bool apex_pole,
                     bool top_pole, const Eigen::Vector3d& origin) {
  auto six_volume = [&](const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                        const Eigen::Vector3d& c) {
    return (a - origin).dot((b - origin).cross(c - origin));
  };
  double six = 0.0;
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
  return six;
}

// The volume (mm^3) of a MakeModelSurface mesh with its open rings (the
// base rim; the apex ring too when it is not a pole) closed by fans about
// their centroids, facing outward as the surface does: EnclosedVolume of
// the closed mesh, its triangles summed in PlaneVolume's blocks and then
// the lids, without building it (the delta method measures it some
// thousand times; KeptCavityVolume keeps the blocks).  The rims are known from
// the layout: found from the edges (CapBoundaryLoops) they cost more than the
// surface.
double CappedVolume(const TriangleMesh& mesh, int meridians, bool apex_pole,
                    bool top_pole) {
  if (mesh.points.empty()) return 0.0;
  const Eigen::Vector3d origin = mesh.points.front();
  // The surface's triangles about the origin, unclipped (a zero normal).
  return std::abs(SixVolumeBelowPlane(mesh, origin, Eigen::Vector3d::Zero()) +
                  LidsSixVolume(mesh, meridians, apex_pole, top_pole, origin)) /
         6.0;
}

// The base plane's normal turned toward the base (the model's +z).
Eigen::Vector3d BaseNormal(const Model& model, const BasePlane& base) {
  Eigen::Vector3d normal = base.normal.normalized();
  if (normal.dot(model.Rotation().col(2)) < 0.0) normal = -normal;
  return normal;
}

// Whether the `count` vertices from `first` lie wholly more than `margin`
// mm above the base plane (on its base side).
bool WhollyAbove(const std::vector<Eigen::Vector3d>& points, int first,
                 int count, const BasePlane& base,
                 const Eigen::Vector3d& normal, double margin) {
  for (int k = first; k < first + count; ++k) {
    if (!(normal.dot(points[k] - base.point) > margin)) return false;
  }
  return true;
}

// Whether a surface cut at its first ring wholly above the plane
// (SampleSurface) still lies above it there: a move (ReplaceVertices) may
// have brought that ring down to the plane, and the volume then takes the
// whole continued surface.
bool CutHolds(const ModelSurface& surface, const BasePlane& base,
              const Eigen::Vector3d& normal) {
  return surface.cut_ring_first < 0 ||
         WhollyAbove(surface.mesh.points, surface.cut_ring_first,
                     kVolumeMeridians, base, normal, 0.0);
}

// MakeModelSurface, which with a base plane stops at the first ring past
// the rim wholly kCutMarginMm above it.  VolumeBelowPlane skips every
// triangle wholly above, so the rings after it add exactly nothing to the
// cavity's volume (past the rim, with the functions held, each ring lies
// higher up the axis and narrower than the one before, so none comes back
// down), and on biv-me's patient they were a third of the continued
// surface.
ModelSurface SampleSurface(const Model& model, int rings, int meridians,
                           std::optional<double> u_end, double w,
                           const BasePlane* cut) {
  ModelSurface surface;
  surface.w = w;
  const double u_min = model.config.u_min;
  const double u_max = u_end.value_or(model.config.u_max);
  // first[i]: index of ring i's vertex at v = -pi; a pole ring has one.
  std::vector<int> first(rings + 1);
  std::vector<bool> pole(rings);
  for (int i = 0; i < rings; ++i) {
    const double u = u_min + (u_max - u_min) * i / (rings - 1);
    pole[i] = IsPole(u);
    first[i] = static_cast<int>(surface.u.size());
    for (int j = 0; j < (pole[i] ? 1 : meridians); ++j) {
      surface.u.push_back(u);
      surface.v.push_back(-kPi + 2.0 * kPi * j / meridians);
    }
  }
  first[rings] = static_cast<int>(surface.u.size());
  // In batches (WorldPoints, round-off from WorldPoint's) of a ring each: a
  // cavity volume's 25,000 points one at a time were a tenth of a contour
  // job.
  const std::vector<double> ws(surface.u.size(), w);
  surface.mesh.points.resize(surface.u.size());
  const Eigen::Vector3d normal =
      cut == nullptr ? Eigen::Vector3d::Zero() : BaseNormal(model, *cut);
  const double u_cut = std::max(model.config.u_max, 0.0);
  int used = rings;
  for (int i = 0; i < rings; ++i) {
    const int count = first[i + 1] - first[i];
    WorldPoints(model, count, &surface.u[first[i]], &surface.v[first[i]],
                &ws[first[i]], 1, &surface.mesh.points[first[i]]);
    if (cut != nullptr && !pole[i] && i + 1 < rings &&
        surface.u[first[i]] >= u_cut &&
        WhollyAbove(surface.mesh.points, first[i], count, *cut, normal,
                    kCutMarginMm)) {
      used = i + 1;
      surface.cut_ring_first = first[i];
      break;
    }
  }
  surface.u.resize(first[used]);
  surface.v.resize(first[used]);
  surface.mesh.points.resize(first[used]);
  auto at = [&](int i, int j) {
    return pole[i] ? first[i] : first[i] + j % meridians;
  };
  for (int i = 0; i + 1 < used; ++i) {
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

}  // namespace

ModelSurface MakeModelSurface(const Model& model, int rings, int meridians,
                              std::optional<double> u_end, double w) {
  return SampleSurface(model, rings, meridians, u_end, w, nullptr);
}

ModelSurface CavitySurface(const Model& model, const BasePlane* base,
                           double w) {
  if (base == nullptr) {
    return MakeModelSurface(model, kVolumeRings, kVolumeMeridians, {}, w);
  }
  // Closed at both poles; twice the rings for twice the range of u.
  return SampleSurface(model, 2 * kVolumeRings, kVolumeMeridians, kPi / 2, w,
                       base);
}

VertexRange ReplaceVertices(const Model& model, double u_low, double u_high,
                            double w, ModelSurface* surface) {
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
  if (which.empty()) return {};
  return {which.front(), which.back() + 1};
}

double CavityVolumeMl(const Model& model, const ModelSurface& surface,
                      const BasePlane* base) {
  if (base == nullptr) {
    return CappedVolume(surface.mesh, kVolumeMeridians,
                        IsPole(model.config.u_min),
                        IsPole(model.config.u_max)) /
           1000.0;
  }
  const Eigen::Vector3d normal = BaseNormal(model, *base);
  if (!CutHolds(surface, *base, normal)) {
    return CavityVolumeMl(
        model,
        SampleSurface(model, 2 * kVolumeRings, kVolumeMeridians, kPi / 2,
                      surface.w, nullptr),
        base);
  }
  return VolumeBelowPlane(surface.mesh, base->point, normal) / 1000.0;
}

BasePlane RimPlane(const Model& model, double w) {
  std::vector<Eigen::Vector3d> rim;
  for (int j = 0; j < kVolumeMeridians; ++j) {
    rim.push_back(model.WorldPoint(model.config.u_max,
                                   -kPi + 2.0 * kPi * j / kVolumeMeridians, w));
  }
  return *FitBasePlane(rim);
}

BasePlane LowestRimPlane(const Model& model) {
  BasePlane lowest = RimPlane(model);
  if (!model.config.Solid()) return lowest;
  const Eigen::Vector3d axis = model.Rotation().col(2);
  for (const double w : {-1.0, 1.0}) {
    const BasePlane rim = RimPlane(model, w);
    if (axis.dot(rim.point) < axis.dot(lowest.point)) lowest = rim;
  }
  return lowest;
}

double LowestRimDrop(const Model& model) {
  const Eigen::Vector3d axis = model.Rotation().col(2);
  return axis.dot(RimPlane(model).point - LowestRimPlane(model).point);
}

KeptCavityVolume::KeptCavityVolume(const Model& model,
                                   const ModelSurface& surface,
                                   const BasePlane* base)
    : base_(base),
      apex_pole_(IsPole(model.config.u_min)),
      top_pole_(IsPole(model.config.u_max)) {
  if (base == nullptr) {
    if (surface.mesh.points.empty()) return;
    // About the kept apex vertex, not the moved one as CappedVolume: the
    // volume does not depend on the origin, and a step that moves the apex
    // then moves only the terms of the triangles that use it.
    origin_ = surface.mesh.points.front();
    blocks_.emplace(surface.mesh, origin_, Eigen::Vector3d::Zero());
    ml_ = FlatLidMl(surface.mesh, blocks_->six_volume());
    return;
  }
  normal_ = BaseNormal(model, *base);
  if (CutHolds(surface, *base, normal_)) {
    blocks_.emplace(surface.mesh, base->point, normal_);
    ml_ = blocks_->volume() / 1000.0;  // CavityVolumeMl's, to the bit.
    return;
  }
  ml_ = CavityVolumeMl(model, surface, base);
}

double KeptCavityVolume::FlatLidMl(const TriangleMesh& mesh,
                                   double surface_six_volume) const {
  return std::abs(surface_six_volume + LidsSixVolume(mesh, kVolumeMeridians,
                                                     apex_pole_, top_pole_,
                                                     origin_)) /
         6.0 / 1000.0;
}

double KeptCavityVolume::MovedMl(const Model& moved_model,
                                 const ModelSurface& moved,
                                 const VertexRange& changed) const {
  if (blocks_ && base_ == nullptr) {
    return FlatLidMl(moved.mesh, blocks_->MovedSixVolume(
                                     moved.mesh, changed.first, changed.last));
  }
  if (!blocks_ || BaseNormal(moved_model, *base_) != normal_ ||
      !CutHolds(moved, *base_, normal_)) {
    return CavityVolumeMl(moved_model, moved, base_);
  }
  return blocks_->Moved(moved.mesh, changed.first, changed.last) / 1000.0;
}

double CavityVolumeMl(const Model& model, const BasePlane* base, double w) {
  return CavityVolumeMl(model, CavitySurface(model, base, w), base);
}

}  // namespace pfdm
