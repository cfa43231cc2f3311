#include "pfdm/fit/problem/local_fit.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "ceres/problem.h"
#include "pfdm/fit/problem/local_regularizer.h"
#include "pfdm/fit/problem/node_normals.h"
#include "pfdm/fit/residuals/linear_node_cost.h"
#include "pfdm/fit/residuals/robust_loss.h"
#include "pfdm/fit/residuals/square_root_form.h"

namespace pfdm {
namespace {

// With a robust loss, the field is solved again with the weights at its
// residuals until no point's weight changes by kReweightTolerance, or
// kMaxReweightings solves.
constexpr int kMaxReweightings = 10;
constexpr double kReweightTolerance = 0.01;

// A solid's parts are solved in turn until a pass moves no nodal value by
// this much (mm), or kMaxPasses passes (q_w's and q_k's shares correlate:
// about 20 passes).
constexpr double kPassTolerance = 1e-4;
constexpr int kMaxPasses = 30;

// The local field's data: each point's rows at its element
// (LocalPointRows), scaled by the square root of its weight when the loss
// weighs the points.  For one part of a solid's field (SolveParts) each
// point's shape weights are scaled by its share of that part and the other
// part's displacement is held in its global point.
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
  // Point i's shape weights on the whole field.
  ShapeWeights BareShape(size_t i) const {
    return ShapeAt(grid_, material_[i].u, material_[i].v);
  }
  // ... and on the part being solved.
  ShapeWeights Shape(size_t i) const {
    ShapeWeights shape = BareShape(i);
    if (!part_scales_.empty()) {
      for (int k = 0; k < shape.count; ++k) shape.weight[k] *= part_scales_[i];
    }
    return shape;
  }
  // Point i's rows, weighed by sqrt_weights (empty: all 1).
  LocalRows Rows(size_t i) const {
    const bool plane = normals_[i] != Eigen::Vector3d::Zero();
    LocalRows rows = LocalPointRows(Global(i), rotation_, Shape(i), points_[i],
                                    plane ? &normals_[i] : nullptr);
    if (!sqrt_weights_.empty()) rows *= sqrt_weights_[i];
    return rows;
  }
  // The points as the direct solve takes them, the weights included.
  LocalDirectData DirectData() const;
  // Each point's residual (its rows' size) under the whole `field` (both
  // parts of a solid's), unweighted; the part's scales and held
  // displacements left out.
  std::vector<Eigen::Vector3d> Residuals(const LocalField& field) const;
  // 1/2 the weighted squared residuals under the whole `field`.
  double Cost(const LocalField& field) const;
  void set_sqrt_weights(std::vector<double> sqrt_weights) {
    sqrt_weights_ = std::move(sqrt_weights);
  }
  double w(size_t i) const { return material_[i].w; }
  // One part of a solid's field: point i's shape weights scaled by
  // scales[i], held[i] (model frame) added to its global point.  Empty:
  // the whole field.
  void set_part(std::vector<double> scales, std::vector<Eigen::Vector3d> held) {
    part_scales_ = std::move(scales);
    part_held_ = std::move(held);
  }

 private:
  const std::vector<Eigen::Vector3d>& points_;
  const std::vector<MaterialPoint>& material_;
  const LocalGrid& grid_;
  const Eigen::Matrix3d rotation_;
  const std::vector<Eigen::Vector3d> globals_;
  const std::vector<Eigen::Vector3d> normals_;
  std::vector<double> sqrt_weights_;
  std::vector<double> part_scales_;
  std::vector<Eigen::Vector3d> part_held_;

