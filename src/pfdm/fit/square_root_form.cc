#include "pfdm/fit/square_root_form.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "Eigen/Cholesky"
#include "Eigen/QR"
#include "glog/logging.h"

namespace pfdm {
namespace {

// How far |z|^2 may exceed |r|^2 from rounding before the factorization is
// distrusted.
constexpr double kRoundingSlack = 1e-12;

// Householder QR of [J r]: slower, but needs no definiteness.
SquareRootForm FromQr(const RowMajorMatrix& a) {
  const int n = static_cast<int>(a.cols()) - 1;
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(a);
  const Eigen::MatrixXd top =
      qr.matrixQR().topRows(n + 1).triangularView<Eigen::Upper>();
  return {top.topLeftCorner(n, n), top.col(n).head(n), std::abs(top(n, n))};
}

}  // namespace

SquareRootForm ToSquareRootForm(const RowMajorMatrix& a) {
  const int n = static_cast<int>(a.cols()) - 1;
  CHECK_GT(a.rows(), n);
  Eigen::MatrixXd gram = Eigen::MatrixXd::Zero(n + 1, n + 1);
  gram.selfadjointView<Eigen::Lower>().rankUpdate(a.transpose());
  return SquareRootFormFromGram(std::move(gram), [&a] { return a; });
}

// From the pivoted factorization J^T J = P^T L D L^T P: R = D^(1/2) L^T P
// and z = D^(-1/2) L^-1 P J^T r, ~half the flops of a QR of [J r].  R need
// not be triangular, only satisfy the identities.  J^T J is often singular
// (b1 while b0 = 0, a knot whose weight is 0 for every point, a rotation
// about the axis of a round model); pivoting puts those directions last,
// where pivots <= 0 are dropped.  Small positive ones are kept: dropping
// even those below 1e-14 of the largest perturbs the gradient by up to the
// square root of that, which cost frame 0 an extra iteration.  What
// rounding does to a near-singular J can still spoil z, which |z| > |r|
// exposes; then the QR decides.
SquareRootForm SquareRootFormFromGram(
    Eigen::MatrixXd gram, const std::function<RowMajorMatrix()>& rows) {
  const int n = static_cast<int>(gram.cols()) - 1;
  const Eigen::LDLT<Eigen::MatrixXd, Eigen::Lower> ldlt(
      gram.topLeftCorner(n, n));
  if (ldlt.info() != Eigen::Success) return FromQr(rows());
  SquareRootForm form;
  form.z = ldlt.transpositionsP() * gram.row(n).head(n).transpose();
  ldlt.matrixL().solveInPlace(form.z);
  Eigen::VectorXd root_d = Eigen::VectorXd::Zero(n);
  for (int i = 0; i < n; ++i) {
    const double d = ldlt.vectorD()[i];
    if (d > 0.0) root_d[i] = std::sqrt(d);
    form.z[i] = d > 0.0 ? form.z[i] / root_d[i] : 0.0;
  }
  const double squared_norm = gram(n, n);
  const double rho_squared = squared_norm - form.z.squaredNorm();
  if (rho_squared < -kRoundingSlack * squared_norm) return FromQr(rows());
  // The permutation as column swaps, not a product with its matrix.
  form.r = root_d.asDiagonal() * Eigen::MatrixXd(ldlt.matrixU());
  form.r = form.r * ldlt.transpositionsP().transpose();
  form.rho = std::sqrt(std::max(rho_squared, 0.0));
  return form;
}

}  // namespace pfdm
