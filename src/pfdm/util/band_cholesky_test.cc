#include "pfdm/util/band_cholesky.h"

#include <random>
#include <vector>

#include "Eigen/Cholesky"
#include "gtest/gtest.h"

namespace pfdm {
namespace {

// A random symmetric matrix of bandwidth `band`, made diagonally dominant.
Eigen::SparseMatrix<double> RandomBand(int n, int band, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<Eigen::Triplet<double>> entries;
  for (int i = 0; i < n; ++i) {
    entries.emplace_back(i, i, 2.0 * band + 1.0);
    for (int j = std::max(0, i - band); j < i; ++j) {
      if (unit(random) < 0.0) continue;  // Holes inside the band too.
      const double value = unit(random);
      entries.emplace_back(i, j, value);
      entries.emplace_back(j, i, value);
    }
  }
  Eigen::SparseMatrix<double> k(n, n);
  k.setFromTriplets(entries.begin(), entries.end());
  return k;
}

// The solves of 7 right-hand sides agree with Eigen's dense LLT to 1e-12
// (the matrix is well conditioned); the bandwidth is the matrix's.
TEST(BandCholeskyTest, SolvesAsADenseCholesky) {
  const Eigen::SparseMatrix<double> k = RandomBand(60, 9, 4);
  BandCholesky band;
  ASSERT_TRUE(band.Compute(k));
  EXPECT_EQ(band.bandwidth(), 9);
  const BandCholesky::RowMajorMatrix b =
      BandCholesky::RowMajorMatrix::Random(60, 7);
  const Eigen::MatrixXd expected =
      Eigen::MatrixXd(k).llt().solve(Eigen::MatrixXd(b));
  const Eigen::MatrixXd x = band.Solve(b);
  EXPECT_LT((x - expected).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_GT(expected.cwiseAbs().maxCoeff(), 0.01);
}

// As wide as the contours' field (dot products of up to 145 terms, which
// the AVX2 kernel takes 8 and 4 at a time with a scalar tail).
TEST(BandCholeskyTest, WideBandSolvesAsADenseCholesky) {
  const Eigen::SparseMatrix<double> k = RandomBand(400, 145, 6);
  BandCholesky band;
  ASSERT_TRUE(band.Compute(k));
  EXPECT_EQ(band.bandwidth(), 145);
  const BandCholesky::RowMajorMatrix b =
      BandCholesky::RowMajorMatrix::Random(400, 3);
  const Eigen::MatrixXd expected =
      Eigen::MatrixXd(k).llt().solve(Eigen::MatrixXd(b));
  const Eigen::MatrixXd x = band.Solve(b);
  EXPECT_LT((x - expected).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_GT(expected.cwiseAbs().maxCoeff(), 1e-3);
}

// One right-hand side takes its own path (dot products and row updates
// instead of Eigen's products): the dense LLT's solve to 1e-12, and the
// many-column path's answer for the same column.
TEST(BandCholeskyTest, SolvesOneRightHandSideAsMany) {
  const Eigen::SparseMatrix<double> k = RandomBand(400, 145, 8);
  BandCholesky band;
  ASSERT_TRUE(band.Compute(k));
  const BandCholesky::RowMajorMatrix b =
      BandCholesky::RowMajorMatrix::Random(400, 2);
  const Eigen::MatrixXd expected =
      Eigen::MatrixXd(k).llt().solve(Eigen::MatrixXd(b.col(0)));
  const Eigen::MatrixXd one = band.Solve(b.col(0));
  const Eigen::MatrixXd many = band.Solve(b);
  EXPECT_LT((one - expected).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT((one - many.col(0)).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_GT(expected.cwiseAbs().maxCoeff(), 1e-3);
}

// K handed over as its lower band factorizes as the sparse K: the same
// solve to the bit, and a band wider than K's entries reach is taken as
// given (its zeros change the sums' grouping: round-off only).
TEST(BandCholeskyTest, FactorizesItsLowerBandAsTheSparseMatrix) {
  const Eigen::SparseMatrix<double> k = RandomBand(80, 11, 7);
  auto lower_band = [&k](int width) {
    BandCholesky::RowMajorMatrix lower =
        BandCholesky::RowMajorMatrix::Zero(k.rows(), width + 1);
    for (int j = 0; j < k.outerSize(); ++j) {
      for (Eigen::SparseMatrix<double>::InnerIterator it(k, j); it; ++it) {
        if (it.index() >= j)
          lower(it.index(), j - it.index() + width) = it.value();
      }
    }
    return lower;
  };
  BandCholesky sparse, band, wide;
  ASSERT_TRUE(sparse.Compute(k));
  ASSERT_TRUE(band.ComputeBand(lower_band(11)));
  ASSERT_TRUE(wide.ComputeBand(lower_band(15)));
  EXPECT_EQ(band.bandwidth(), 11);
  EXPECT_EQ(wide.bandwidth(), 15);
  const BandCholesky::RowMajorMatrix b =
      BandCholesky::RowMajorMatrix::Random(80, 4);
  const BandCholesky::RowMajorMatrix x = sparse.Solve(b);
  EXPECT_EQ(band.Solve(b), x);
  EXPECT_LT((wide.Solve(b) - x).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_GT(x.cwiseAbs().maxCoeff(), 0.01);
}

TEST(BandCholeskyTest, RefusesAnIndefiniteMatrix) {
  Eigen::SparseMatrix<double> k = RandomBand(20, 3, 5);
  k.coeffRef(11, 11) = -1.0;
  BandCholesky band;
  EXPECT_FALSE(band.Compute(k));
}

}  // namespace
}  // namespace pfdm
