// A local field that moves its nodes along the global surface's normal.
//
// Contours say where the surface is, not which material point sits where on
// it: a closest-point residual is blind to a field's displacement along the
// surface.  Left free, that part of the field is set by the regularizer and
// the correspondences alone, and the contour rounds chase it: on biv-me
// patient 1 the points slid 1.5-10 mm from one round to the next, never
// settling, and a segment's Ecc moved by up to 4.6 points when the guide
// points moved by 1e-5 mm.  A frame whose every point slides therefore fits
// one unknown per node, q_k = n_k d_k, n_k the global surface's unit normal
// at the node (model frame): the rounds converge (the farthest point's
// slide shrinks about twofold a round) and Ecc follows the wall's shape
// (docs/local_deformations.md, "Contours move the wall along its normal").
#ifndef PFDM_FIT_PROBLEM_NODE_NORMALS_H_
#define PFDM_FIT_PROBLEM_NODE_NORMALS_H_

#include <vector>

#include "Eigen/Core"
#include "ceres/manifold.h"
#include "pfdm/model/local_field.h"
#include "pfdm/model/model.h"

namespace pfdm {

// The unit outward normals of `global`'s mid-wall surface at `grid`'s nodes
// (LocalGrid::Node's order), model frame; the apex pole's is -z.  Any local
// field of `global` is ignored.
std::vector<Eigen::Vector3d> NodeNormals(const Model& global,
                                         const LocalGrid& grid);

// A node's three values kept on the line through them along a unit
// direction n: x + n delta.  (The field starts from zero, on every node's
// line through the origin.)
class AlongDirection : public ceres::Manifold {
 public:
  explicit AlongDirection(const Eigen::Vector3d& direction)
      : direction_(direction) {}
  int AmbientSize() const override { return 3; }
  int TangentSize() const override { return 1; }
  bool Plus(const double* x, const double* delta,
            double* x_plus_delta) const override;
  bool PlusJacobian(const double* x, double* jacobian) const override;
  bool Minus(const double* y, const double* x,
             double* y_minus_x) const override;
  bool MinusJacobian(const double* x, double* jacobian) const override;

 private:
  Eigen::Vector3d direction_;
};

}  // namespace pfdm

#endif  // PFDM_FIT_PROBLEM_NODE_NORMALS_H_
