#include "pfdm/fit/correspondence/correspondence.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <thread>

#include "Eigen/Dense"
#include "ceres/jet.h"
#include "glog/logging.h"
#include "pfdm/fit/correspondence/surface_grid.h"
#include "pfdm/model/shape_angle_derivative.h"
#include "pfdm/model/world_points.h"
#include "pfdm/util/angles.h"

namespace pfdm {

static_assert(sizeof(MaterialPoint) == 3 * sizeof(double),
              "WorldPoints reads material points as {u, v, w} triples");

std::vector<Eigen::Vector3d> WorldPoints(
    const Model& model, const std::vector<MaterialPoint>& material) {
  std::vector<Eigen::Vector3d> points(material.size());
  if (material.empty()) return points;
  WorldPoints(model, material.size(), &material[0].u, &material[0].v,
              &material[0].w, 3, points.data());
  return points;
}

std::vector<Eigen::Vector3d> Residuals(
    const Model& model, const std::vector<Eigen::Vector3d>& points,
    const std::vector<MaterialPoint>& material) {
  std::vector<Eigen::Vector3d> residuals = WorldPoints(model, material);
  for (size_t i = 0; i < residuals.size(); ++i) residuals[i] -= points[i];
  return residuals;
}

std::vector<double> AxialHeights(const Model& model,
                                 const std::vector<MaterialPoint>& material) {
  const Eigen::Vector3d axis = model.Rotation().col(2);
  std::vector<double> heights;
  heights.reserve(material.size());
  for (const Eigen::Vector3d& x : WorldPoints(model, material)) {
    heights.push_back(x.dot(axis));
  }
  return heights;
}
namespace {

constexpr int kRefinementSteps = 10;

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

// The model's world point x(u, v, w) and dx/d(u, v), the functions
// interpolated along u as WorldPointAt does, derivatives in closed form
// (ShapeAngleDerivatives) rather than through ceres::Jet, which made the
// search several times slower.  The closed form covers every layer w of
// the global model, a local field's bilinear d(u, v, w) added with its own
// Jets (cheap: no functions of the angles).
class SurfacePoints {
 public:
  SurfacePoints(const Model& model, bool jet_derivatives)
      : model_(model),
        jet_derivatives_(jet_derivatives),
        grid_(model.config.Grid()),
        free_mask_(model.config.FreeMask()),
        unit_exponents_(model.UnitExponents()),
        rotation_(model.Rotation()),
        center_(model.state.center.data()) {}

  // x in *point, dx/du and dx/dv in the columns of *jacobian.
  void Evaluate(double u, double v, double w, Eigen::Vector3d* point,
                Eigen::Matrix<double, 3, 2>* jacobian) const {
    if (jet_derivatives_) {
      using Jet2 = ceres::Jet<double, 2>;
      const Eigen::Matrix<Jet2, 3, 1> x =
          WorldPointAt(model_, Jet2(u, 0), Jet2(v, 1), w);
      for (int i = 0; i < 3; ++i) {
        (*point)[i] = x[i].a;
        jacobian->row(i) = x[i].v.transpose();
      }
      return;
    }
    const ModelConfig& config = model_.config;
    const KnotSpan span = grid_.Span(u);
    const int k1 = std::min(span.k0 + 1, config.num_knots - 1);
    const double width = grid_.KnotU(k1) - grid_.KnotU(span.k0);
    const double weight =
        config.num_knots == 1 ? 0.0 : (u - grid_.KnotU(span.k0)) / width;
    const double* knot0 = model_.state.knots[span.k0].data();
    const double* knot1 = model_.state.knots[k1].data();
    double f[kNumFunctions], df_du[kNumFunctions] = {};
    InterpolateFunctions(free_mask_, model_.state.globals.data(), knot0, knot1,
                         weight, f);
    if (config.num_knots > 1) {
      InterpolateFunctionSlopes(free_mask_, knot0, knot1, width, df_du);
    }
    const ShapeAndAngleDerivatives shape =
        ShapeAngleDerivatives(f, df_du, u, v, unit_exponents_, w);
    Eigen::Vector3d model_point = shape.shape;
    Eigen::Matrix<double, 3, 2> model_jacobian;
    model_jacobian << shape.d_u, shape.d_v;
    if (!model_.state.local.empty()) {
      AddLocal(u, v, w, &model_point, &model_jacobian);
    }
    *point = center_ + rotation_ * model_point;
    *jacobian = rotation_ * model_jacobian;
  }

