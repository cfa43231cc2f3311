#include "pfdm/fit/problem/local_direct.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include "Eigen/Cholesky"
#include "pfdm/fit/problem/lower_band.h"
#include "pfdm/util/band_cholesky.h"
#include "pfdm/util/stopwatch.h"

namespace pfdm {
namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;
// Nodal values, a node's (x, y, z) per row, as LocalField keeps them.
using NodeMatrix = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;
// U's rows of one coordinate: a node per row, two columns per ring.
using RingColumns = std::array<Eigen::MatrixXd, 3>;

double Weight(const LocalDirectData& data, size_t i) {
  return data.weights.empty() ? 1.0 : data.weights[i];
}

Eigen::Vector3d Normal(const LocalDirectData& data, size_t i) {
  return data.normals.empty() ? Eigen::Vector3d::Zero() : data.normals[i];
}

bool HasNormals(const LocalDirectData& data) {
  for (const Eigen::Vector3d& normal : data.normals) {
    if (!normal.isZero(0.0)) return true;
  }
  return false;
}

// Appends a term of K: its weight, node count, nodes and (when not null:
// all 1) coefficients.
void AppendTerm(double weight, int count, const int* nodes,
                const double* coefficients, std::vector<double>* signature) {
  signature->push_back(weight);
  signature->push_back(count);
  signature->insert(signature->end(), nodes, nodes + count);
  if (coefficients != nullptr) {
    signature->insert(signature->end(), coefficients, coefficients + count);
  }
}

// Appends the regularizer's terms and, with `directions`, the ring means'
// radial and tangential directions (which the whole A takes, and K leaves
// to the Woodbury columns).
void AppendRegularizer(const LocalRegularizer& regularizer, bool directions,
                       std::vector<double>* signature) {
  for (const NodeDifference& term : regularizer.differences) {
    AppendTerm(term.sqrt_weight, static_cast<int>(term.nodes.size()),
               term.nodes.data(), term.coefficients.data(), signature);
  }
  for (const RingMean& ring : regularizer.rings) {
    AppendTerm(ring.displacement_scale(), static_cast<int>(ring.nodes.size()),
               ring.nodes.data(), nullptr, signature);
    if (!directions) continue;
    for (size_t k = 0; k < ring.nodes.size(); ++k) {
      signature->insert(signature->end(), ring.radial[k].data(),
                        ring.radial[k].data() + 3);
      signature->insert(signature->end(), ring.tangential[k].data(),
                        ring.tangential[k].data() + 3);
    }
  }
}

// Everything K is made of, in order: equal signatures, equal K.
std::vector<double> Signature(const LocalDirectData& data,
                              const LocalRegularizer& regularizer,
                              int num_nodes) {
  std::vector<double> signature = {static_cast<double>(num_nodes)};
  for (size_t i = 0; i < data.shapes.size(); ++i) {
    const ShapeWeights& shape = data.shapes[i];
    AppendTerm(Weight(data, i), shape.count, shape.node.data(),
               shape.weight.data(), &signature);
  }
  AppendRegularizer(regularizer, /*directions=*/false, &signature);
  return signature;
}

// Calls visit(weight, count, nodes, coefficients) for each term of K, in
// K's order (coefficients null: all 1).
template <typename Visit>
void ForEachScalarTerm(const LocalDirectData& data,
                       const LocalRegularizer& regularizer, Visit visit) {
  for (size_t i = 0; i < data.shapes.size(); ++i) {
    const ShapeWeights& shape = data.shapes[i];
    visit(Weight(data, i), shape.count, shape.node.data(), shape.weight.data());
  }
  for (const NodeDifference& term : regularizer.differences) {
    visit(term.sqrt_weight * term.sqrt_weight,
          static_cast<int>(term.nodes.size()), term.nodes.data(),
          term.coefficients.data());
  }
  for (const RingMean& ring : regularizer.rings) {
    visit(ring.displacement_scale() * ring.displacement_scale(),
          static_cast<int>(ring.nodes.size()), ring.nodes.data(), nullptr);
  }
}

// The largest node distance within one term (of K, and of A in nodes).
int NodeSpan(const LocalDirectData& data, const LocalRegularizer& regularizer) {
  int span = 0;
  ForEachScalarTerm(
      data, regularizer,
      [&span](double, int count, const int* nodes, const double*) {
        if (count == 0) return;
        const auto [low, high] = std::minmax_element(nodes, nodes + count);
        span = std::max(span, *high - *low);
      });
  return span;
}

// K: each term's scalar rows' outer products, summed.  Summed in place in
// K's band, in the terms' order, as Eigen's setFromTriplets sums repeated
// entries (the same K to the bit): a triplet per product, 320,000 at
// 20,000 tags, and their sorting were most of frame 0's local field.
SparseMatrix ScalarMatrix(const LocalDirectData& data,
                          const LocalRegularizer& regularizer, int num_nodes) {
  const int band = NodeSpan(data, regularizer);
  // Column c's entry in row r at c * width + r - c + band.
  const size_t width = 2 * band + 1;
  std::vector<double> values(num_nodes * width, 0.0);
  std::vector<char> present(num_nodes * width, 0);
  ForEachScalarTerm(
      data, regularizer,
      [&](double weight, int count, const int* nodes,
          const double* coefficients) {
        for (int a = 0; a < count; ++a) {
          for (int b = 0; b < count; ++b) {
            const double ca = coefficients == nullptr ? 1.0 : coefficients[a];
            const double cb = coefficients == nullptr ? 1.0 : coefficients[b];
            const size_t at = nodes[b] * width + nodes[a] - nodes[b] + band;
            values[at] += weight * ca * cb;
            present[at] = 1;
          }
        }
      });
  std::vector<Eigen::Triplet<double>> entries;
  for (int c = 0; c < num_nodes; ++c) {
    for (size_t offset = 0; offset < width; ++offset) {
      const size_t at = c * width + offset;
      if (present[at]) {
        entries.emplace_back(static_cast<int>(c + offset) - band, c,
                             values[at]);
      }
    }
  }
  SparseMatrix k(num_nodes, num_nodes);
  k.setFromTriplets(entries.begin(), entries.end());
  return k;
}

RingColumns MakeRingColumns(const LocalRegularizer& regularizer,
                            int num_nodes) {
  const int columns = 2 * static_cast<int>(regularizer.rings.size());
  RingColumns u;
  for (Eigen::MatrixXd& rows : u)
    rows = Eigen::MatrixXd::Zero(num_nodes, columns);
  for (size_t j = 0; j < regularizer.rings.size(); ++j) {
    const RingMean& ring = regularizer.rings[j];
    for (size_t k = 0; k < ring.nodes.size(); ++k) {
      for (int c = 0; c < 3; ++c) {
        u[c](ring.nodes[k], 2 * j) = ring.scale * ring.radial[k][c];
        u[c](ring.nodes[k], 2 * j + 1) = ring.scale * ring.tangential[k][c];
      }
    }
  }
  return u;
}

// b = -sum_i w_i S_i^T e_i, a node per row.
NodeMatrix RightHandSide(const LocalDirectData& data, int num_nodes) {
  NodeMatrix b = NodeMatrix::Zero(num_nodes, 3);
  for (size_t i = 0; i < data.shapes.size(); ++i) {
    const ShapeWeights& shape = data.shapes[i];
    const Eigen::RowVector3d pull =
        Weight(data, i) * data.offsets[i].transpose();
    for (int k = 0; k < shape.count; ++k) {
      b.row(shape.node[k]) -= shape.weight[k] * pull;
    }
  }
  return b;
}

// 1/2 the sum of squared residuals at q, as Ceres counts the cost.
double Cost(const LocalDirectData& data, const LocalRegularizer& regularizer,
            const NodeMatrix& q) {
  double sum = 0.0;
  for (size_t i = 0; i < data.shapes.size(); ++i) {
    const ShapeWeights& shape = data.shapes[i];
    Eigen::RowVector3d r = data.offsets[i].transpose();
    for (int k = 0; k < shape.count; ++k) {
      r += shape.weight[k] * q.row(shape.node[k]);
    }
    const Eigen::Vector3d normal = Normal(data, i);
    const double squared =
        normal.isZero(0.0) ? r.squaredNorm() : std::pow(r.dot(normal), 2);
    sum += Weight(data, i) * squared;
  }
  const std::vector<double> values(q.data(), q.data() + q.size());
  return 0.5 * sum + RegularizerCost(regularizer, values);
}

// |A q - b|, the cost's gradient.
double GradientNorm(const SparseMatrix& k, const RingColumns& u,
                    const NodeMatrix& b, const NodeMatrix& q) {
  Eigen::VectorXd along = Eigen::VectorXd::Zero(u[0].cols());
  for (int c = 0; c < 3; ++c) along += u[c].transpose() * q.col(c);
  double sum = 0.0;
  for (int c = 0; c < 3; ++c) {
    sum += (k * q.col(c) + u[c] * along - b.col(c)).squaredNorm();
  }
  return std::sqrt(sum);
}

// Adds m to A's 3 x 3 block of nodes (row_node, col_node), its zeros left
// out.
void AddBlock(int row_node, int col_node, const Eigen::Matrix3d& m,
              LowerBand* a) {
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) {
      if (m(r, c) != 0.0) a->Add(3 * row_node + r, 3 * col_node + c, m(r, c));
    }
  }
}

