#include "pfdm/util/band_cholesky.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace pfdm {

bool BandCholesky::Compute(const Eigen::SparseMatrix<double>& k) {
  size_ = static_cast<int>(k.rows());
  bandwidth_ = 0;
  for (int j = 0; j < k.outerSize(); ++j) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(k, j); it; ++it) {
      bandwidth_ = std::max(bandwidth_, std::abs(it.index() - j));
    }
  }
  const int b = bandwidth_;
  band_ = RowMajorMatrix::Zero(size_, b + 1);
  for (int j = 0; j < k.outerSize(); ++j) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(k, j); it; ++it) {
      const int i = it.index();
      if (i >= j) band_(i, j - i + b) += it.value();
    }
  }
  for (int i = 0; i < size_; ++i) {
    const int first = std::max(0, i - b);
    for (int j = first; j <= i; ++j) {
      // L(i, j) = (K(i, j) - sum_{first <= m < j} L(i, m) L(j, m)) / L(j, j);
      // both rows hold columns first .. j - 1 within the band.
      const int count = j - first;
      double s = band_(i, j - i + b);
      if (count > 0) {
        s -= band_.row(i)
                 .segment(first - i + b, count)
                 .dot(band_.row(j).segment(first - j + b, count));
      }
      if (j < i) {
        band_(i, j - i + b) = s / band_(j, b);
      } else {
        if (!(s > 0.0)) return false;
        band_(i, b) = std::sqrt(s);
      }
    }
  }
  return true;
}

BandCholesky::RowMajorMatrix BandCholesky::Solve(RowMajorMatrix x) const {
  const int b = bandwidth_;
  // L y = b, row by row.
  for (int i = 0; i < size_; ++i) {
    const int first = std::max(0, i - b);
    if (i > first) {
      x.row(i).noalias() -= band_.row(i).segment(first - i + b, i - first) *
                            x.middleRows(first, i - first);
    }
    x.row(i) /= band_(i, b);
  }
  // L^T x = y from the last row up, each solved row taken out of the rows
  // its column of L^T reaches.
  for (int i = size_ - 1; i >= 0; --i) {
    x.row(i) /= band_(i, b);
    const int first = std::max(0, i - b);
    if (i > first) {
      x.middleRows(first, i - first).noalias() -=
          band_.row(i).segment(first - i + b, i - first).transpose() * x.row(i);
    }
  }
  return x;
}

}  // namespace pfdm
