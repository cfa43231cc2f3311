// Sines and cosines of many angles in one call.  A group of points needs
// five of each per point and per evaluation; glibc's vector math library
// (libmvec) computes four at once in ~2 ns where one scalar sincos takes
// ~13 ns, which was a fifth of the analytic Jacobian's time.
#ifndef PFDM_UTIL_BATCH_TRIG_H_
#define PFDM_UTIL_BATCH_TRIG_H_

namespace pfdm {

// sines[i] = sin(angles[i]), cosines[i] = cos(angles[i]) for i < n, within
// libmvec's 4 ulp where it is available, else from std::sin and std::cos.
void SinCosMany(const double* angles, int n, double* sines, double* cosines);

// Which implementation SinCosMany uses on this machine ("avx2", "sse2" or
// "scalar"), for the benchmarks' context.
const char* SinCosManyKind();

}  // namespace pfdm

#endif  // PFDM_UTIL_BATCH_TRIG_H_
