#include "pfdm/util/band_cholesky.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <utility>

#if defined(__x86_64__)
#include <immintrin.h>
#endif

namespace pfdm {
namespace {

// sum_i a[i] b[i]: the factorization's inner loop, n up to the bandwidth
// (145 for the contours' 13 x 24 field with normals).
double DotSse2(const double* a, const double* b, int n) {
  return Eigen::Map<const Eigen::VectorXd>(a, n).dot(
      Eigen::Map<const Eigen::VectorXd>(b, n));
}

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define PFDM_BAND_AVX2 1
// Four lanes and fused multiply-adds where the CPU has them: the build
// targets SSE2, whose two lanes made this loop a tenth of a contour job.
// Other round-off than DotSse2's (the sums' order), nothing else.
__attribute__((target("avx2,fma"))) double DotAvx2(const double* a,
                                                   const double* b, int n) {
  __m256d sum0 = _mm256_setzero_pd(), sum1 = _mm256_setzero_pd();
  int i = 0;
  for (; i + 8 <= n; i += 8) {
    sum0 =
        _mm256_fmadd_pd(_mm256_loadu_pd(a + i), _mm256_loadu_pd(b + i), sum0);
    sum1 = _mm256_fmadd_pd(_mm256_loadu_pd(a + i + 4),
                           _mm256_loadu_pd(b + i + 4), sum1);
  }
  if (i + 4 <= n) {
    sum0 =
        _mm256_fmadd_pd(_mm256_loadu_pd(a + i), _mm256_loadu_pd(b + i), sum0);
    i += 4;
  }
  sum0 = _mm256_add_pd(sum0, sum1);
  __m128d half =
      _mm_add_pd(_mm256_castpd256_pd128(sum0), _mm256_extractf128_pd(sum0, 1));
  double sum = _mm_cvtsd_f64(_mm_add_sd(half, _mm_unpackhi_pd(half, half)));
  for (; i < n; ++i) sum += a[i] * b[i];
  return sum;
}
#endif

using DotFunction = double (*)(const double*, const double*, int);

DotFunction ChooseDot() {
#ifdef PFDM_BAND_AVX2
  if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma")) {
    return DotAvx2;
  }
#endif
  return DotSse2;
}

}  // namespace

bool BandCholesky::Compute(const Eigen::SparseMatrix<double>& k) {
  int b = 0;
  for (int j = 0; j < k.outerSize(); ++j) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(k, j); it; ++it) {
      b = std::max(b, std::abs(it.index() - j));
    }
  }
  RowMajorMatrix lower = RowMajorMatrix::Zero(k.rows(), b + 1);
  for (int j = 0; j < k.outerSize(); ++j) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(k, j); it; ++it) {
      const int i = it.index();
      if (i >= j) lower(i, j - i + b) += it.value();
    }
  }
  return ComputeBand(std::move(lower));
}

bool BandCholesky::ComputeBand(RowMajorMatrix lower) {
  size_ = static_cast<int>(lower.rows());
  bandwidth_ = static_cast<int>(lower.cols()) - 1;
  const int b = bandwidth_;
  band_ = std::move(lower);
  static const DotFunction dot = ChooseDot();
  for (int i = 0; i < size_; ++i) {
    const int first = std::max(0, i - b);
    const double* row_i = band_.row(i).data();
    for (int j = first; j <= i; ++j) {
      // L(i, j) = (K(i, j) - sum_{first <= m < j} L(i, m) L(j, m)) / L(j, j);
      // both rows hold columns first .. j - 1 within the band.
      const int count = j - first;
      double s = band_(i, j - i + b);
      if (count > 0) {
        s -= dot(row_i + first - i + b, band_.row(j).data() + first - j + b,
                 count);
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
