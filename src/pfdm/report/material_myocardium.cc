#include "pfdm/report/material_myocardium.h"

#include <cmath>
#include <functional>
#include <vector>

#include "pfdm/model/world_points.h"
#include "pfdm/util/angles.h"

namespace pfdm {
namespace {

constexpr int kUSteps = 48, kVSteps = 72, kWSteps = 8;

// The material point (u, v, w) at grid node (i, j).
struct GridPoint {
  double u, v, w;
};

// The signed volume enclosed with `origin` by the quads of a grid of
// points p(i, j), i = 0..rows, j = 0..columns - 1 and periodic in j (v),
// oriented by d/di x d/dj: (1/6) sum (a - o) . ((b - o) x (c - o)).  The
// points in one WorldPoints batch: one at a time, a frame's myocardium
// took as long as the rest of its clinical summary.
double GridVolume(const Model& model,
                  const std::function<GridPoint(int, int)>& at, int rows,
                  int columns, const Eigen::Vector3d& origin) {
  const size_t n = static_cast<size_t>(rows + 1) * columns;
  std::vector<double> u(n), v(n), w(n);
  for (int i = 0; i <= rows; ++i) {
    for (int j = 0; j < columns; ++j) {
      const GridPoint g = at(i, j);
      const size_t k = static_cast<size_t>(i) * columns + j;
      u[k] = g.u;
      v[k] = g.v;
      w[k] = g.w;
    }
  }
  std::vector<Eigen::Vector3d> points(n);
  WorldPoints(model, n, u.data(), v.data(), w.data(), 1, points.data());
  for (Eigen::Vector3d& point : points) point -= origin;
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
          model,
          [&](int i, int j) {
            return GridPoint{u_at(i), v_at(j), 1.0};
          },
          kUSteps, kVSteps, origin) +
      GridVolume(
          model,
          [&](int i, int j) {
            return GridPoint{u_at(kUSteps - i), v_at(j), -1.0};
          },
          kUSteps, kVSteps, origin) +
      GridVolume(
          model,
          [&](int k, int j) {
            return GridPoint{u_high, v_at(j), w_at(kWSteps - k)};
          },
          kWSteps, kVSteps, origin) +
      GridVolume(
          model,
          [&](int k, int j) {
            return GridPoint{u_low, v_at(j), w_at(k)};
          },
          kWSteps, kVSteps, origin);
  return std::abs(volume) / 1000.0;
}

}  // namespace pfdm
