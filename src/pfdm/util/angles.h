// Pi and the degree conversions, for the model's angles (radians) and the
// clinical numbers' (degrees).
#ifndef PFDM_UTIL_ANGLES_H_
#define PFDM_UTIL_ANGLES_H_

namespace pfdm {

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kDegreesPerRadian = 180.0 / kPi;
inline constexpr double kRadiansPerDegree = kPi / 180.0;

}  // namespace pfdm

#endif  // PFDM_UTIL_ANGLES_H_
