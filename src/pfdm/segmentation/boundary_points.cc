#include "pfdm/segmentation/boundary_points.h"

#include <array>

namespace pfdm {

namespace {

// The indicator smoothed by [1 2 1] / 4 along i and j, on the image padded
// by one voxel of 0 on each side: (nx + 2) x (ny + 2), index (j + 1) *
// (nx + 2) + i + 1.
std::vector<double> Smoothed(const SliceMask& mask) {
  const int w = mask.nx + 2, h = mask.ny + 2;
  auto value = [&](int i, int j) { return mask.At(i, j) ? 1.0 : 0.0; };
  std::vector<double> along_i(static_cast<size_t>(w) * h, 0.0);
  for (int j = -1; j <= mask.ny; ++j) {
    for (int i = -1; i <= mask.nx; ++i) {
      along_i[(j + 1) * w + i + 1] =
          0.25 * value(i - 1, j) + 0.5 * value(i, j) + 0.25 * value(i + 1, j);
    }
  }
  auto at = [&](int i, int j) {
    return i < -1 || j < -1 || i > mask.nx || j > mask.ny
               ? 0.0
               : along_i[(j + 1) * w + i + 1];
  };
  std::vector<double> smooth(along_i.size(), 0.0);
  for (int j = -1; j <= mask.ny; ++j) {
    for (int i = -1; i <= mask.nx; ++i) {
      smooth[(j + 1) * w + i + 1] =
          0.25 * at(i, j - 1) + 0.5 * at(i, j) + 0.25 * at(i, j + 1);
    }
  }
  return smooth;
}

}  // namespace

std::vector<Eigen::Vector2d> BoundaryPoints(const SliceMask& mask) {
  const std::vector<double> f = Smoothed(mask);
  const int w = mask.nx + 2;
  auto at = [&](int i, int j) { return f[(j + 1) * w + i + 1]; };
  std::vector<Eigen::Vector2d> points;
  // Each segment from a voxel centre to its +i and +j neighbour, once.
  const std::array<Eigen::Vector2i, 2> steps{Eigen::Vector2i(1, 0),
                                             Eigen::Vector2i(0, 1)};
  for (int j = -1; j <= mask.ny; ++j) {
    for (int i = -1; i <= mask.nx; ++i) {
      for (const Eigen::Vector2i& step : steps) {
        const int i2 = i + step.x(), j2 = j + step.y();
        if (i2 > mask.nx || j2 > mask.ny) continue;
        const double a = at(i, j) - 0.5, b = at(i2, j2) - 0.5;
        if ((a < 0.0) == (b < 0.0)) continue;
        const double s = a / (a - b);
        points.emplace_back(i + s * step.x(), j + s * step.y());
      }
    }
  }
  return points;
}

RegionMoments Moments(const SliceMask& mask) {
  RegionMoments moments;
  for (int j = 0; j < mask.ny; ++j) {
    for (int i = 0; i < mask.nx; ++i) {
      if (!mask.At(i, j)) continue;
      ++moments.count;
      moments.centroid += Eigen::Vector2d(i, j);
    }
  }
  if (moments.count > 0) moments.centroid /= moments.count;
  return moments;
}

bool ReachableFromBorder(const SliceMask& wall, const SliceMask& target) {
  const int nx = wall.nx, ny = wall.ny;
  std::vector<std::uint8_t> seen(static_cast<size_t>(nx) * ny, 0);
  std::vector<Eigen::Vector2i> stack;
  auto visit = [&](int i, int j) {
    if (i < 0 || j < 0 || i >= nx || j >= ny) return;
    if (seen[j * nx + i] || wall.At(i, j)) return;
    seen[j * nx + i] = 1;
    stack.emplace_back(i, j);
  };
  for (int i = 0; i < nx; ++i) {
    visit(i, 0);
    visit(i, ny - 1);
  }
  for (int j = 0; j < ny; ++j) {
    visit(0, j);
    visit(nx - 1, j);
  }
  while (!stack.empty()) {
    const Eigen::Vector2i v = stack.back();
    stack.pop_back();
    if (target.At(v.x(), v.y())) return true;
    visit(v.x() + 1, v.y());
    visit(v.x() - 1, v.y());
    visit(v.x(), v.y() + 1);
    visit(v.x(), v.y() - 1);
  }
  return false;
}

}  // namespace pfdm