// The regularizer's part of A, 3 unknowns per node (index 3 node +
// coordinate), summed in place in its band `width` wide: the same for
// every solve of a frame's contour rounds (the ring means' 24 x 24 node
// blocks were most of A's assembly), so kept between them.
LowerBand StiffnessBand(const LocalRegularizer& regularizer, int num_nodes,
                        int width) {
  LowerBand a(3 * num_nodes, width);
  const Eigen::Matrix3d identity = Eigen::Matrix3d::Identity();
  for (const NodeDifference& term : regularizer.differences) {
    const double w2 = term.sqrt_weight * term.sqrt_weight;
    for (size_t p = 0; p < term.nodes.size(); ++p) {
      for (size_t r = 0; r < term.nodes.size(); ++r) {
        AddBlock(term.nodes[p], term.nodes[r],
                 w2 * term.coefficients[p] * term.coefficients[r] * identity,
                 &a);
      }
    }
  }
  for (const RingMean& ring : regularizer.rings) {
    const double s2 = ring.scale * ring.scale;
    const double d2 = ring.displacement_scale() * ring.displacement_scale();
    for (size_t p = 0; p < ring.nodes.size(); ++p) {
      for (size_t r = 0; r < ring.nodes.size(); ++r) {
        AddBlock(ring.nodes[p], ring.nodes[r],
                 d2 * identity +
                     s2 * (ring.radial[p] * ring.radial[r].transpose() +
                           ring.tangential[p] * ring.tangential[r].transpose()),
                 &a);
      }
    }
  }
  return a;
}