 private:
  void AddLocal(double u, double v, double w, Eigen::Vector3d* point,
                Eigen::Matrix<double, 3, 2>* jacobian) const {
    using Jet2 = ceres::Jet<double, 2>;
    const Eigen::Matrix<Jet2, 3, 1> d =
        LocalDisplacement(model_.state.local, Jet2(u, 0), Jet2(v, 1), w);
    for (int i = 0; i < 3; ++i) {
      (*point)[i] += d[i].a;
      jacobian->row(i) += d[i].v.transpose();
    }
  }

  const Model& model_;
  const bool jet_derivatives_;
  const KnotGrid& grid_;
  const FunctionMask free_mask_;
  const bool unit_exponents_;
  const Eigen::Matrix3d rotation_;
  const Eigen::Vector3d center_;
};

// a^-1 b for a symmetric 2 x 2 a: Cramer's rule when a is positive
// definite (Eigen's LDLT, with its pivoting, was 7 % of a profile of the
// search), else the LDLT.
Eigen::Vector2d SolveSymmetric2(const Eigen::Matrix2d& a,
                                const Eigen::Vector2d& b) {
  const double det = a(0, 0) * a(1, 1) - a(0, 1) * a(0, 1);
  if (a(0, 0) > 0.0 && det > 0.0) {
    return Eigen::Vector2d(a(1, 1) * b[0] - a(0, 1) * b[1],
                           a(0, 0) * b[1] - a(0, 1) * b[0]) /
           det;
  }
  return a.ldlt().solve(b);
}

// A material point with its model point and dx/d(u, v).
struct SurfaceSample {
  MaterialPoint at;
  Eigen::Vector3d point;
  Eigen::Matrix<double, 3, 2> jacobian;
};

SurfaceSample Sample(const SurfacePoints& surface, const MaterialPoint& at,
                     std::int64_t* evaluations) {
  SurfaceSample sample;
  sample.at = at;
  surface.Evaluate(at.u, at.v, at.w, &sample.point, &sample.jacobian);
  ++*evaluations;
  return sample;
}

// Damped Newton on |x(u, v) - p|^2 / 2, whose Hessian is J^T J + S with
// S = sum_k r_k d2x_k/d(u, v)2, the surface's curvature seen from the
// point.  Gauss-Newton (S = 0) converges only linearly, at a rate near
// distance / radius of curvature: on frame 0, with the data millimetres off
// the initial model, most points ran into the step cap.  S is learnt from
// the steps taken (the structured secant update of NL2SOL: S delta =
// (J_new - J_old)^T r_new, a symmetric rank-one change), which costs no
// evaluation, and is left out while J^T J + S is not positive definite.
// Every evaluation brings its derivatives, so the start and an accepted
// trial point are the next step's linearization, and a step shorter than
// step_tolerance_mm ends the search before it is evaluated: the sample
// returned is the last one evaluated, derivatives included.
SurfaceSample Refine(const SurfacePoints& surface, const Model& model,
                     const Eigen::Vector3d& target, const SurfaceSample& start,
                     double step_tolerance_mm, std::int64_t* evaluations) {
  MaterialPoint best = start.at;
  Eigen::Matrix<double, 3, 2> jacobian = start.jacobian;
  Eigen::Vector3d residual = start.point - target;
  double best_cost = residual.squaredNorm();
  double lambda = 1e-3;
  Eigen::Matrix2d curvature = Eigen::Matrix2d::Zero();
  for (int step = 0; step < kRefinementSteps; ++step) {
    Eigen::Matrix2d normal = jacobian.transpose() * jacobian;
    const Eigen::Matrix2d newton = normal + curvature;
    if (newton(0, 0) > 0.0 && newton.determinant() > 0.0) normal = newton;
    const Eigen::Vector2d gradient = jacobian.transpose() * residual;
    if (gradient.norm() < 1e-12) break;
    bool improved = false, converged = false;
    for (int attempt = 0; attempt < 8 && !improved; ++attempt) {
      Eigen::Matrix2d damped = normal;
      damped.diagonal() += lambda * (normal.diagonal().array() + 1e-9).matrix();
      const Eigen::Vector2d delta = -SolveSymmetric2(damped, gradient);
      // A step this short is where the search ends: converging faster than
      // linearly, what is left is far shorter still, and evaluating the
      // step would only confirm it.
      if (attempt == 0 && (jacobian * delta).norm() < step_tolerance_mm) {
        converged = true;
        break;
      }
      const MaterialPoint trial{
          std::clamp(best.u + delta[0], model.config.u_min, model.config.u_max),
          WrapLongitude(best.v + delta[1]), best.w};
      Eigen::Vector3d trial_point;
      Eigen::Matrix<double, 3, 2> trial_jacobian;
      surface.Evaluate(trial.u, trial.v, trial.w, &trial_point,
                       &trial_jacobian);
      ++*evaluations;
      const double cost = (trial_point - target).squaredNorm();
      if (cost < best_cost) {
        const Eigen::Vector2d taken(trial.u - best.u, delta[1]);
        const Eigen::Vector3d trial_residual = trial_point - target;
        const Eigen::Vector2d secant =
            (trial_jacobian - jacobian).transpose() * trial_residual -
            curvature * taken;
        const double along = secant.dot(taken);
        if (std::abs(along) > 1e-8 * secant.norm() * taken.norm()) {
          curvature += secant * secant.transpose() / along;
        }
        best = trial;
        best_cost = cost;
        residual = trial_residual;
        jacobian = trial_jacobian;
        lambda = std::max(lambda * 0.3, 1e-9);
        improved = true;
      } else {
        lambda *= 10.0;
      }
    }
    // Converged, or no step along the gradient lowers the distance.
    if (converged || !improved) break;
  }
  return {best, target + residual, jacobian};
}

}  // namespace

template <typename T>
Eigen::Matrix<T, 3, 1> WorldPointAt(const Model& model, const T& u, const T& v,
                                    double w) {
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
          LocalDisplacement(model.state.local, u, v, w)));
}

