#include "pfdm/fit/correspondence.h"

#include <algorithm>
#include <cmath>
#include <thread>

#include "Eigen/Dense"
#include "ceres/jet.h"
#include "nanoflann.hpp"

namespace pfdm {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kGridU = 48;
constexpr int kGridV = 72;
constexpr int kRefinementSteps = 10;

// nanoflann's view of the grid samples.
struct SampleCloud {
  std::vector<Eigen::Vector3d> points;
  size_t kdtree_get_point_count() const { return points.size(); }
  double kdtree_get_pt(size_t i, size_t dim) const { return points[i][dim]; }
  template <class BoundingBox>
  bool kdtree_get_bbox(BoundingBox&) const {
    return false;
  }
};
using SampleTree = nanoflann::KDTreeSingleIndexAdaptor<
    nanoflann::L2_Simple_Adaptor<double, SampleCloud>, SampleCloud, 3>;

double WrapLongitude(double v) {
  v = std::fmod(v + kPi, 2.0 * kPi);
  if (v < 0.0) v += 2.0 * kPi;
  return v - kPi;
}

// At the apex pole every longitude gives the same model point and no
// gradient in v, so a search started there would stay on whichever meridian
// the grid offered: start from the point's own direction about the axis.
double LongitudeAround(const Model& model, const Eigen::Vector3d& point,
                       double u) {
  const Eigen::Vector3d local =
      model.Rotation().transpose() *
      (point - Eigen::Map<const Eigen::Vector3d>(model.state.center.data()));
  const FunctionValues f = model.FunctionsAt(u);
  const double angle =
      std::atan2(local.y() - f[kE2o], local.x() - f[kE1o]) - f[kTau];
  return std::atan2(std::sin(angle) / f[kA2], std::cos(angle) / f[kA1]);
}

// Gauss-Newton converges linearly here (the data sit off the surface), at a
// rate near distance / radius of curvature, so once a step is shorter than
// step_tolerance_mm what is left is a few percent of that.
MaterialPoint Refine(const Model& model, const Eigen::Vector3d& target,
                     MaterialPoint start, double step_tolerance_mm) {
  using Jet2 = ceres::Jet<double, 2>;
  MaterialPoint best = start;
  double best_cost =
      (WorldPointAt(model, best.u, best.v, best.w) - target).squaredNorm();
  double lambda = 1e-3;
  for (int step = 0; step < kRefinementSteps; ++step) {
    const Eigen::Matrix<Jet2, 3, 1> x =
        WorldPointAt(model, Jet2(best.u, 0), Jet2(best.v, 1), best.w);
    Eigen::Matrix<double, 3, 2> jacobian;
    Eigen::Vector3d residual;
    for (int i = 0; i < 3; ++i) {
      residual[i] = x[i].a - target[i];
      jacobian.row(i) = x[i].v.transpose();
    }
    Eigen::Matrix2d normal = jacobian.transpose() * jacobian;
    const Eigen::Vector2d gradient = jacobian.transpose() * residual;
    if (gradient.norm() < 1e-12) break;
    bool improved = false;
    double step_mm = 0.0;
    for (int attempt = 0; attempt < 8 && !improved; ++attempt) {
      Eigen::Matrix2d damped = normal;
      damped.diagonal() += lambda * (normal.diagonal().array() + 1e-9).matrix();
      const Eigen::Vector2d delta = -damped.ldlt().solve(gradient);
      MaterialPoint trial{
          std::clamp(best.u + delta[0], model.config.u_min, model.config.u_max),
          WrapLongitude(best.v + delta[1]), best.w};
      const double cost =
          (WorldPointAt(model, trial.u, trial.v, trial.w) - target)
              .squaredNorm();
      if (cost < best_cost) {
        best = trial;
        best_cost = cost;
        lambda = std::max(lambda * 0.3, 1e-9);
        improved = true;
        step_mm = (jacobian * delta).norm();
      } else {
        lambda *= 10.0;
      }
    }
    // Converged: further steps would only be rejected (each costing up to
    // eight evaluations) or move the point by less than anything downstream
    // can see.
    if (!improved || step_mm < step_tolerance_mm) break;
  }
  return best;
}

}  // namespace

