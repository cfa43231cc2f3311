#include "pfdm/square_root_form.h"

#include <cmath>
#include <vector>

#include "Eigen/Cholesky"
#include "Eigen/QR"
#include "glog/logging.h"

namespace pfdm {
namespace {

// How far |z|^2 may exceed |r|^2 from rounding before the Cholesky route
// is distrusted.
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

// The Cholesky factor of the Gram matrix [J r]^T [J r] is [R z; 0 rho]:
// ~half the flops of a QR and one dense rank update.  Columns that are
// exactly zero (b1 while b0 = 0, a knot whose weight is 0 for every point)
// make it singular; they are decoupled from the rest, so they are factored
// as 1 and zeroed after.  Near-singular J can still spoil z, which
// |z| > |r| exposes; then the QR decides.
SquareRootForm ToSquareRootForm(const RowMajorMatrix& a) {
  const int n = static_cast<int>(a.cols()) - 1;
  CHECK_GT(a.rows(), n);
  Eigen::MatrixXd gram = Eigen::MatrixXd::Zero(n + 1, n + 1);
  gram.selfadjointView<Eigen::Lower>().rankUpdate(a.transpose());
  std::vector<int> zero_columns;
  for (int i = 0; i < n; ++i) {
    if (gram(i, i) == 0.0) {
      gram(i, i) = 1.0;
      zero_columns.push_back(i);
    }
  }
  const Eigen::LLT<Eigen::MatrixXd, Eigen::Lower> llt(gram.topLeftCorner(n, n));
  if (llt.info() != Eigen::Success) return FromQr(a);
  SquareRootForm form;
  form.z = llt.matrixL().solve(gram.row(n).head(n).transpose());
  const double squared_norm = gram(n, n);
  const double rho_squared = squared_norm - form.z.squaredNorm();
  if (rho_squared < -kRoundingSlack * squared_norm) return FromQr(a);
  form.r = llt.matrixU();
  for (int i : zero_columns) form.r(i, i) = 0.0;
  form.rho = std::sqrt(std::max(rho_squared, 0.0));
  return form;
}

}  // namespace pfdm