template Eigen::Vector3d WorldPointAt(const Model&, const double&,
                                      const double&, double);
template Eigen::Matrix<ceres::Jet<double, 2>, 3, 1> WorldPointAt(
    const Model&, const ceres::Jet<double, 2>&, const ceres::Jet<double, 2>&,
    double);

namespace {

// The unit normal from the tangents dx/du and dx/dv.
Eigen::Vector3d NormalFromTangents(
    const Model& model, const Eigen::Matrix<double, 3, 2>& tangents) {
  const Eigen::Vector3d du = tangents.col(0), dv = tangents.col(1);
  // v turns counter-clockwise about +z and u runs up the axis, so
  // dv x du points out of the cavity, as the apex fallback does.
  const Eigen::Vector3d normal = dv.cross(du);
  if (normal.norm() > 1e-9 * du.squaredNorm()) return normal.normalized();
  return -model.Rotation().col(2);
}

}  // namespace

Eigen::Vector3d SurfaceNormal(const Model& model, double u, double v,
                              double w) {
  Eigen::Vector3d x;
  Eigen::Matrix<double, 3, 2> tangents;
  SurfacePoints(model, false).Evaluate(u, v, w, &x, &tangents);
  return NormalFromTangents(model, tangents);
}

std::vector<Eigen::Vector3d> SurfaceNormals(
    const Model& model, const std::vector<MaterialPoint>& material,
    std::vector<Eigen::Vector3d>* surface_points) {
  const SurfacePoints surface(model, false);
  std::vector<Eigen::Vector3d> normals(material.size());
  if (surface_points != nullptr) surface_points->resize(material.size());
  Eigen::Vector3d x;
  Eigen::Matrix<double, 3, 2> tangents;
  for (size_t i = 0; i < material.size(); ++i) {
    surface.Evaluate(material[i].u, material[i].v, material[i].w, &x,
                     &tangents);
    normals[i] = NormalFromTangents(model, tangents);
    if (surface_points != nullptr) (*surface_points)[i] = x;
  }
  return normals;
}

std::vector<Eigen::Matrix<double, 3, 2>> SurfaceTangents(
    const Model& model, const std::vector<MaterialPoint>& material) {
  const SurfacePoints surface(model, false);
  std::vector<Eigen::Matrix<double, 3, 2>> tangents(material.size());
  Eigen::Vector3d x;
  for (size_t i = 0; i < material.size(); ++i) {
    surface.Evaluate(material[i].u, material[i].v, material[i].w, &x,
                     &tangents[i]);
  }
  return tangents;
}

bool PullsAlongNormal(const ModelConfig& config, const MaterialPoint& at) {
  return at.u < config.u_max;
}