  Eigen::Vector3d Global(size_t i) const {
    return part_held_.empty()
               ? globals_[i]
               : Eigen::Vector3d(globals_[i] + rotation_ * part_held_[i]);
  }
};

std::vector<Eigen::Vector3d> LocalData::Residuals(
    const LocalField& field) const {
  std::vector<Eigen::Vector3d> residuals(size(), Eigen::Vector3d::Zero());
  for (size_t i = 0; i < size(); ++i) {
    const bool plane = normals_[i] != Eigen::Vector3d::Zero();
    const ShapeWeights shape = BareShape(i);
    const LocalRows rows =
        LocalPointRows(globals_[i], rotation_, shape, points_[i],
                       plane ? &normals_[i] : nullptr);
    const int n = 3 * shape.count;
    Eigen::VectorXd q(n);
    for (int k = 0; k < shape.count; ++k) {
      const int at = 3 * shape.node[k];
      q.segment<3>(3 * k) = Eigen::Vector3d(&field.values[at]);
      if (field.transmural()) {
        q.segment<3>(3 * k) += w(i) * Eigen::Vector3d(&field.slope[at]);
      }
      if (!field.kink.empty()) {
        q.segment<3>(3 * k) +=
            TransmuralKink(w(i)) * Eigen::Vector3d(&field.kink[at]);
      }
    }
    residuals[i].head(rows.rows()) = rows.leftCols(n) * q + rows.col(n);
  }
  return residuals;
}

double LocalData::Cost(const LocalField& field) const {
  const std::vector<Eigen::Vector3d> residuals = Residuals(field);
  double sum = 0.0;
  for (size_t i = 0; i < size(); ++i) {
    const double weight =
        sqrt_weights_.empty() ? 1.0 : sqrt_weights_[i] * sqrt_weights_[i];
    sum += weight * residuals[i].squaredNorm();
  }
  return 0.5 * sum;
}

LocalDirectData LocalData::DirectData() const {
  LocalDirectData data;
  data.shapes.reserve(size());
  data.offsets.reserve(size());
  for (size_t i = 0; i < size(); ++i) {
    data.shapes.push_back(Shape(i));
    data.offsets.push_back(rotation_.transpose() * (Global(i) - points_[i]));
    data.normals.push_back(rotation_.transpose() * normals_[i]);
  }
  for (double w : sqrt_weights_) data.weights.push_back(w * w);
  return data;
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

// One linear solve of the field (its values; a part of a solid's, as the
// data hold it) for the data's current weights, from *field's values: the
// direct solver's without Ceres where it can (local_direct.h), the same
// minimum to round-off.
SolverReport SolveOne(const LocalData& data,
                      const LocalRegularizer& regularizer,
                      const FitOptions& options, LocalDirectSolver* direct,
                      LocalField* field) {
  if (options.solver.kind == SolverKind::kDirect) {
    CheckInterrupt(options.solver);
    SolverReport report;
    if (direct->Solve(data.DirectData(), regularizer, field, &report)) {
      return report;
    }
  }
  ceres::Problem problem;
  AddLocalData(data, field, &problem);
  AddLocalRegularizer(regularizer, field, &problem);
  for (size_t k = 0; k < regularizer.node_normals.size(); ++k) {
    double* node = &field->values[3 * k];
    if (problem.HasParameterBlock(node)) {
      problem.SetManifold(node,
                          new AlongDirection(regularizer.node_normals[k]));
    }
  }
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

// A solid's field d_i = S_i (q + w_i q_w + k(w_i) q_k) (k: TransmuralKink)
// as parts P_j with d_i = sum_j a_ij S_i P_j.  When every point lies on a
// wall (|w| = 1: both walls' contours) the parts are the endocardium's and
// the epicardium's fields A and B, a = (1 - w) / 2, b = (1 + w) / 2, q =
// (A + B) / 2, q_w = (B - A) / 2, and q_k, zero at the walls, stays 0:
// their points are apart, and with half the regularizer each (the
// parallelogram law: R(q) + R(q_w) = (R(A) + R(B)) / 2) so are their
// costs, and one pass is the minimum.  Otherwise (tags through the wall)
// the parts are q, q_w and q_k with shares 1, w and k(w): tags spread
// about the mid-wall keep q apart from the others, but w and k(w)
// correlate (0.67 over an even spread), and the passes converge slowly.
struct Parts {
  bool layers = false;
  std::vector<std::vector<double>> scales;
  std::vector<LocalField> fields;  // Values only.
};

Parts SplitParts(const LocalData& data, const LocalField& field) {
  Parts parts;
  parts.layers = true;
  for (size_t i = 0; i < data.size(); ++i) {
    parts.layers = parts.layers && std::abs(data.w(i)) == 1.0;
  }
  const int count = parts.layers || field.kink.empty() ? 2 : 3;
  parts.scales.assign(count, std::vector<double>(data.size()));
  for (size_t i = 0; i < data.size(); ++i) {
    parts.scales[0][i] = parts.layers ? 0.5 * (1.0 - data.w(i)) : 1.0;
    parts.scales[1][i] = parts.layers ? 0.5 * (1.0 + data.w(i)) : data.w(i);
    if (count == 3) parts.scales[2][i] = TransmuralKink(data.w(i));
  }
  parts.fields.assign(count, LocalField::Zero(field.grid));
  for (size_t k = 0; k < field.values.size(); ++k) {
    const double q = field.values[k], q_w = field.slope[k];
    parts.fields[0].values[k] = parts.layers ? q - q_w : q;
    parts.fields[1].values[k] = parts.layers ? q + q_w : q_w;
    if (count == 3) parts.fields[2].values[k] = field.kink[k];
  }
  return parts;
}

void JoinParts(const Parts& parts, LocalField* field) {
  for (size_t k = 0; k < field->values.size(); ++k) {
    const double a = parts.fields[0].values[k], b = parts.fields[1].values[k];
    field->values[k] = parts.layers ? 0.5 * (a + b) : a;
    field->slope[k] = parts.layers ? 0.5 * (b - a) : b;
    if (parts.fields.size() == 3) field->kink[k] = parts.fields[2].values[k];
  }
}

// Each point's displacement by `part` scaled by its share `scales`.
std::vector<Eigen::Vector3d> Held(const LocalData& data,
                                  const std::vector<double>& scales,
                                  const LocalField& part) {
  std::vector<Eigen::Vector3d> held(data.size());
  for (size_t i = 0; i < data.size(); ++i) {
    const ShapeWeights shape = data.BareShape(i);
    held[i].setZero();
    for (int k = 0; k < shape.count; ++k) {
      held[i] += scales[i] * shape.weight[k] *
                 Eigen::Vector3d(&part.values[3 * shape.node[k]]);
    }
  }
  return held;
}

// Each point's displacement by every part but `solved`.
std::vector<Eigen::Vector3d> HeldByOthers(const LocalData& data,
                                          const Parts& parts, size_t solved) {
  std::vector<Eigen::Vector3d> held(data.size(), Eigen::Vector3d::Zero());
  for (size_t p = 0; p < parts.fields.size(); ++p) {
    if (p == solved) continue;
    const std::vector<Eigen::Vector3d> part =
        Held(data, parts.scales[p], parts.fields[p]);
    for (size_t i = 0; i < held.size(); ++i) held[i] += part[i];
  }
  return held;
}

double MaxChange(const LocalField& before, const LocalField& after) {
  double change = 0.0;
  for (size_t k = 0; k < before.values.size(); ++k) {
    change = std::max(change, std::abs(after.values[k] - before.values[k]));
  }
  return change;
}

// Each part's regularizer.  Tags through the wall: q_w's and q_k's
// stiffness is scaled by their mean squared share, so that each part is
// as stiff against its own data as q (q_w's data weigh w^2, a third of
// q's).  q_w keeps the ring means of its radial and tangential components
// (a ring's mean thickness and transmural twist are the global
// functions') but not of its displacement: no global function moves the
// endocardium's centre against the epicardium's, and those rows held a
// lesion's thickening toward its ring.  q_k has none: the global model has
// no bend through the wall (docs/local_deformations.md, "Through the
// wall").
std::vector<LocalRegularizer> PartRegularizers(
    const Parts& parts, const LocalRegularizer& regularizer) {
  if (parts.layers) {
    return std::vector<LocalRegularizer>(parts.fields.size(),
                                         Scaled(regularizer, std::sqrt(0.5)));
  }
  std::vector<LocalRegularizer> regularizers = {regularizer};
  for (size_t p = 1; p < parts.fields.size(); ++p) {
    double mean_square = 0.0;
    for (double share : parts.scales[p]) mean_square += share * share;
    mean_square /=
        static_cast<double>(std::max<size_t>(1, parts.scales[p].size()));
    LocalRegularizer part = Scaled(regularizer, std::sqrt(mean_square));
    if (p == 1) {
      for (RingMean& ring : part.rings) ring.mean_displacement = false;
    } else {
      part.rings.clear();
    }
    regularizers.push_back(std::move(part));
  }
  return regularizers;
}

// Block Gauss-Seidel over the parts (Parts): each solved with the others
// held, until a pass changes none.  The report's last cost is the whole
// field's, every part's regularizer included.
SolverReport SolveParts(LocalData* data, const LocalRegularizer& regularizer,
                        const FitOptions& options, LocalDirectSolver* direct,
                        LocalField* field) {
  Parts parts = SplitParts(*data, *field);
  const std::vector<LocalRegularizer> regularizers =
      PartRegularizers(parts, regularizer);
  SolverReport report;
  int iterations = 0;
  for (int pass = 0; pass < kMaxPasses; ++pass) {
    double change = 0.0;
    for (size_t p = 0; p < parts.fields.size(); ++p) {
      const LocalField before = parts.fields[p];
      data->set_part(parts.scales[p], HeldByOthers(*data, parts, p));
      report =
          SolveOne(*data, regularizers[p], options, direct, &parts.fields[p]);
      iterations += report.iterations;
      if (!report.usable) break;
      change = std::max(change, MaxChange(before, parts.fields[p]));
    }
    if (!report.usable || parts.layers || change < kPassTolerance) break;
  }
  data->set_part({}, {});
  JoinParts(parts, field);
  report.iterations = iterations;
  if (!report.trace.empty()) {
    double cost = data->Cost(*field);
    for (size_t p = 0; p < parts.fields.size(); ++p) {
      cost += RegularizerCost(regularizers[p], parts.fields[p].values);
    }
    report.trace.back().cost = cost;
  }
  return report;
}

// The field's solve for the data's current weights: one solve, or a
// solid's two parts in turn; its nodes held to `node_normals` unless that
// is empty (node_normals.h).
SolverReport SolveLocal(LocalData* data, const Model& model,
                        const FitOptions& options,
                        const std::vector<Eigen::Vector3d>& node_normals,
                        LocalDirectSolver* direct, LocalField* field) {
  LocalRegularizer regularizer =
      MakeLocalRegularizer(model, field->grid, static_cast<int>(data->size()),
                           options.local.stiffness);
  regularizer.node_normals = node_normals;
  if (!field->transmural()) {
    return SolveOne(*data, regularizer, options, direct, field);
  }
  return SolveParts(data, regularizer, options, direct, field);
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
                           const FitOptions& options, Model* model,
                           LocalDirectSolver* direct) {
  LocalDirectSolver own;
  if (direct == nullptr) direct = &own;
  const ModelConfig& config = model->config;
  model->state.local = LocalField();
  LocalGrid grid;
  grid.rows = options.local.rows;
  grid.cols = options.local.cols;
  grid.u_min = config.u_min;
  grid.u_max = config.u_max;
  LocalField field =
      LocalField::Zero(grid, options.local.transmural && config.Solid());
  LocalData data(points, material, sliding, grid, *model);
  const bool contours_alone =
      !sliding.empty() &&
      std::all_of(sliding.begin(), sliding.end(), [](bool s) { return s; });
  const std::vector<Eigen::Vector3d> node_normals =
      contours_alone ? NodeNormals(*model, grid)
                     : std::vector<Eigen::Vector3d>();
  const bool robust = options.loss != "none";
  // With a loss, iteratively reweighted least squares: each solve weighs
  // the points by the loss at their residuals under the last field (the
  // global fit's first), which ends at a minimum of the loss's cost and
  // keeps the problem linear, in square-root form.
  std::vector<double> sqrt_weights;
  if (robust) sqrt_weights = SqrtLossWeights(data, options, field);
  data.set_sqrt_weights(sqrt_weights);
  SolverReport report =
      SolveLocal(&data, *model, options, node_normals, direct, &field);
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
    report = SolveLocal(&data, *model, options, node_normals, direct, &field);
    report.iterations += iterations;
  }
  model->state.local = std::move(field);
  return report;
}

}  // namespace pfdm
