#include "pfdm/fit/problem/local_regularizer.h"

#include <cmath>
#include <utility>

#include "pfdm/fit/residuals/linear_node_cost.h"

namespace pfdm {
namespace {

// The membrane term's weight against the thin plate's: one
// --local_stiffness sets both (the ratio was not tuned; the stiffness was).
constexpr double kMembraneShare = 1.0;
// A ring's mean displacement costs like this many times the ring's points
// all that far off: stiff, as the gauge terms are, without dwarfing the
// data in the integrator's stability bound.
constexpr double kRingMeanWeight = 10.0;

// The membrane's first and the thin plate's second differences along the
// meridians and around the rings, the plate's mixed term, and the plate
// straight through the pole.
void AddStiffness(const LocalGrid& grid, double per_node, double stiffness,
                  std::vector<NodeDifference>* differences) {
  const double membrane = std::sqrt(kMembraneShare * stiffness * per_node);
  const double plate = std::sqrt(stiffness * per_node);
  auto add = [&](double weight, std::vector<double> coefficients,
                 std::vector<int> nodes) {
    differences->push_back({weight, std::move(coefficients), std::move(nodes)});
  };
  auto node = [&grid](int row, int col) { return grid.Node(row, col); };
  for (int row = 0; row + 1 < grid.rows; ++row) {
    for (int col = 0; col < grid.cols; ++col) {
      // Along the meridian, from the pole down each column.
      add(membrane, {1.0, -1.0}, {node(row, col), node(row + 1, col)});
      if (row > 0) {
        add(plate, {1.0, -2.0, 1.0},
            {node(row - 1, col), node(row, col), node(row + 1, col)});
      }
    }
  }
  for (int row = 1; row < grid.rows; ++row) {
    for (int col = 0; col < grid.cols; ++col) {
      add(membrane, {1.0, -1.0}, {node(row, col), node(row, col + 1)});
      add(plate, {1.0, -2.0, 1.0},
          {node(row, col - 1), node(row, col), node(row, col + 1)});
      if (row + 1 < grid.rows) {
        // The mixed term of the thin plate, |d_uv|^2 counted twice.
        add(std::sqrt(2.0) * plate, {1.0, -1.0, -1.0, 1.0},
            {node(row, col), node(row, col + 1), node(row + 1, col),
             node(row + 1, col + 1)});
      }
    }
  }
  // Straight through the pole: the meridians v and v + pi are one curve.
  if (grid.cols % 2 == 0) {
    for (int col = 0; col < grid.cols / 2; ++col) {
      add(plate, {1.0, -2.0, 1.0},
          {node(1, col), node(0, 0), node(1, col + grid.cols / 2)});
    }
  }
}

// Row `row`'s ring mean in the global model's own directions at its nodes.
RingMean MakeRingMean(const Model& global, const LocalGrid& grid, int row,
                      double sqrt_weight) {
  const double u = grid.RowU(row);
  std::vector<Eigen::Vector3d> at(grid.cols);
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (int col = 0; col < grid.cols; ++col) {
    at[col] = global.ModelPoint(u, grid.ColV(col));
    centre += at[col] / grid.cols;
  }
  RingMean ring;
  ring.scale = sqrt_weight / grid.cols;
  for (int col = 0; col < grid.cols; ++col) {
    Eigen::Vector3d radial = at[col] - centre;
    radial.z() = 0.0;
    radial.normalize();
    ring.nodes.push_back(grid.Node(row, col));
    ring.radial.push_back(radial);
    ring.tangential.push_back(Eigen::Vector3d::UnitZ().cross(radial));
  }
  return ring;
}

}  // namespace

LocalRegularizer MakeLocalRegularizer(const Model& global,
                                      const LocalGrid& grid, int num_points,
                                      double stiffness) {
  LocalRegularizer regularizer;
  const double per_node = static_cast<double>(num_points) / grid.NumNodes();
  if (stiffness > 0.0) {
    AddStiffness(grid, per_node, stiffness, &regularizer.differences);
  }
  // The pole is a ring of one point: where the apex is, is the global
  // functions' too.
  const double sqrt_weight = std::sqrt(
      kRingMeanWeight * static_cast<double>(num_points) / (grid.rows - 1));
  regularizer.differences.push_back({sqrt_weight, {1.0}, {grid.Node(0, 0)}});
  for (int row = 1; row < grid.rows; ++row) {
    regularizer.rings.push_back(MakeRingMean(global, grid, row, sqrt_weight));
  }
  return regularizer;
}

double RegularizerCost(const LocalRegularizer& regularizer,
                       const std::vector<double>& q) {
  const auto node = [&q](int k) { return Eigen::Vector3d(&q[3 * k]); };
  double sum = 0.0;
  for (const NodeDifference& term : regularizer.differences) {
    Eigen::Vector3d r = Eigen::Vector3d::Zero();
    for (size_t k = 0; k < term.nodes.size(); ++k) {
      r += term.coefficients[k] * node(term.nodes[k]);
    }
    sum += term.sqrt_weight * term.sqrt_weight * r.squaredNorm();
  }
  for (const RingMean& ring : regularizer.rings) {
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    double radial = 0.0, tangential = 0.0;
    for (size_t k = 0; k < ring.nodes.size(); ++k) {
      mean += node(ring.nodes[k]);
      radial += node(ring.nodes[k]).dot(ring.radial[k]);
      tangential += node(ring.nodes[k]).dot(ring.tangential[k]);
    }
    const double d = ring.displacement_scale();
    sum +=
        d * d * mean.squaredNorm() +
        ring.scale * ring.scale * (radial * radial + tangential * tangential);
  }
  return 0.5 * sum;
}

LocalRegularizer Scaled(LocalRegularizer regularizer, double factor) {
  for (NodeDifference& term : regularizer.differences) {
    term.sqrt_weight *= factor;
  }
  for (RingMean& ring : regularizer.rings) ring.scale *= factor;
  return regularizer;
}

void AddLocalRegularizer(const LocalRegularizer& regularizer, LocalField* field,
                         ceres::Problem* problem) {
  auto block = [field](int node) { return &field->values[3 * node]; };
  for (const NodeDifference& term : regularizer.differences) {
    std::vector<double*> nodes;
    for (int node : term.nodes) nodes.push_back(block(node));
    problem->AddResidualBlock(
        MakeNodeDifferenceCost(term.sqrt_weight, term.coefficients), nullptr,
        nodes);
  }
  for (const RingMean& ring : regularizer.rings) {
    std::vector<Eigen::MatrixXd> blocks;
    std::vector<double*> nodes;
    for (size_t k = 0; k < ring.nodes.size(); ++k) {
      Eigen::MatrixXd rows(5, 3);
      rows.topRows<3>() =
          ring.displacement_scale() * Eigen::Matrix3d::Identity();
      rows.row(3) = ring.scale * ring.radial[k].transpose();
      rows.row(4) = ring.scale * ring.tangential[k].transpose();
      blocks.push_back(rows);
      nodes.push_back(block(ring.nodes[k]));
    }
    problem->AddResidualBlock(
        new LinearNodeCost(Eigen::VectorXd::Zero(5), std::move(blocks)),
        nullptr, nodes);
  }
}

}  // namespace pfdm