std::vector<Eigen::Vector3d> SlidingNormals(
    const Model& model, const std::vector<MaterialPoint>& material,
    const std::vector<bool>& sliding) {
  std::vector<size_t> planes;
  std::vector<MaterialPoint> plane_material;
  for (size_t i = 0; i < material.size(); ++i) {
    if (sliding[i] && PullsAlongNormal(model.config, material[i])) {
      planes.push_back(i);
      plane_material.push_back(material[i]);
    }
  }
  const std::vector<Eigen::Vector3d> plane_normals =
      SurfaceNormals(model, plane_material);
  std::vector<Eigen::Vector3d> normals(material.size(),
                                       Eigen::Vector3d::Zero());
  for (size_t j = 0; j < planes.size(); ++j) {
    normals[planes[j]] = plane_normals[j];
  }
  return normals;
}

std::vector<MaterialPoint> ClosestMaterialPoints(
    const Model& model, const std::vector<Eigen::Vector3d>& points,
    const CorrespondenceOptions& options,
    std::vector<Eigen::Vector3d>* model_points,
    std::vector<Eigen::Vector3d>* normals) {
  return ClosestMaterialPointsFrom(SurfaceGrid(model), model, points, options,
                                   model_points, normals);
}

std::vector<MaterialPoint> ClosestMaterialPointsFrom(
    const SurfaceGrid& grid, const Model& model,
    const std::vector<Eigen::Vector3d>& points,
    const CorrespondenceOptions& options,
    std::vector<Eigen::Vector3d>* model_points,
    std::vector<Eigen::Vector3d>* normals) {
  CHECK(options.hints.empty() || options.hints.size() == points.size());
  if (model_points != nullptr) model_points->resize(points.size());
  if (normals != nullptr) normals->resize(points.size());
  std::vector<MaterialPoint> result(points.size());
  const SurfacePoints surface(model, options.jet_derivatives);
  std::atomic<std::int64_t> evaluations{0};
  const auto refine_range = [&](size_t begin, size_t end) {
    std::int64_t range_evaluations = 0;
    for (size_t i = begin; i < end; ++i) {
      const double w = options.surfaces.empty() ? 0.0 : options.surfaces[i];
      // The hint's evaluation, when no grid sample is nearer, is the
      // search's first.
      std::optional<SurfaceSample> from;
      double hint_squared = std::numeric_limits<double>::infinity();
      if (!options.hints.empty() && options.hints[i].w == w) {
        from = Sample(surface, options.hints[i], &range_evaluations);
        hint_squared = (from->point - points[i]).squaredNorm();
      }
      const std::optional<SurfaceGrid::Nearest> nearest =
          grid.NearestWithin(points[i], hint_squared);
      if (nearest) {
        MaterialPoint start = grid.Sample(nearest->index);
        start.w = w;
        if (nearest->index < static_cast<size_t>(SurfaceGrid::kGridV)) {
          start.v = LongitudeAround(model, points[i], start.u);
        }
        from = Sample(surface, start, &range_evaluations);
      }
      const SurfaceSample found =
          Refine(surface, model, points[i], *from, options.step_tolerance_mm,
                 &range_evaluations);
      result[i] = found.at;
      if (model_points != nullptr) (*model_points)[i] = found.point;
      if (normals != nullptr) {
        (*normals)[i] = NormalFromTangents(model, found.jacobian);
      }
    }
    evaluations += range_evaluations;
  };
  // Threads only pay for themselves past a few hundred points (a point
  // costs ~1 us).  They take blocks of points as they free up, as
  // PrecomputedGroups' threads take groups: with fixed halves, a thread on
  // a slower vCPU would hold up the other.
  const size_t num_threads = std::clamp<size_t>(
      std::min<size_t>(options.num_threads, points.size() / 256), 1, 64);
  if (num_threads == 1) {
    refine_range(0, points.size());
  } else {
    constexpr size_t kBlock = 256;
    std::atomic<size_t> next(0);
    const auto take_blocks = [&] {
      for (size_t begin = next.fetch_add(kBlock); begin < points.size();
           begin = next.fetch_add(kBlock)) {
        refine_range(begin, std::min(points.size(), begin + kBlock));
      }
    };
    std::vector<std::thread> threads;
    for (size_t t = 1; t < num_threads; ++t) threads.emplace_back(take_blocks);
    take_blocks();
    for (std::thread& thread : threads) thread.join();
  }
  if (options.evaluations != nullptr) *options.evaluations += evaluations;
  return result;
}

}  // namespace pfdm
