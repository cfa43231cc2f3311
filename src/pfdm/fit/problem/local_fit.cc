#include "pfdm/fit/problem/local_fit.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "ceres/problem.h"
#include "pfdm/fit/residuals/linear_node_cost.h"
#include "pfdm/fit/residuals/robust_loss.h"
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
// With a robust loss, the field is solved again with the weights at its
// residuals until no point's weight changes by kReweightTolerance, or
// kMaxReweightings solves.
constexpr int kMaxReweightings = 10;
constexpr double kReweightTolerance = 0.01;

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

// The local field's data: each point's rows at its element
// (LocalPointRows), scaled by the square root of its weight when the loss
// weighs the points.
class LocalData {
 public:
  LocalData(const std::vector<Eigen::Vector3d>& points,
            const std::vector<MaterialPoint>& material,
            const std::vector<bool>& sliding, const LocalGrid& grid,
            const Model& model)
      : points_(points),
        material_(material),
        grid_(grid),
        rotation_(model.Rotation()),
        // d moves every surface of a solid alike.
        globals_(WorldPoints(model, material)),
        normals_(SlidingNormals(model, material, sliding)) {}

  size_t size() const { return points_.size(); }
  LocalElement Element(size_t i) const {
    return ElementAt(grid_, material_[i].u, material_[i].v);
  }
  ShapeWeights Shape(size_t i) const {
    return ShapeAt(grid_, material_[i].u, material_[i].v);
  }
  // Point i's rows, weighed by sqrt_weights (empty: all 1).
  LocalRows Rows(size_t i) const {
    const bool plane = normals_[i] != Eigen::Vector3d::Zero();
    LocalRows rows = LocalPointRows(globals_[i], rotation_, Shape(i),
                                    points_[i], plane ? &normals_[i] : nullptr);
    if (!sqrt_weights_.empty()) rows *= sqrt_weights_[i];
    return rows;
  }
  // Each point's residual (its rows' size) under `field`, unweighted.
  std::vector<Eigen::Vector3d> Residuals(const LocalField& field) const;
  void set_sqrt_weights(std::vector<double> sqrt_weights) {
    sqrt_weights_ = std::move(sqrt_weights);
  }

 private:
  const std::vector<Eigen::Vector3d>& points_;
  const std::vector<MaterialPoint>& material_;
  const LocalGrid& grid_;
  const Eigen::Matrix3d rotation_;
  const std::vector<Eigen::Vector3d> globals_;
  const std::vector<Eigen::Vector3d> normals_;
  std::vector<double> sqrt_weights_;
};

std::vector<Eigen::Vector3d> LocalData::Residuals(
    const LocalField& field) const {
  std::vector<Eigen::Vector3d> residuals(size(), Eigen::Vector3d::Zero());
  for (size_t i = 0; i < size(); ++i) {
    const bool plane = normals_[i] != Eigen::Vector3d::Zero();
    const ShapeWeights shape = Shape(i);
    const LocalRows rows =
        LocalPointRows(globals_[i], rotation_, shape, points_[i],
                       plane ? &normals_[i] : nullptr);
    const int n = 3 * shape.count;
    Eigen::VectorXd q(n);
    for (int k = 0; k < shape.count; ++k) {
      q.segment<3>(3 * k) = Eigen::Vector3d(&field.values[3 * shape.node[k]]);
    }
    residuals[i].head(rows.rows()) = rows.leftCols(n) * q + rows.col(n);
  }
  return residuals;
}