// The data's part of A added to *a, and b.
void AddDataSystem(const LocalDirectData& data, int num_nodes, LowerBand* a,
                   Eigen::VectorXd* b) {
  const Eigen::Matrix3d identity = Eigen::Matrix3d::Identity();
  *b = Eigen::VectorXd::Zero(3 * num_nodes);
  for (size_t i = 0; i < data.shapes.size(); ++i) {
    const ShapeWeights& shape = data.shapes[i];
    const Eigen::Vector3d normal = Normal(data, i);
    const Eigen::Matrix3d gram =
        Weight(data, i) *
        (normal.isZero(0.0) ? identity : normal * normal.transpose());
    for (int p = 0; p < shape.count; ++p) {
      for (int r = 0; r < shape.count; ++r) {
        AddBlock(shape.node[p], shape.node[r],
                 shape.weight[p] * shape.weight[r] * gram, a);
      }
      b->segment<3>(3 * shape.node[p]) -=
          shape.weight[p] * gram * data.offsets[i];
    }
  }
}

// The regularizer's terms, flattened: equal signatures, equal stiffness.
std::vector<double> StiffnessSignature(const LocalRegularizer& regularizer,
                                       int num_nodes, int width) {
  std::vector<double> signature = {static_cast<double>(num_nodes),
                                   static_cast<double>(width)};
  AppendRegularizer(regularizer, /*directions=*/true, &signature);
  return signature;
}

void FillReport(double seconds, const SolverTracePoint& before,
                const SolverTracePoint& after, SolverReport* report) {
  *report = SolverReport();
  report->iterations = 1;
  report->converged = true;
  report->termination = "CONVERGENCE";
  report->message = "local field: one direct solve";
  report->residual_evaluations = 2;
  report->jacobian_evaluations = 1;
  report->linear_solver_seconds = seconds;
  report->minimizer_seconds = seconds;
  report->trace = {before, after};
  report->trace.back().iteration = 1;
  report->trace.back().wall_seconds = seconds;
}

