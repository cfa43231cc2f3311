// Cholesky factorization K = L L^T of a symmetric positive definite matrix
// in its own order, with L kept within K's bandwidth b (the largest |i - j|
// of a nonzero): n b^2 / 2 multiply-adds to factorize, and solves of many
// right-hand sides at once row by row, vectorized along them.  For the
// local field's node matrix (fit/problem/local_direct.h), whose grid order
// is already banded (two rings wide): a general sparse Cholesky solves one
// right-hand side at a time through index arrays, several times slower at
// this size.
#ifndef PFDM_UTIL_BAND_CHOLESKY_H_
#define PFDM_UTIL_BAND_CHOLESKY_H_

#include "Eigen/Core"
#include "Eigen/SparseCore"

namespace pfdm {

class BandCholesky {
 public:
  using RowMajorMatrix =
      Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

  // Factorizes k (its lower triangle is read); returns false when k is not
  // positive definite (a pivot <= 0).
  bool Compute(const Eigen::SparseMatrix<double>& k);
  // The same from K's lower band, K(i, j) at lower(i, j - i + b) for j in
  // [i - b, i], b = lower.cols() - 1 (taken as the bandwidth): for a caller
  // that sums K in place, where a sparse K's triplets and their sorting
  // cost more than the factorization.
  bool ComputeBand(RowMajorMatrix lower);
  // K^{-1} b, column by column.
  RowMajorMatrix Solve(RowMajorMatrix b) const;

  int bandwidth() const { return bandwidth_; }

 private:
  void SolveVector(double* x) const;

  int size_ = 0;
  int bandwidth_ = 0;
  // L(i, j) at band_(i, j - i + bandwidth_), j in [i - bandwidth_, i].
  RowMajorMatrix band_;
};

}  // namespace pfdm

#endif  // PFDM_UTIL_BAND_CHOLESKY_H_
