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
// The four lanes' sum, (l0 + l2) + (l1 + l3).
__attribute__((target("avx2,fma"))) double LaneSum(__m256d lanes) {
  const __m128d half = _mm_add_pd(_mm256_castpd256_pd128(lanes),
                                  _mm256_extractf128_pd(lanes, 1));
  return _mm_cvtsd_f64(_mm_add_sd(half, _mm_unpackhi_pd(half, half)));
}

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
  double sum = LaneSum(_mm256_add_pd(sum0, sum1));
  for (; i < n; ++i) sum += a[i] * b[i];
  return sum;
}

// The dot products of a with b[0..3], one pass over a: the factorization
// takes four entries of a row of L at a time, whose rows of L share its
// columns (each of a's loads serves four products).
__attribute__((target("avx2,fma"))) void Dot4Avx2(const double* a,
                                                  const double* const* b, int n,
                                                  double* out) {
  __m256d sum[4] = {_mm256_setzero_pd(), _mm256_setzero_pd(),
                    _mm256_setzero_pd(), _mm256_setzero_pd()};
  int i = 0;
  for (; i + 4 <= n; i += 4) {
    const __m256d x = _mm256_loadu_pd(a + i);
    for (int k = 0; k < 4; ++k) {
      sum[k] = _mm256_fmadd_pd(x, _mm256_loadu_pd(b[k] + i), sum[k]);
    }
  }
  for (int k = 0; k < 4; ++k) {
    out[k] = LaneSum(sum[k]);
    for (int m = i; m < n; ++m) out[k] += a[m] * b[k][m];
  }
}
#endif

void Dot4Sse2(const double* a, const double* const* b, int n, double* out) {
  for (int k = 0; k < 4; ++k) out[k] = DotSse2(a, b[k], n);
}

// The kernels this CPU runs, chosen once.
struct DotKernels {
  double (*dot)(const double*, const double*, int);
  void (*dot4)(const double*, const double* const*, int, double*);
};

const DotKernels& Kernels() {
  static const DotKernels kernels = [] {
#ifdef PFDM_BAND_AVX2
    if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma")) {
      return DotKernels{DotAvx2, Dot4Avx2};
    }
#endif
    return DotKernels{DotSse2, Dot4Sse2};
  }();
  return kernels;
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
  const auto [dot, dot4] = Kernels();
  for (int i = 0; i < size_; ++i) {
    const int first = std::max(0, i - b);
    const double* row_i = band_.row(i).data();
    // L(i, j .. j + 3) four at a time: their sums over the columns before
    // j in one pass, then each with the entries of L(i, .) just found.
    int j = first;
    for (; j + 4 <= i; j += 4) {
      double sums[4] = {0.0, 0.0, 0.0, 0.0};
      const double* rows[4];
      for (int k = 0; k < 4; ++k) {
        rows[k] = band_.row(j + k).data() + first - (j + k) + b;
      }
      if (j > first) dot4(row_i + first - i + b, rows, j - first, sums);
      for (int k = 0; k < 4; ++k) {
        double s = band_(i, j + k - i + b) - sums[k];
        for (int m = 0; m < k; ++m) {
          s -= band_(i, j + m - i + b) * rows[k][j + m - first];
        }
        band_(i, j + k - i + b) = s / band_(j + k, b);
      }
    }
    for (; j <= i; ++j) {
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

// One right-hand side: Eigen's products, row by row, cost as much in
// dispatch as in arithmetic at this bandwidth (a fifth of the contours'
// whole solve of their field with normals).
void BandCholesky::SolveVector(double* x) const {
  const int b = bandwidth_;
  const auto dot = Kernels().dot;
  for (int i = 0; i < size_; ++i) {
    const int first = std::max(0, i - b);
    const double* row = band_.row(i).data() + first - i + b;
    x[i] = (x[i] - dot(row, x + first, i - first)) / band_(i, b);
  }
  for (int i = size_ - 1; i >= 0; --i) {
    x[i] /= band_(i, b);
    const int first = std::max(0, i - b);
    const double* row = band_.row(i).data() + first - i + b;
    const double xi = x[i];
    for (int m = 0; m < i - first; ++m) x[first + m] -= row[m] * xi;
  }
}

BandCholesky::RowMajorMatrix BandCholesky::Solve(RowMajorMatrix x) const {
  const int b = bandwidth_;
  if (x.cols() == 1) {
    SolveVector(x.data());
    return x;
  }
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
