// The local displacement field of one frame, fitted after the global one
// (Metaxas & Terzopoulos: global first, local after): the global functions
// and the pose held, the nodal displacements q_d solve the linear least
// squares
//
//   sum_i |x_g(u_i, v_i) + R S(u_i, v_i) q_d - data_i|^2        (data)
//   + W n (sum |first differences|^2 + sum |second differences|^2)  (K)
//   + ring means,
//
// n = N / nodes, the stiffness in the paper's deformation energy, and the
// ring means a stiff penalty on each ring's mean displacement (axial,
// across the axis, radial and tangential), which the global functions
// already carry: the local field keeps what varies around a ring.
// docs/local_deformations.md has the details.
#ifndef PFDM_FIT_PROBLEM_LOCAL_FIT_H_
#define PFDM_FIT_PROBLEM_LOCAL_FIT_H_

#include <vector>

#include "Eigen/Core"
#include "pfdm/fit/correspondence/correspondence.h"
#include "pfdm/fit/fit_options.h"
#include "pfdm/fit/problem/local_direct.h"
#include "pfdm/model/local_field.h"
#include "pfdm/model/model.h"
#include "pfdm/solvers/solver.h"

namespace pfdm {

// Replaces model->state.local by the field fitted with `options.solver`
// (any of the three solvers) on `options.local`'s grid, everything else of
// the model held.  Points listed in `sliding` pull along the global
// surface's normal (but past the base rim), as in SolveFrame; when every
// point slides (contours alone) the nodes move along that normal only
// (node_normals.h).  The direct
// solver solves without Ceres when no point slides (local_direct.h), with
// `direct`'s factorization when its matrix is the same (pass one solver
// over a sequence's tracked frames; nullptr: a fresh one).
SolverReport FitLocalField(const std::vector<Eigen::Vector3d>& points,
                           const std::vector<MaterialPoint>& material,
                           const std::vector<bool>& sliding,
                           const FitOptions& options, Model* model,
                           LocalDirectSolver* direct = nullptr);

}  // namespace pfdm

#endif  // PFDM_FIT_PROBLEM_LOCAL_FIT_H_