// The points of each element are one residual block in square-root form
// (square_root_form.h): the residual is linear in q_d, so its n + 1 rows
// give the same cost as the points' own rows for every q_d, and Ceres
// handles one block per element instead of one per point.  Each element
// sums its points' Gram matrices as they come, keeping their indices to
// stack their rows where it has too few for the form.
void AddLocalData(const LocalData& data, LocalField* field,
                  ceres::Problem* problem) {
  const LocalGrid& grid = field->grid;
  const int num_elements = (grid.rows - 1) * grid.cols;
  std::vector<Eigen::MatrixXd> element_gram(num_elements);
  std::vector<int> element_rows(num_elements, 0);
  std::vector<std::vector<size_t>> element_points(num_elements);
  std::vector<ShapeWeights> element_shape(num_elements);
  for (size_t i = 0; i < data.size(); ++i) {
    const LocalElement element = data.Element(i);
    const int e = element.row * grid.cols + element.col;
    element_shape[e] = data.Shape(i);
    const LocalRows rows = data.Rows(i);
    if (element_gram[e].size() == 0) {
      element_gram[e] = Eigen::MatrixXd::Zero(rows.cols(), rows.cols());
    }
    element_gram[e].noalias() += rows.transpose() * rows;
    element_rows[e] += static_cast<int>(rows.rows());
    element_points[e].push_back(i);
  }
  for (int e = 0; e < num_elements; ++e) {
    if (element_points[e].empty()) continue;
    const ShapeWeights& shape = element_shape[e];
    std::vector<double*> nodes;
    for (int k = 0; k < shape.count; ++k) {
      nodes.push_back(&field->values[3 * shape.node[k]]);
    }
    const auto stacked = [&] {
      RowMajorMatrix rows(element_rows[e], 3 * shape.count + 1);
      int height = 0;
      for (size_t i : element_points[e]) {
        const LocalRows point = data.Rows(i);
        rows.middleRows(height, point.rows()) = point;
        height += static_cast<int>(point.rows());
      }
      return rows;
    };
    const int n = 3 * shape.count;
    if (element_rows[e] <= n + 1) {
      problem->AddResidualBlock(MakeLinearNodeCost(stacked()), nullptr, nodes);
      continue;
    }
    const SquareRootForm form =
        SquareRootFormFromGram(std::move(element_gram[e]), stacked);
    RowMajorMatrix square = RowMajorMatrix::Zero(n + 1, n + 1);
    square.topLeftCorner(n, n) = form.r;
    square.col(n).head(n) = form.z;
    square(n, n) = form.rho;
    problem->AddResidualBlock(MakeLinearNodeCost(square), nullptr, nodes);
  }
}

// One linear solve of the field for the data's current weights, from
// *field's values.
SolverReport SolveLocal(const LocalData& data, const Model& model,
                        const FitOptions& options, LocalField* field) {
  ceres::Problem problem;
  AddLocalData(data, field, &problem);
  AddLocalRegularizer(model, static_cast<int>(data.size()),
                      options.local.stiffness, field, &problem);
  SolverOptions solver = options.solver;
  solver.on_step = nullptr;
  solver.damping_scale.clear();
  solver.linear = true;
  // Sparse whatever the global solve uses: the field's problem has a node
  // grid's sparsity, and a dense solver would form its Jacobian, thousands
  // of regularizer rows by 867 columns, for a third of a second a frame.
  solver.linear_solver = ceres::SPARSE_NORMAL_CHOLESKY;
  return SolveProblem(&problem, solver);
}

// Square roots of the loss's weights of the data's points under `field`.
std::vector<double> SqrtLossWeights(const LocalData& data,
                                    const FitOptions& options,
                                    const LocalField& field) {
  std::vector<double> weights =
      LossWeights(options.loss, options.loss_scale_mm, data.Residuals(field));
  for (double& w : weights) w = std::sqrt(w);
  return weights;
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
  LocalData data(points, material, sliding, grid, *model);
  const bool robust = options.loss != "none";
  // With a loss, iteratively reweighted least squares: each solve weighs
  // the points by the loss at their residuals under the last field (the
  // global fit's first), which ends at a minimum of the loss's cost and
  // keeps the problem linear, in square-root form.
  std::vector<double> sqrt_weights;
  if (robust) sqrt_weights = SqrtLossWeights(data, options, field);
  data.set_sqrt_weights(sqrt_weights);
  SolverReport report = SolveLocal(data, *model, options, &field);
  for (int pass = 1; robust && pass < kMaxReweightings && report.usable;
       ++pass) {
    const std::vector<double> next = SqrtLossWeights(data, options, field);
    double change = 0.0;
    for (size_t i = 0; i < next.size(); ++i) {
      change = std::max(change, std::abs(next[i] * next[i] -
                                         sqrt_weights[i] * sqrt_weights[i]));
    }
    if (change < kReweightTolerance) break;
    sqrt_weights = next;
    data.set_sqrt_weights(sqrt_weights);
    const int iterations = report.iterations;
    report = SolveLocal(data, *model, options, &field);
    report.iterations += iterations;
  }
  model->state.local = std::move(field);
  return report;
}

}  // namespace pfdm
