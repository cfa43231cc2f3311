// The model as a solid: the transmural coordinate w, -1 at the endocardium,
// 0 on the mid-wall surface, +1 at the epicardium (docs/gauge.md, "The
// wall").
#ifndef PFDM_MODEL_TRANSMURAL_H_
#define PFDM_MODEL_TRANSMURAL_H_

#include <cmath>

#include "Eigen/Core"
#include "pfdm/model/parameter_function.h"
#include "pfdm/model/superellipsoid.h"

namespace pfdm {

// n = m / |m|, m = (cos u cos v / a1, cos u sin v / a2, sin u / a3): the unit
// outward normal of the ellipsoid with the radii a1..a3 that the functions
// take at u.  That is the primitive's own normal when eps1 = eps2 = 1 (the
// paper's LV set-up) and a1..a3 do not vary along u; bends, tapers and other
// exponents tilt the true normal away from it, by a few degrees on an LV
// (docs/gauge.md says what that does to h).  It has no singular point: at
// the apex pole it is (0, 0, -1).
template <typename T, typename A>
Eigen::Matrix<T, 3, 1> WallDirection(const T* f, const Angles<A>& angles) {
  using std::sqrt;
  const Eigen::Matrix<T, 3, 1> m(T(angles.cos_u * angles.cos_v) / f[kA1],
                                 T(angles.cos_u * angles.sin_v) / f[kA2],
                                 T(angles.sin_u) / f[kA3]);
  return m / sqrt(m.squaredNorm());
}

// How far along n the material layer w sits from the primitive's surface
// (the layer w = 0): w h / 2 + w^2 s + (w^3 - w) q, s = shift, q = squeeze.
// The endocardium and the epicardium sit at s -+ h / 2, h apart, their
// middle s outward of the layer w = 0; q leaves both walls where they are
// and crowds the layers inside toward the layer w = 0 (q > 0; the spacing
// there, dk/dw = h / 2 - q) or toward the walls (q < 0).  Frame 0 spaces
// the layers evenly (s = q = 0); s lets a wall that thickens more at the
// endocardium carry its middle outward of its middle layer, as an
// incompressible one does and no choice of h can, and q lets the layers
// follow a thickening that is not a quadratic across the wall: the LV
// phantom's designed law makes the cylinder's layers a cubic in w (r =
// 21.07 + 6.33 w + 2.34 w^2 + 0.35 w^3 mm at end-systole), which a quadratic
// fitted to tags through the wall met 0.14 mm inside each wall, reading
// thickening 30.8 % against 33.6 (docs/gauge.md, "The profile across the
// wall").
template <typename T>
T WallDepth(const T* f, double w) {
  return (0.5 * w) * f[kH] + (w * w) * f[kWallShift] +
         (w * w * w - w) * f[kWallSqueeze];
}

// The primitive point of surface w: e + WallDepth n.  The bend, twist and
// offsets then act on it as on the mid-wall.
template <typename T, typename A>
Eigen::Matrix<T, 3, 1> WallOffset(const T* f, const Angles<A>& angles,
                                  double w) {
  return WallDepth(f, w) * WallDirection(f, angles);
}

// The twist of surface w: tau at the mid-wall, tau -+ dtau / 2 at the
// endocardium and epicardium.
template <typename T>
T TwistAt(const T* f, double w) {
  return f[kTau] + (0.5 * w) * f[kDtau];
}

}  // namespace pfdm

#endif  // PFDM_MODEL_TRANSMURAL_H_
