#include "pfdm/report/material_rings.h"

#include <cmath>
#include <vector>

#include "pfdm/fit/correspondence/correspondence.h"
#include "pfdm/model/world_points.h"
#include "pfdm/util/angles.h"

namespace pfdm {

// In one batch (WorldPoints: the ring's functions and Bessel values once,
// the sines and cosines vectorized; round-off from WorldPointWith's): the
// regional analysis samples 60 rings a frame.
MaterialRing SampleRing(const Model& model, double u, int samples, double w) {
  MaterialRing ring;
  std::vector<double> us(samples, u), vs(samples), ws(samples, w);
  for (int j = 0; j < samples; ++j) {
    vs[j] = -kPi + 2.0 * kPi * (j + 0.5) / samples;
  }
  ring.points.resize(samples);
  WorldPoints(model, samples, us.data(), vs.data(), ws.data(), 1,
              ring.points.data());
  for (const Eigen::Vector3d& point : ring.points) ring.centroid += point;
  ring.centroid /= samples;
  return ring;
}

double MeanRadius(const MaterialRing& ring) {
  double sum = 0.0;
  for (const Eigen::Vector3d& p : ring.points)
    sum += (p - ring.centroid).norm();
  return sum / ring.points.size();
}

double AngleAbout(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                  const Eigen::Vector3d& axis) {
  const Eigen::Vector3d pa = a - a.dot(axis) * axis;
  const Eigen::Vector3d pb = b - b.dot(axis) * axis;
  return std::atan2(pa.cross(pb).dot(axis), pa.dot(pb));
}

double MeanRotation(const MaterialRing& from, const MaterialRing& to,
                    const Eigen::Vector3d& axis) {
  double sum = 0.0;
  for (size_t j = 0; j < from.points.size(); ++j) {
    sum += AngleAbout(from.points[j] - from.centroid,
                      to.points[j] - to.centroid, axis);
  }
  return sum / from.points.size();
}

namespace {

// The chord from endo to epi along the unit `normal`.
double ThicknessAlong(const Eigen::Vector3d& endo, const Eigen::Vector3d& epi,
                      const Eigen::Vector3d& normal) {
  return std::abs((epi - endo).dot(normal));
}

}  // namespace

double WallThickness(const Model& model, double u, double v) {
  const FunctionValues f = model.FunctionsAt(u);
  return ThicknessAlong(model.WorldPointWith(f, u, v, -1.0),
                        model.WorldPointWith(f, u, v, 1.0),
                        SurfaceNormal(model, u, v));
}

double MeanWallThickness(const Model& model, double u) {
  double sum = 0.0;
  for (int j = 0; j < kRingSamples; ++j) {
    sum += WallThickness(model, u, -kPi + 2.0 * kPi * (j + 0.5) / kRingSamples);
  }
  return sum / kRingSamples;
}

double WallThickness(const Model& model, double u, double v,
                     const Eigen::Vector3d& endo, const Eigen::Vector3d& epi,
                     const Eigen::Vector3d& xu, const Eigen::Vector3d& xv) {
  // dv x du, as SurfaceNormal orients it (the sign does not matter here).
  const Eigen::Vector3d normal = xv.cross(xu);
  if (!(normal.norm() > 1e-9 * xu.squaredNorm())) {
    return WallThickness(model, u, v);
  }
  return ThicknessAlong(endo, epi, normal.normalized());
}

double RingHeight(const Model& model, double u) {
  return model.ShapeHeight(u) + model.FunctionAt(kE3o, u);
}

double RingAtHeightFraction(const Model& reference, double h) {
  double low = reference.config.u_min, high = reference.config.u_max;
  const double apex = RingHeight(reference, low);
  const double target = apex + h * (RingHeight(reference, high) - apex);
  // The height rises monotonically from apex to base on a fitted frame 0.
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (low + high);
    (RingHeight(reference, mid) < target ? low : high) = mid;
  }
  return 0.5 * (low + high);
}

double RingAtHeightFraction(const Model& reference, double h, double w) {
  const double u_mid = RingAtHeightFraction(reference, h);
  if (w == 0.0) return u_mid;
  const double target = RingHeight(reference, u_mid);
  // Surface w's ring height, model frame: the mean of its points' z.
  auto height = [&](double u) {
    double sum = 0.0;
    constexpr int kSamples = 24;
    for (int j = 0; j < kSamples; ++j) {
      sum += reference.ModelPoint(u, -kPi + 2.0 * kPi * (j + 0.5) / kSamples, w)
                 .z();
    }
    return sum / kSamples;
  };
  double low = reference.config.u_min, high = reference.config.u_max;
  if (height(low) >= target) return low;
  if (height(high) <= target) return high;
  for (int i = 0; i < 50; ++i) {
    const double mid = 0.5 * (low + high);
    (height(mid) < target ? low : high) = mid;
  }
  return 0.5 * (low + high);
}

Eigen::Vector3d LongAxis(const Model& model) { return model.Rotation().col(2); }

}  // namespace pfdm
