#include "pfdm/model/local_field.h"

#include <algorithm>
#include <cstdio>

#include "pfdm/util/angles.h"
#include "pfdm/util/error.h"

namespace pfdm {

double LocalGrid::ColV(int col) const { return -kPi + 2.0 * kPi * col / cols; }

LocalGrid ParseLocalGrid(const std::string& text) {
  LocalGrid grid;
  int consumed = 0;
  if (std::sscanf(text.c_str(), "%dx%d%n", &grid.rows, &grid.cols, &consumed) !=
          2 ||
      consumed != static_cast<int>(text.size()) ||
      grid.rows < LocalGrid::kMinRows || grid.rows > LocalGrid::kMaxRows ||
      grid.cols < LocalGrid::kMinCols || grid.cols > LocalGrid::kMaxCols) {
    throw InputError("--local_grid must be NUxNV with " +
                     std::to_string(LocalGrid::kMinRows) + " to " +
                     std::to_string(LocalGrid::kMaxRows) + " rows and " +
                     std::to_string(LocalGrid::kMinCols) + " to " +
                     std::to_string(LocalGrid::kMaxCols) + " columns, got '" +
                     text + "'");
  }
  return grid;
}

LocalElement ElementAt(const LocalGrid& grid, double u, double v) {
  LocalElement e;
  e.du = (grid.u_max - grid.u_min) / (grid.rows - 1);
  const double row =
      (std::clamp(u, grid.u_min, grid.u_max) - grid.u_min) / e.du;
  // row >= 0, so the cast is the floor.
  e.row = std::clamp(static_cast<int>(row), 0, grid.rows - 2);
  e.u0 = grid.RowU(e.row);
  e.dv = 2.0 * kPi / grid.cols;
  const double column = std::floor((v + kPi) / e.dv);
  e.v0 = -kPi + column * e.dv;
  // v in [-pi, pi), nearly always: its column as it is, without the
  // modulo's division (every point of every surface and sample finds its
  // element here).
  const int col = static_cast<int>(column);
  e.col = col >= 0 && col < grid.cols
              ? col
              : ((col % grid.cols) + grid.cols) % grid.cols;
  return e;
}

ShapeWeights ShapeAt(const LocalGrid& grid, double u, double v) {
  const LocalElement e = ElementAt(grid, u, v);
  const double s = std::clamp(
      (std::clamp(u, grid.u_min, grid.u_max) - e.u0) / e.du, 0.0, 1.0);
  const double t = std::clamp((v - e.v0) / e.dv, 0.0, 1.0);
  ShapeWeights shape;
  auto add = [&shape](int node, double weight) {
    shape.node[shape.count] = node;
    shape.weight[shape.count] = weight;
    ++shape.count;
  };
  if (e.row == 0) {
    add(grid.Node(0, 0), 1.0 - s);
  } else {
    add(grid.Node(e.row, e.col), (1.0 - s) * (1.0 - t));
    add(grid.Node(e.row, e.col + 1), (1.0 - s) * t);
  }
  add(grid.Node(e.row + 1, e.col), s * (1.0 - t));
  add(grid.Node(e.row + 1, e.col + 1), s * t);
  return shape;
}

LocalField LocalField::Zero(const LocalGrid& grid, bool transmural) {
  LocalField field;
  field.grid = grid;
  field.values.assign(3 * grid.NumNodes(), 0.0);
  if (transmural) field.slope = field.kink = field.values;
  return field;
}

Eigen::Vector3d LocalField::Displacement(double u, double v, double w) const {
  return LocalDisplacement(*this, u, v, w);
}

std::vector<double> LocalField::Coefficients() const {
  std::vector<double> all = values;
  all.insert(all.end(), slope.begin(), slope.end());
  all.insert(all.end(), kink.begin(), kink.end());
  return all;
}

void LocalField::SetCoefficients(const double* coefficients) {
  std::copy(coefficients, coefficients + values.size(), values.begin());
  std::copy(coefficients + values.size(),
            coefficients + values.size() + slope.size(), slope.begin());
  std::copy(coefficients + values.size() + slope.size(),
            coefficients + values.size() + slope.size() + kink.size(),
            kink.begin());
}

void LocalField::AddCoefficients(const std::vector<double>& change) {
  for (size_t i = 0; i < change.size(); ++i) {
    if (i < values.size()) {
      values[i] += change[i];
    } else if (i - values.size() < slope.size()) {
      slope[i - values.size()] += change[i];
    } else if (i - values.size() - slope.size() < kink.size()) {
      kink[i - values.size() - slope.size()] += change[i];
    }
  }
}

}  // namespace pfdm