// A restricted to nodes moving along unit directions n_k, q_k = n_k d_k:
// A'(k, l) = n_k^T A_kl n_l.  A node's own block is stored below its
// diagonal only, so its off-diagonal entries count twice.
LowerBand AlongDirections(const LowerBand& a,
                          const std::vector<Eigen::Vector3d>& directions) {
  LowerBand reduced(static_cast<int>(directions.size()), a.used / 3 + 1);
  for (int i = 0; i < a.lower.rows(); ++i) {
    for (int j = std::max(0, i - a.used); j <= i; ++j) {
      const double value = a.lower(i, j - i + a.width);
      if (value == 0.0) continue;
      const int k = i / 3, l = j / 3;
      const double twice = k == l && i != j ? 2.0 : 1.0;
      reduced.Add(k, l,
                  twice * directions[k][i % 3] * directions[l][j % 3] * value);
    }
  }
  return reduced;
}

// x_k = n_k . v_k for each node, or back: v_k = n_k x_k.
Eigen::VectorXd Along(const std::vector<Eigen::Vector3d>& directions,
                      const Eigen::VectorXd& v) {
  Eigen::VectorXd x(directions.size());
  for (size_t k = 0; k < directions.size(); ++k) {
    x[k] = directions[k].dot(v.segment<3>(3 * k));
  }
  return x;
}
Eigen::VectorXd Across(const std::vector<Eigen::Vector3d>& directions,
                       const Eigen::VectorXd& x) {
  Eigen::VectorXd v(3 * directions.size());
  for (size_t k = 0; k < directions.size(); ++k) {
    v.segment<3>(3 * k) = directions[k] * x[k];
  }
  return v;
}

// Points with normals, or nodes held to their normals: A as a whole
// (`stiffness`, the regularizer's part, plus the data's), restricted to the
// nodes' normals when the regularizer holds them so, factorized for this
// solve.  The gradient reported is the restricted one.
bool SolveWhole(const LocalDirectData& data, const LowerBand& stiffness,
                const LocalRegularizer& regularizer, LocalField* field,
                SolverReport* report) {
  const auto start = Clock::now();
  const int num_nodes = field->grid.NumNodes();
  LowerBand a = stiffness;
  Eigen::VectorXd b;
  AddDataSystem(data, num_nodes, &a, &b);
  const std::vector<Eigen::Vector3d>& normals = regularizer.node_normals;
  const bool along = !normals.empty();
  if (along) {
    a = AlongDirections(a, normals);
    b = Along(normals, b);
  }
  BandCholesky cholesky;
  if (!cholesky.ComputeBand(a.Trimmed())) return false;
  Eigen::Map<Eigen::VectorXd> values(field->values.data(), 3 * num_nodes);
  const Eigen::Map<const NodeMatrix> q(field->values.data(), num_nodes, 3);
  const auto gradient = [&] {
    return (a.Times(along ? Along(normals, values) : Eigen::VectorXd(values)) -
            b)
        .norm();
  };
  const SolverTracePoint before{0, 0.0, 0.0, Cost(data, regularizer, q),
                                gradient()};
  const Eigen::VectorXd x = cholesky.Solve(b);
  values = along ? Across(normals, x) : x;
  const SolverTracePoint after{1, 0.0, 0.0, Cost(data, regularizer, q),
                               gradient()};
  FillReport(SecondsSince(start), before, after, report);
  return true;
}

}  // namespace

struct LocalDirectSolver::Stiffness {
  std::vector<double> signature;
  LowerBand band{0, 0};
};

const LocalDirectSolver::Stiffness& LocalDirectSolver::StiffnessFor(
    const LocalDirectData& data, const LocalRegularizer& regularizer,
    int num_nodes) {
  const int width = 3 * NodeSpan(data, regularizer) + 2;
  std::vector<double> signature =
      StiffnessSignature(regularizer, num_nodes, width);
  if (stiffness_ == nullptr || stiffness_->signature != signature) {
    stiffness_ = std::make_unique<Stiffness>();
    stiffness_->band = StiffnessBand(regularizer, num_nodes, width);
    stiffness_->signature = std::move(signature);
  }
  return *stiffness_;
}

