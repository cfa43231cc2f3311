#include "pfdm/util/batch_trig.h"

#include <algorithm>
#include <cmath>

#if defined(PFDM_HAVE_LIBMVEC) && defined(__x86_64__)
#include <immintrin.h>

// libmvec's entry points, named by the x86-64 vector function ABI: 'b' for
// SSE (two lanes), 'd' for AVX2 (four lanes).  glibc declares them only
// under -ffast-math, which this project does not use.
extern "C" {
__m128d _ZGVbN2v_sin(__m128d);
__m128d _ZGVbN2v_cos(__m128d);
__m256d _ZGVdN4v_sin(__m256d);
__m256d _ZGVdN4v_cos(__m256d);
}
#define PFDM_VECTOR_TRIG 1
#endif

namespace pfdm {
namespace {

#ifdef PFDM_VECTOR_TRIG

// The last, partial vector is padded, so every angle takes the same route
// whatever its place in the batch.
template <int kLanes, typename Kernel>
void InLanes(const double* angles, int n, double* sines, double* cosines,
             Kernel kernel) {
  int i = 0;
  for (; i + kLanes <= n; i += kLanes) {
    kernel(angles + i, sines + i, cosines + i);
  }
  if (i == n) return;
  double in[kLanes] = {}, s[kLanes], c[kLanes];
  std::copy(angles + i, angles + n, in);
  kernel(in, s, c);
  std::copy(s, s + (n - i), sines + i);
  std::copy(c, c + (n - i), cosines + i);
}

__attribute__((target("avx2,fma"))) void SinCosAvx2(const double* angles, int n,
                                                    double* sines,
                                                    double* cosines) {
  InLanes<4>(
      angles, n, sines, cosines,
      [](const double* x, double* s, double* c)
          __attribute__((target("avx2,fma"))) {
            const __m256d v = _mm256_loadu_pd(x);
            _mm256_storeu_pd(s, _ZGVdN4v_sin(v));
            _mm256_storeu_pd(c, _ZGVdN4v_cos(v));
          });
}

void SinCosSse2(const double* angles, int n, double* sines, double* cosines) {
  InLanes<2>(angles, n, sines, cosines,
             [](const double* x, double* s, double* c) {
               const __m128d v = _mm_loadu_pd(x);
               _mm_storeu_pd(s, _ZGVbN2v_sin(v));
               _mm_storeu_pd(c, _ZGVbN2v_cos(v));
             });
}

bool HasAvx2() {
  static const bool has =
      __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  return has;
}

#endif  // PFDM_VECTOR_TRIG

}  // namespace

void SinCosMany(const double* angles, int n, double* sines, double* cosines) {
#ifdef PFDM_VECTOR_TRIG
  if (HasAvx2()) return SinCosAvx2(angles, n, sines, cosines);
  return SinCosSse2(angles, n, sines, cosines);
#else
  for (int i = 0; i < n; ++i) {
    sines[i] = std::sin(angles[i]);
    cosines[i] = std::cos(angles[i]);
  }
#endif
}

const char* SinCosManyKind() {
#ifdef PFDM_VECTOR_TRIG
  return HasAvx2() ? "avx2" : "sse2";
#else
  return "scalar";
#endif
}

}  // namespace pfdm
