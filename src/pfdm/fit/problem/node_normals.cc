#include "pfdm/fit/problem/node_normals.h"

#include <vector>

#include "pfdm/fit/correspondence/correspondence.h"

namespace pfdm {

std::vector<Eigen::Vector3d> NodeNormals(const Model& global,
                                         const LocalGrid& grid) {
  Model surface = global;
  surface.state.local = LocalField();
  std::vector<MaterialPoint> nodes(grid.NumNodes());
  nodes[0].u = grid.u_min;
  for (int row = 1; row < grid.rows; ++row) {
    for (int col = 0; col < grid.cols; ++col) {
      MaterialPoint& node = nodes[grid.Node(row, col)];
      node.u = grid.RowU(row);
      node.v = grid.ColV(col);
    }
  }
  std::vector<Eigen::Vector3d> normals = SurfaceNormals(surface, nodes);
  const Eigen::Matrix3d model_from_world = surface.Rotation().transpose();
  for (Eigen::Vector3d& normal : normals) normal = model_from_world * normal;
  return normals;
}

bool AlongDirection::Plus(const double* x, const double* delta,
                          double* x_plus_delta) const {
  Eigen::Map<Eigen::Vector3d> moved(x_plus_delta);
  moved = Eigen::Map<const Eigen::Vector3d>(x) + delta[0] * direction_;
  return true;
}

bool AlongDirection::PlusJacobian(const double* /*x*/, double* jacobian) const {
  Eigen::Map<Eigen::Vector3d> column(jacobian);
  column = direction_;
  return true;
}

bool AlongDirection::Minus(const double* y, const double* x,
                           double* y_minus_x) const {
  y_minus_x[0] = direction_.dot(Eigen::Map<const Eigen::Vector3d>(y) -
                                Eigen::Map<const Eigen::Vector3d>(x));
  return true;
}

bool AlongDirection::MinusJacobian(const double* /*x*/,
                                   double* jacobian) const {
  Eigen::Map<Eigen::Vector3d> column(jacobian);
  column = direction_;
  return true;
}

}  // namespace pfdm
