#include "pfdm/fit/residuals/square_root_form.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include "Eigen/Cholesky"
#include "Eigen/QR"
#include "glog/logging.h"

namespace pfdm {
namespace {

// How far |z|^2 may exceed |r|^2 from rounding before the factorization is
// distrusted.
constexpr double kRoundingSlack = 1e-12;

// LAPACK's Cholesky with complete pivoting of a positive semidefinite
// matrix (reference LAPACK, Debian's liblapack): P^T A P = U^T U, U's
// first `rank` rows valid.
extern "C" void dpstrf_(const char* uplo, const int* n, double* a,
                        const int* lda, int* piv, int* rank, const double* tol,
                        double* work, int* info, size_t uplo_length);

// The form from J^T J = P^T U^T U P, pivoting on the largest diagonal of
// what is left to factor, and stopping where that is <= 0: R = U P^T
// (rank rows), z from U11^T z = (P^T J^T r) over the rank.  Eigen's LDLT
// pivots on the diagonal it started with, so a pivot that elimination left
// exactly 0 before a regular one fails it (5 % of the groups of a tracked
// 50,000-tag frame, whose QR of 3,072 rows then cost as much as a third of
// the groups' time); this does not.  nullopt if LAPACK reports an error.
std::optional<SquareRootForm> FromPivotedCholesky(const Eigen::MatrixXd& gram) {
  const int n = static_cast<int>(gram.cols()) - 1;
  Eigen::MatrixXd u = gram.topLeftCorner(n, n);
  u.triangularView<Eigen::StrictlyUpper>() = u.transpose();
  std::vector<int> piv(n);
  std::vector<double> work(2 * n);
  int rank = 0, info = 0;
  const double tol = 0.0;
  dpstrf_("U", &n, u.data(), &n, piv.data(), &rank, &tol, work.data(), &info,
          1);
  if (info < 0) return std::nullopt;
  Eigen::VectorXd g(n);  // P^T J^T r.
  for (int i = 0; i < n; ++i) g[i] = gram(n, piv[i] - 1);
  SquareRootForm form;
  form.z = Eigen::VectorXd::Zero(n);
  form.z.head(rank) = u.topLeftCorner(rank, rank)
                          .triangularView<Eigen::Upper>()
                          .transpose()
                          .solve(g.head(rank));
  Eigen::MatrixXd top = u.topRows(rank);
  top.triangularView<Eigen::StrictlyLower>().setZero();
  form.r = Eigen::MatrixXd::Zero(n, n);
  for (int j = 0; j < n; ++j) form.r.col(piv[j] - 1).head(rank) = top.col(j);
  return form;
}

// Householder QR of [J r]: slower, but needs no definiteness.
SquareRootForm FromQr(const RowMajorMatrix& a) {
  const int n = static_cast<int>(a.cols()) - 1;
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(a);
  const Eigen::MatrixXd top =
      qr.matrixQR().topRows(n + 1).triangularView<Eigen::Upper>();
  return {top.topLeftCorner(n, n), top.col(n).head(n), std::abs(top(n, n))};
}

// From the pivoted factorization J^T J = P^T L D L^T P: R = D^(1/2) L^T P
// and z = D^(-1/2) L^-1 P J^T r, ~half the flops of a QR of [J r].  R need
// not be triangular, only satisfy the identities.  J^T J is often singular
// (b1 while b0 = 0, a knot whose weight is 0 for every point, a rotation
// about the axis of a round model); pivoting puts those directions last,
// where pivots <= 0 are dropped.  Small positive ones are kept: dropping
// even those below 1e-14 of the largest perturbs the gradient by up to the
// square root of that, which cost frame 0 an extra iteration.  nullopt
// when Eigen reports the factorization failed (FromPivotedCholesky).
std::optional<SquareRootForm> FromLdlt(const Eigen::MatrixXd& gram) {
  const int n = static_cast<int>(gram.cols()) - 1;
  const Eigen::LDLT<Eigen::MatrixXd, Eigen::Lower> ldlt(
      gram.topLeftCorner(n, n));
  if (ldlt.info() != Eigen::Success) return std::nullopt;
  SquareRootForm form;
  form.z = ldlt.transpositionsP() * gram.row(n).head(n).transpose();
  ldlt.matrixL().solveInPlace(form.z);
  Eigen::VectorXd root_d = Eigen::VectorXd::Zero(n);
  for (int i = 0; i < n; ++i) {
    const double d = ldlt.vectorD()[i];
    if (d > 0.0) root_d[i] = std::sqrt(d);
    form.z[i] = d > 0.0 ? form.z[i] / root_d[i] : 0.0;
  }
  // The permutation as column swaps, not a product with its matrix.
  form.r = root_d.asDiagonal() * Eigen::MatrixXd(ldlt.matrixU());
  form.r = form.r * ldlt.transpositionsP().transpose();
  return form;
}

}  // namespace

SquareRootForm ToSquareRootForm(const RowMajorMatrix& a) {
  const int n = static_cast<int>(a.cols()) - 1;
  CHECK_GT(a.rows(), n);
  Eigen::MatrixXd gram = Eigen::MatrixXd::Zero(n + 1, n + 1);
  gram.selfadjointView<Eigen::Lower>().rankUpdate(a.transpose());
  return SquareRootFormFromGram(std::move(gram), [&a] { return a; });
}

// What rounding does to a near-singular J can still spoil z, which
// |z| > |r| exposes; then the QR of [J r] decides.
SquareRootForm SquareRootFormFromGram(
    Eigen::MatrixXd gram, const std::function<RowMajorMatrix()>& rows) {
  const int n = static_cast<int>(gram.cols()) - 1;
  std::optional<SquareRootForm> form = FromLdlt(gram);
  if (!form) form = FromPivotedCholesky(gram);
  if (!form) return FromQr(rows());
  const double squared_norm = gram(n, n);
  const double rho_squared = squared_norm - form->z.squaredNorm();
  if (rho_squared < -kRoundingSlack * squared_norm) return FromQr(rows());
  form->rho = std::sqrt(std::max(rho_squared, 0.0));
  return *std::move(form);
}

}  // namespace pfdm