struct LocalDirectSolver::Factor {
  std::vector<double> signature;
  SparseMatrix k;
  // In the grid's node order, two rings wide (band_cholesky.h).
  BandCholesky cholesky;
};

LocalDirectSolver::LocalDirectSolver() = default;
LocalDirectSolver::~LocalDirectSolver() = default;
LocalDirectSolver::LocalDirectSolver(LocalDirectSolver&&) = default;
LocalDirectSolver& LocalDirectSolver::operator=(LocalDirectSolver&&) = default;

const LocalDirectSolver::Factor* LocalDirectSolver::FactorFor(
    const LocalDirectData& data, const LocalRegularizer& regularizer,
    int num_nodes) {
  constexpr size_t kKept = 3;
  std::vector<double> signature = Signature(data, regularizer, num_nodes);
  for (size_t i = 0; i < factors_.size(); ++i) {
    if (factors_[i]->signature == signature) {
      std::rotate(factors_.begin(), factors_.begin() + i,
                  factors_.begin() + i + 1);
      return factors_.front().get();
    }
  }
  auto factor = std::make_unique<Factor>();
  factor->k = ScalarMatrix(data, regularizer, num_nodes);
  if (!factor->cholesky.Compute(factor->k)) return nullptr;
  factor->signature = std::move(signature);
  factors_.insert(factors_.begin(), std::move(factor));
  if (factors_.size() > kKept) factors_.pop_back();
  ++factorizations_;
  return factors_.front().get();
}

bool LocalDirectSolver::Solve(const LocalDirectData& data,
                              const LocalRegularizer& regularizer,
                              LocalField* field, SolverReport* report) {
  if (HasNormals(data) || !regularizer.node_normals.empty()) {
    const Stiffness& stiffness =
        StiffnessFor(data, regularizer, field->grid.NumNodes());
    return SolveWhole(data, stiffness.band, regularizer, field, report);
  }
  const auto start = Clock::now();
  const int num_nodes = field->grid.NumNodes();
  const Factor* factor = FactorFor(data, regularizer, num_nodes);
  if (factor == nullptr) return false;
  const RingColumns u = MakeRingColumns(regularizer, num_nodes);
  const NodeMatrix b = RightHandSide(data, num_nodes);
  Eigen::Map<NodeMatrix> q(field->values.data(), num_nodes, 3);
  const double cost_before = Cost(data, regularizer, q);
  const double gradient_before = GradientNorm(factor->k, u, b, q);

  // Woodbury: b and the rings' columns through K in one solve (the rings'
  // directions lie in the model's xy plane: no z columns), then the
  // capacitance I + U^T Y.
  const int m = static_cast<int>(u[0].cols());
  const int coordinates = u[2].isZero(0.0) ? 2 : 3;
  BandCholesky::RowMajorMatrix rhs(num_nodes, 3 + coordinates * m);
  rhs.leftCols<3>() = b;
  for (int c = 0; c < coordinates; ++c) rhs.middleCols(3 + c * m, m) = u[c];
  const BandCholesky::RowMajorMatrix solved =
      factor->cholesky.Solve(std::move(rhs));
  Eigen::MatrixXd capacitance = Eigen::MatrixXd::Identity(m, m);
  Eigen::VectorXd along = Eigen::VectorXd::Zero(m);
  for (int c = 0; c < coordinates; ++c) {
    capacitance.noalias() += u[c].transpose() * solved.middleCols(3 + c * m, m);
    along.noalias() += u[c].transpose() * solved.col(c);
  }
  const Eigen::VectorXd s = capacitance.llt().solve(along);
  q = solved.leftCols<3>();
  for (int c = 0; c < coordinates; ++c) {
    q.col(c).noalias() -= solved.middleCols(3 + c * m, m) * s;
  }

  const SolverTracePoint after{1, 0.0, 0.0, Cost(data, regularizer, q),
                               GradientNorm(factor->k, u, b, q)};
  FillReport(SecondsSince(start), {0, 0.0, 0.0, cost_before, gradient_before},
             after, report);
  return true;
}

}  // namespace pfdm
