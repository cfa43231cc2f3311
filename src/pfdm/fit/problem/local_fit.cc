#include "pfdm/fit/problem/local_fit.h"

#include <cmath>
#include <utility>
#include <vector>

#include "ceres/problem.h"
#include "pfdm/fit/residuals/linear_node_cost.h"
#include "pfdm/fit/residuals/square_root_form.h"

namespace pfdm {
namespace {

// The membrane term's weight against the thin plate's: one
// --local_stiffness sets both (the ratio was not tuned; the stiffness was).
constexpr double kMembraneShare = 1.0;
// A ring's mean displacement costs like this many times the ring's points
// all that far off: stiff, as the gauge terms are, without dwarfing the
// data in the integrator's stability bound.
constexpr double kRingMeanWeight = 10.0;

// The stiffness and ring-mean terms of the field's grid on its nodal
// values (which stay where they are while the problem lives), for
// `num_points` data points.
void AddLocalRegularizer(const Model& global, int num_points, double stiffness,
                         LocalField* field, ceres::Problem* problem) {
  const LocalGrid& grid = field->grid;
  auto block = [field, &grid](int row, int col) {
    return &field->values[3 * grid.Node(row, col)];
  };
  const double per_node = static_cast<double>(num_points) / grid.NumNodes();
  if (stiffness > 0.0) {
    const double membrane = std::sqrt(kMembraneShare * stiffness * per_node);
    const double plate = std::sqrt(stiffness * per_node);
    auto add = [&](double weight, const std::vector<double>& coefficients,
                   std::vector<double*> nodes) {
      problem->AddResidualBlock(MakeNodeDifferenceCost(weight, coefficients),
                                nullptr, nodes);
    };
    for (int row = 0; row + 1 < grid.rows; ++row) {
      for (int col = 0; col < grid.cols; ++col) {
        // Along the meridian, from the pole down each column.
        add(membrane, {1.0, -1.0}, {block(row, col), block(row + 1, col)});
        if (row > 0) {
          add(plate, {1.0, -2.0, 1.0},
              {block(row - 1, col), block(row, col), block(row + 1, col)});
        }
      }
    }
    for (int row = 1; row < grid.rows; ++row) {
      for (int col = 0; col < grid.cols; ++col) {
        add(membrane, {1.0, -1.0}, {block(row, col), block(row, col + 1)});
        add(plate, {1.0, -2.0, 1.0},
            {block(row, col - 1), block(row, col), block(row, col + 1)});
        if (row + 1 < grid.rows) {
          // The mixed term of the thin plate, |d_uv|^2 counted twice.
          add(std::sqrt(2.0) * plate, {1.0, -1.0, -1.0, 1.0},
              {block(row, col), block(row, col + 1), block(row + 1, col),
               block(row + 1, col + 1)});
        }
      }
    }
    // Straight through the pole: the meridians v and v + pi are one curve.
    if (grid.cols % 2 == 0) {
      for (int col = 0; col < grid.cols / 2; ++col) {
        add(plate, {1.0, -2.0, 1.0},
            {block(1, col), block(0, 0), block(1, col + grid.cols / 2)});
      }
    }
  }
  // Ring means in the global model's own directions at each node.  The
  // pole is a ring of one point: where the apex is, is the global
  // functions' too.
  const double sqrt_weight = std::sqrt(
      kRingMeanWeight * static_cast<double>(num_points) / (grid.rows - 1));
  problem->AddResidualBlock(MakeNodeDifferenceCost(sqrt_weight, {1.0}), nullptr,
                            {block(0, 0)});
  for (int row = 1; row < grid.rows; ++row) {
    const double u = grid.RowU(row);
    std::vector<Eigen::Vector3d> at(grid.cols);
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (int col = 0; col < grid.cols; ++col) {
      at[col] = global.ModelPoint(u, grid.ColV(col));
      centre += at[col] / grid.cols;
    }
    std::vector<Eigen::MatrixXd> blocks;
    std::vector<double*> nodes;
    for (int col = 0; col < grid.cols; ++col) {
      Eigen::Vector3d radial = at[col] - centre;
      radial.z() = 0.0;
      radial.normalize();
      const Eigen::Vector3d tangential = Eigen::Vector3d::UnitZ().cross(radial);
      Eigen::MatrixXd rows(5, 3);
      rows.topRows<3>() = Eigen::Matrix3d::Identity();
      rows.row(3) = radial.transpose();
      rows.row(4) = tangential.transpose();
      blocks.push_back(sqrt_weight / grid.cols * rows);
      nodes.push_back(block(row, col));
    }
    problem->AddResidualBlock(
        new LinearNodeCost(Eigen::VectorXd::Zero(5), std::move(blocks)),
        nullptr, nodes);
  }
}

}  // namespace

SolverReport FitLocalField(const std::vector<Eigen::Vector3d>& points,
                           const std::vector<MaterialPoint>& material,
                           const std::vector<bool>& sliding,
                           const FitOptions& options, Model* model) {
  const ModelConfig& config = model->config;
  model->state.local = LocalField();
  LocalGrid grid;
  grid.rows = options.local.rows;
  grid.cols = options.local.cols;
  grid.u_min = config.u_min;
  grid.u_max = config.u_max;
  LocalField field = LocalField::Zero(grid);

  // The points of each element are one residual block in square-root
  // form (square_root_form.h): the residual is linear in q_d, so its
  // n + 1 rows give the same cost as the points' own rows for every q_d,
  // and Ceres handles one block per element instead of one per point.
  // Each element sums its points' Gram matrices as they come, keeping
  // their indices to stack their rows where it has too few for the form.
  const int num_elements = (grid.rows - 1) * grid.cols;
  std::vector<Eigen::MatrixXd> element_gram(num_elements);
  std::vector<int> element_rows(num_elements, 0);
  std::vector<std::vector<size_t>> element_points(num_elements);
  std::vector<ShapeWeights> element_shape(num_elements);
  const Eigen::Matrix3d rotation = model->Rotation();
  // d moves every surface of a solid alike.
  const std::vector<Eigen::Vector3d> globals = WorldPoints(*model, material);
  const std::vector<Eigen::Vector3d> normals =
      SlidingNormals(*model, material, sliding);
  auto point_rows = [&](size_t i) {
    const ShapeWeights shape = ShapeAt(grid, material[i].u, material[i].v);
    const bool plane = normals[i] != Eigen::Vector3d::Zero();
    return LocalPointRows(globals[i], rotation, shape, points[i],
                          plane ? &normals[i] : nullptr);
  };
  for (size_t i = 0; i < points.size(); ++i) {
    const LocalElement element = ElementAt(grid, material[i].u, material[i].v);
    const int e = element.row * grid.cols + element.col;
    element_shape[e] = ShapeAt(grid, material[i].u, material[i].v);
    const LocalRows rows = point_rows(i);
    if (element_gram[e].size() == 0) {
      element_gram[e] = Eigen::MatrixXd::Zero(rows.cols(), rows.cols());
    }
    element_gram[e].noalias() += rows.transpose() * rows;
    element_rows[e] += static_cast<int>(rows.rows());
    element_points[e].push_back(i);
  }
  ceres::Problem problem;
  for (int e = 0; e < num_elements; ++e) {
    if (element_points[e].empty()) continue;
    const ShapeWeights& shape = element_shape[e];
    std::vector<double*> nodes;
    for (int k = 0; k < shape.count; ++k) {
      nodes.push_back(&field.values[3 * shape.node[k]]);
    }
    const auto stacked = [&] {
      RowMajorMatrix rows(element_rows[e], 3 * shape.count + 1);
      int height = 0;
      for (size_t i : element_points[e]) {
        const LocalRows point = point_rows(i);
        rows.middleRows(height, point.rows()) = point;
        height += static_cast<int>(point.rows());
      }
      return rows;
    };
    const int n = 3 * shape.count;
    if (element_rows[e] <= n + 1) {
      problem.AddResidualBlock(MakeLinearNodeCost(stacked()), nullptr, nodes);
      continue;
    }
    const SquareRootForm form =
        SquareRootFormFromGram(std::move(element_gram[e]), stacked);
    RowMajorMatrix square = RowMajorMatrix::Zero(n + 1, n + 1);
    square.topLeftCorner(n, n) = form.r;
    square.col(n).head(n) = form.z;
    square(n, n) = form.rho;
    problem.AddResidualBlock(MakeLinearNodeCost(square), nullptr, nodes);
  }
  AddLocalRegularizer(*model, static_cast<int>(points.size()),
                      options.local.stiffness, &field, &problem);

  SolverOptions solver = options.solver;
  solver.on_step = nullptr;
  solver.damping_scale.clear();
  solver.linear = true;
  // Sparse whatever the global solve uses: the field's problem has a node
  // grid's sparsity, and a dense solver would form its Jacobian, thousands
  // of regularizer rows by 867 columns, for a third of a second a frame.
  solver.linear_solver = ceres::SPARSE_NORMAL_CHOLESKY;
  const SolverReport report = SolveProblem(&problem, solver);
  model->state.local = std::move(field);
  return report;
}

}  // namespace pfdm