template <typename T>
Eigen::Matrix<T, 3, 1> WorldPointAt(const Model& model, const T& u,
                                    const T& v, double w) {
  const ModelConfig& config = model.config;
  const KnotGrid& grid = config.Grid();
  double u_value;
  if constexpr (std::is_same_v<T, double>) {
    u_value = u;
  } else {
    u_value = u.a;
  }
  const KnotSpan span = grid.Span(u_value);
  const int k1 = std::min(span.k0 + 1, config.num_knots - 1);
  const T weight =
      config.num_knots == 1
          ? T(0.0)
          : (u - grid.KnotU(span.k0)) / (grid.KnotU(k1) - grid.KnotU(span.k0));
  T globals[kNumFunctions], knot0[kNumFunctions], knot1[kNumFunctions];
  for (int f = 0; f < kNumFunctions; ++f) {
    globals[f] = T(model.state.globals[f]);
    knot0[f] = T(model.state.knots[span.k0][f]);
    knot1[f] = T(model.state.knots[k1][f]);
  }
  T f[kNumFunctions];
  InterpolateFunctions(config.FreeMask(), globals, knot0, knot1, weight, f);
  T center[3], quaternion[4];
  for (int i = 0; i < 3; ++i) center[i] = T(model.state.center[i]);
  for (int i = 0; i < 4; ++i) quaternion[i] = T(model.state.quaternion[i]);
  return WorldFromModel(
      center, quaternion,
      Eigen::Matrix<T, 3, 1>(
          ReferenceShape(f, MakeAngles(u, v), model.UnitExponents(), w) +
          LocalDisplacement(model.state.local, u, v)));
}

template Eigen::Vector3d WorldPointAt(const Model&, const double&,
                                      const double&, double);

Eigen::Vector3d SurfaceNormal(const Model& model, double u, double v,
                              double w) {
  using Jet2 = ceres::Jet<double, 2>;
  const Eigen::Matrix<Jet2, 3, 1> x =
      WorldPointAt(model, Jet2(u, 0), Jet2(v, 1), w);
  Eigen::Vector3d du, dv;
  for (int i = 0; i < 3; ++i) {
    du[i] = x[i].v[0];
    dv[i] = x[i].v[1];
  }
  // v turns counter-clockwise about +z and u runs up the axis, so
  // dv x du points out of the cavity, as the apex fallback does.
  const Eigen::Vector3d normal = dv.cross(du);
  if (normal.norm() > 1e-9 * du.squaredNorm()) return normal.normalized();
  return -model.Rotation().col(2);
}

std::vector<MaterialPoint> ClosestMaterialPoints(
    const Model& model, const std::vector<Eigen::Vector3d>& points,
    const CorrespondenceOptions& options) {
  SampleCloud cloud;
  std::vector<MaterialPoint> samples;
  cloud.points.reserve(kGridU * kGridV);
  for (int i = 0; i < kGridU; ++i) {
    const double u =
        model.config.u_min +
        (model.config.u_max - model.config.u_min) * i / (kGridU - 1);
    for (int j = 0; j < kGridV; ++j) {
      const double v = -kPi + 2.0 * kPi * j / kGridV;
      samples.push_back({u, v});
      cloud.points.push_back(WorldPointAt(model, u, v));
    }
  }
  SampleTree tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10));
  tree.buildIndex();

  std::vector<MaterialPoint> result(points.size());
  const auto refine_range = [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i) {
      unsigned int nearest = 0;
      double distance_squared = 0.0;
      tree.knnSearch(points[i].data(), 1, &nearest, &distance_squared);
      MaterialPoint start = samples[nearest];
      if (!options.surfaces.empty()) start.w = options.surfaces[i];
      if (nearest < static_cast<unsigned int>(kGridV)) {
        start.v = LongitudeAround(model, points[i], start.u);
      }
      result[i] = Refine(model, points[i], start, options.step_tolerance_mm);
    }
  };
  // Threads only pay for themselves past a few hundred points (a point
  // costs ~10 us).
  const size_t num_threads = std::clamp<size_t>(
      std::min<size_t>(options.num_threads, points.size() / 256), 1, 64);
  if (num_threads == 1) {
    refine_range(0, points.size());
    return result;
  }
  std::vector<std::thread> threads;
  const size_t chunk = (points.size() + num_threads - 1) / num_threads;
  for (size_t begin = chunk; begin < points.size(); begin += chunk) {
    threads.emplace_back(refine_range, begin,
                         std::min(points.size(), begin + chunk));
  }
  refine_range(0, std::min(points.size(), chunk));
  for (std::thread& thread : threads) thread.join();
  return result;
}

}  // namespace pfdm
