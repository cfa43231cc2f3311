// The local field's direct solve without Ceres, for points that pull with
// the whole vector (tracked points; no plane rows).  Each point's residual
// w_i (x_g + R S_i q - data_i) has the norm of w_i (S_i q + e_i), e_i =
// R^T (x_g - data_i), for R is a rotation; S_i is a node weight times the
// identity, and so are the stiffness terms and the rings' mean
// displacements.  The normal matrix is therefore
//
//   A = K (x) I_3 + U U^T,
//
// K the nodes' scalar matrix (one third of the unknowns, a third of the
// grid's bandwidth) and U two columns per ring, its mean radial and
// tangential rows, which alone depend on the frame's global shape.  K is
// factorized (a band Cholesky in the grid's node order, two rings wide:
// util/band_cholesky.h) and A^{-1} b follows by Woodbury's identity:
//
//   A^{-1} b = Z - Y (I + U^T Y)^{-1} U^T Z,  Z = K^{-1} b, Y = K^{-1} U,
//
// one exact solve, as the direct Ceres solve's one Gauss-Newton step.  K
// depends only on the points' nodes and shape weights, their loss weights
// and the stiffness terms, not on the frame: a solver kept across frames
// factorizes it again only when one of those changed (tracked frames keep
// frame 0's material points).  It keeps the last two K: a solid's
// transmural field solves two parts in turn (local_fit.h), each its own K.
//
// Points with a normal make the data's Gram blocks w s_a s_b m m^T, no
// multiple of the identity: then the whole A (3 unknowns per node, node by
// node, three times K's bandwidth) is factorized for each solve, as the
// contours' closest points change from one to the next.  When the
// regularizer holds each node to its normal (node_normals.h: a frame of
// contours alone), A is restricted to those directions first, one unknown
// per node and K's bandwidth.
#ifndef PFDM_FIT_PROBLEM_LOCAL_DIRECT_H_
#define PFDM_FIT_PROBLEM_LOCAL_DIRECT_H_

#include <memory>
#include <vector>

#include "Eigen/Core"
#include "pfdm/fit/problem/local_regularizer.h"
#include "pfdm/model/local_field.h"
#include "pfdm/solvers/solver.h"

namespace pfdm {

// The data of the direct solve, one entry per point.
struct LocalDirectData {
  std::vector<ShapeWeights> shapes;
  std::vector<Eigen::Vector3d> offsets;  // e_i = R^T (x_g - data_i), mm.
  std::vector<double> weights;           // w_i^2; empty: all 1.
  // Points on contours pull along a normal only, m_i = R^T n_i in the
  // model frame: the row m_i . (S_i q + e_i).  Empty, or zero for a point:
  // the whole vector.
  std::vector<Eigen::Vector3d> normals;
};

class LocalDirectSolver {
 public:
  LocalDirectSolver();
  ~LocalDirectSolver();
  LocalDirectSolver(LocalDirectSolver&&);
  LocalDirectSolver& operator=(LocalDirectSolver&&);

  // Replaces field->values by the minimum of the data's and the
  // regularizer's cost; the report as the direct Ceres solve's (one
  // iteration, the costs before and after).  Returns false, the field
  // untouched, when K is not positive definite (no data and no stiffness
  // on some node): the caller solves with Ceres then.
  bool Solve(const LocalDirectData& data, const LocalRegularizer& regularizer,
             LocalField* field, SolverReport* report);

  // How many times K was factorized: once per distinct K.
  int factorizations() const { return factorizations_; }

 private:
  struct Factor;
  // The factor of this K, made (and kept, the older of two dropped) when
  // neither kept one is; null when K is not positive definite.
  const Factor* FactorFor(const LocalDirectData& data,
                          const LocalRegularizer& regularizer, int num_nodes);

  struct Stiffness;
  // A with normals less the data's part, as the last solve had it: kept
  // while the regularizer stays (a frame's contour rounds).
  const Stiffness& StiffnessFor(const LocalDirectData& data,
                                const LocalRegularizer& regularizer,
                                int num_nodes);

  std::vector<std::unique_ptr<Factor>> factors_;  // Most recent first.
  std::unique_ptr<Stiffness> stiffness_;
  int factorizations_ = 0;
};

}  // namespace pfdm

#endif  // PFDM_FIT_PROBLEM_LOCAL_DIRECT_H_
