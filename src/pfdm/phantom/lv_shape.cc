#include "pfdm/phantom/lv_shape.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "pfdm/util/angles.h"

namespace pfdm {
namespace {

// Trapezoid steps along a meridian: arc fractions good to ~1e-5.
constexpr int kArcSteps = 400;

}  // namespace

LvShape::LvShape(const LvShapeSize& size)
    : size_(size), length_(size.length_mm) {
  // The mid-wall's apex pole is at z = 0 and its base plane cuts it at
  // nu_base: length = a (1 - cos nu_base).
  a_ = length_ / (1.0 - std::cos(size.base_nu_deg * kPi / 180.0));
  d_ = std::sqrt(a_ * a_ - size.radius_mm * size.radius_mm);
  mu_mid_ = std::atanh(size.radius_mm / a_);
  // Equatorial thickness d (sinh(mu + dmu) - sinh(mu - dmu)) = 2 a sinh dmu.
  dmu_ = std::asinh(size.wall_mm / (2.0 * a_));
}

Eigen::Vector3d LvShape::Position(double nu, double phi, double w) const {
  const double mu = Mu(w);
  const double r = d_ * std::sinh(mu) * std::sin(nu);
  return {r * std::cos(phi), r * std::sin(phi),
          a_ - d_ * std::cosh(mu) * std::cos(nu)};
}

double LvShape::ApexZ(double w) const { return a_ - d_ * std::cosh(Mu(w)); }

double LvShape::NuAtHeight(double z, double w) const {
  const double c = (a_ - z) / (d_ * std::cosh(Mu(w)));
  return std::acos(std::clamp(c, -1.0, 1.0));
}

double LvShape::Transmural(const Eigen::Vector3d& body) const {
  const double r = std::hypot(body.x(), body.y());
  const double sum =
      std::hypot(r, body.z() - (a_ - d_)) + std::hypot(r, body.z() - (a_ + d_));
  const double mu = std::acosh(std::max(1.0, sum / (2.0 * d_)));
  return (mu - mu_mid_) / dmu_;
}

double LvShape::NuAtArcFraction(double fraction, double w) const {
  const double mu = Mu(w), nu_end = BaseNu(w);
  const double sh = std::sinh(mu), ch = std::cosh(mu);
  auto speed = [&](double nu) {
    return d_ * std::hypot(sh * std::cos(nu), ch * std::sin(nu));
  };
  std::vector<double> arc(kArcSteps + 1, 0.0);
  const double step = nu_end / kArcSteps;
  for (int i = 1; i <= kArcSteps; ++i) {
    arc[i] =
        arc[i - 1] + 0.5 * step * (speed((i - 1) * step) + speed(i * step));
  }
  const double target = std::clamp(fraction, 0.0, 1.0) * arc.back();
  const int i = static_cast<int>(
      std::upper_bound(arc.begin(), arc.end(), target) - arc.begin());
  if (i > kArcSteps) return nu_end;
  const double t = (target - arc[i - 1]) / (arc[i] - arc[i - 1]);
  return (i - 1 + t) * step;
}

double LvShape::ClosedVolume(double w) const {
  // A spheroid of semi-axes (A, B) from its pole to a plane l above it:
  // pi B^2 / A^2 (A l^2 - l^3 / 3).
  const double big = d_ * std::cosh(Mu(w)), small = d_ * std::sinh(Mu(w));
  const double l = length_ - ApexZ(w);
  return kPi * small * small / (big * big) * (big * l * l - l * l * l / 3.0);
}

}  // namespace pfdm
