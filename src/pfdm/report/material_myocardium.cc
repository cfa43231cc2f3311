#include "pfdm/report/material_myocardium.h"

#include <cmath>
#include <functional>

#include "pfdm/util/angles.h"

namespace pfdm {
namespace {

constexpr int kUSteps = 48, kVSteps = 72, kWSteps = 8;

// The signed volume enclosed with `origin` by the quads of a grid of
// points p(i, j), i = 0..rows, j = 0..columns - 1 and periodic in j (v),
// oriented by d/di x d/dj: (1/6) sum (a - o) . ((b - o) x (c - o)).
double GridVolume(const std::function<Eigen::Vector3d(int, int)>& at, int rows,
                  int columns, const Eigen::Vector3d& origin) {
  std::vector<Eigen::Vector3d> points;
  points.reserve((rows + 1) * columns);
  for (int i = 0; i <= rows; ++i) {
    for (int j = 0; j < columns; ++j) points.push_back(at(i, j) - origin);
  }
  auto p = [&](int i, int j) -> const Eigen::Vector3d& {
    return points[i * columns + (j % columns)];
  };
  double six_volume = 0.0;
  for (int i = 0; i < rows; ++i) {
    for (int j = 0; j < columns; ++j) {
      const Eigen::Vector3d &a = p(i, j), &b = p(i + 1, j),
                            &c = p(i + 1, j + 1), &d = p(i, j + 1);
      six_volume += a.dot(b.cross(c)) + a.dot(c.cross(d));
    }
  }
  return six_volume / 6.0;
}

}  // namespace

double MaterialMyocardiumMl(const Model& model, double u_low, double u_high) {
  const Eigen::Vector3d origin(model.state.center.data());
  auto u_at = [&](int i) { return u_low + (u_high - u_low) * i / kUSteps; };
  auto v_at = [](int j) { return -kPi + 2.0 * kPi * j / kVSteps; };
  auto w_at = [](int k) { return -1.0 + 2.0 * k / kWSteps; };
  // The parameter box's faces, each oriented outward in (u, v, w): the
  // epicardium by d/du x d/dv, the endocardium by its reverse (d/du x d/dv
  // with u run backward), the strip at u_high by d/dw x d/dv reversed,
  // i.e. rows in w backward, the strip at u_low with rows in w forward.
  const double volume =
      GridVolume(
          [&](int i, int j) { return model.WorldPoint(u_at(i), v_at(j), 1.0); },
          kUSteps, kVSteps, origin) +
      GridVolume(
          [&](int i, int j) {
            return model.WorldPoint(u_at(kUSteps - i), v_at(j), -1.0);
          },
          kUSteps, kVSteps, origin) +
      GridVolume(
          [&](int k, int j) {
            return model.WorldPoint(u_high, v_at(j), w_at(kWSteps - k));
          },
          kWSteps, kVSteps, origin) +
      GridVolume(
          [&](int k, int j) {
            return model.WorldPoint(u_low, v_at(j), w_at(k));
          },
          kWSteps, kVSteps, origin);
  return std::abs(volume) / 1000.0;
}

}  // namespace pfdm
