// The local field's stiffness and ring-mean terms (local_fit.h) as lists of
// rows linear in the nodal values, so that the Ceres problem and the direct
// solve (local_direct.h) take the same terms from one place.
#ifndef PFDM_FIT_PROBLEM_LOCAL_REGULARIZER_H_
#define PFDM_FIT_PROBLEM_LOCAL_REGULARIZER_H_

#include <vector>

#include "Eigen/Core"
#include "ceres/problem.h"
#include "pfdm/model/local_field.h"
#include "pfdm/model/model.h"

namespace pfdm {

// r = sqrt_weight sum_k c_k q_{node_k}: 3 rows, each coordinate alike (the
// membrane's and thin plate's differences, the pole's ring mean).
struct NodeDifference {
  double sqrt_weight = 0.0;
  std::vector<double> coefficients;
  std::vector<int> nodes;
};

// r = scale sum_k [I; radial_k^T; tangential_k^T] q_{node_k}: a ring's mean
// displacement (3 rows) and its mean radial and tangential components, in
// the global model's directions at each node (z = 0).
struct RingMean {
  double scale = 0.0;
  // False: the mean radial and tangential components alone (a solid's q_w:
  // the ring's mean thickness and transmural twist are the global
  // functions', an endocardium's centre moving against the epicardium's is
  // none's).
  bool mean_displacement = true;
  std::vector<int> nodes;
  std::vector<Eigen::Vector3d> radial;
  std::vector<Eigen::Vector3d> tangential;

  // The weight of the mean displacement's rows: scale, or 0 without them.
  double displacement_scale() const { return mean_displacement ? scale : 0.0; }
};

struct LocalRegularizer {
  std::vector<NodeDifference> differences;
  std::vector<RingMean> rings;
  // When not empty, node k moves along node_normals[k] only (a frame of
  // contours alone: node_normals.h); the terms above are unchanged.
  std::vector<Eigen::Vector3d> node_normals;
};

// The terms on `grid` for `num_points` data points: stiffness W n (n = the
// points per node; none when 0) and the ring means of `global`.
LocalRegularizer MakeLocalRegularizer(const Model& global,
                                      const LocalGrid& grid, int num_points,
                                      double stiffness);

// The terms' cost at the nodal values q (3 per node): 1/2 their squared
// rows, as Ceres counts it.
double RegularizerCost(const LocalRegularizer& regularizer,
                       const std::vector<double>& q);

// The terms with every row scaled by `factor` (their cost by its square).
LocalRegularizer Scaled(LocalRegularizer regularizer, double factor);

// The terms as residual blocks on *field's nodal values, in order.
void AddLocalRegularizer(const LocalRegularizer& regularizer, LocalField* field,
                         ceres::Problem* problem);

}  // namespace pfdm

#endif  // PFDM_FIT_PROBLEM_LOCAL_REGULARIZER_H_
