// A symmetric matrix summed in place in its lower band, as the local
// field's direct solve assembles its normal matrix (local_direct.h).
#ifndef PFDM_FIT_PROBLEM_LOWER_BAND_H_
#define PFDM_FIT_PROBLEM_LOWER_BAND_H_

#include <algorithm>

#include "Eigen/Core"
#include "pfdm/util/band_cholesky.h"

namespace pfdm {

// A symmetric matrix summed in place in its lower band: A(i, j), j <= i,
// at lower(i, j - i + width), width a bound on the bandwidth from the
// terms' node spans; used, the largest i - j of an entry added.
struct LowerBand {
  LowerBand(int size, int width_bound)
      : lower(BandCholesky::RowMajorMatrix::Zero(size, width_bound + 1)),
        width(width_bound) {}

  // Entries above the diagonal are A's by symmetry: left out.
  void Add(int i, int j, double value) {
    if (j > i) return;
    lower(i, j - i + width) += value;
    used = std::max(used, i - j);
  }
  // The band as wide as A's entries reach, as BandCholesky takes it.
  BandCholesky::RowMajorMatrix Trimmed() const {
    return lower.rightCols(used + 1);
  }
  // A x, row by row of the band: the row's lower part against x, and its
  // mirror above the diagonal added along x's entries (contiguous both; the
  // column walk of the mirror was a tenth of the contours' field solve).
  Eigen::VectorXd Times(const Eigen::VectorXd& x) const {
    const int n = static_cast<int>(lower.rows());
    Eigen::VectorXd y = Eigen::VectorXd::Zero(n);
    for (int i = 0; i < n; ++i) {
      const int first = std::max(0, i - used);
      const int count = i - first;
      const auto row = lower.row(i).segment(first - i + width, count);
      y[i] += row.dot(x.segment(first, count)) + lower(i, width) * x[i];
      y.segment(first, count) += row.transpose() * x[i];
    }
    return y;
  }

  BandCholesky::RowMajorMatrix lower;
  int width;
  int used = 0;
};

}  // namespace pfdm

#endif  // PFDM_FIT_PROBLEM_LOWER_BAND_H_
