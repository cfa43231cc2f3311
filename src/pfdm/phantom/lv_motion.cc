#include "pfdm/phantom/lv_motion.h"

#include <algorithm>
#include <cmath>

#include "pfdm/util/angles.h"

namespace pfdm {
namespace {

constexpr double kRadians = kPi / 180.0;

struct NamedKinematics {
  const char* name;
  LvKinematics kinematics;
};
constexpr NamedKinematics kNames[] = {
    {"systole", LvKinematics::kSystole},
    {"cycle", LvKinematics::kCycle},
    {"rigid-axial", LvKinematics::kRigidAxial},
    {"rigid-lateral", LvKinematics::kRigidLateral},
    {"rigid-tilt", LvKinematics::kRigidTilt},
    {"rigid-spin", LvKinematics::kRigidSpin},
    {"static", LvKinematics::kStatic},
};

// 0 at x <= 0, 1 at x >= 1, flat at both ends.
double SmoothStep(double x) {
  const double t = std::clamp(x, 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

// 1 well inside [begin, end], 0 outside, rising over `edge` at each end.
double Window(double x, double begin, double end, double edge) {
  return SmoothStep((x - begin) / edge) * SmoothStep((end - x) / edge);
}

}  // namespace

double DesignedRadialContraction(const LvDeformation& design, double h,
                                 double w) {
  const double mid =
      design.radial_apex + (design.radial_base - design.radial_apex) * h;
  const double endo = design.radial_endo_extra, epi = design.radial_epi_less;
  return mid - 0.5 * (endo + epi) * w + 0.5 * (endo - epi) * w * w;
}

double DesignedRotationDeg(const LvDeformation& design, double h) {
  return design.apex_rotation_deg +
         (design.base_rotation_deg - design.apex_rotation_deg) * h;
}

double LesionWeight(const LvDeformation& design, double h, double lambda_deg,
                    double w) {
  // Longitude from the lesion's centre, in [-180, 180).
  const double from = lambda_deg - design.lesion_center_deg;
  const double off = from - 360.0 * std::floor((from + 180.0) / 360.0);
  const double depth =
      design.lesion_outer_w >= 1.0
          ? 1.0
          : SmoothStep((design.lesion_outer_w - w) / design.lesion_edge_w +
                       0.5);
  return Window(h, 1.0 / 3.0, 2.0 / 3.0, design.lesion_edge_h) *
         Window(off, -30.0, 30.0, design.lesion_edge_deg) * depth;
}

LvMaterialPoint MaterialPointAt(const LvShape& shape,
                                const Eigen::Vector3d& ed_body) {
  LvMaterialPoint point;
  point.h = ed_body.z() / shape.base_z();
  point.w = shape.Transmural(ed_body);
  point.radius = std::hypot(ed_body.x(), ed_body.y());
  point.phi = std::atan2(ed_body.y(), ed_body.x());
  point.z = ed_body.z();
  return point;
}

bool ParseLvThickeningLaw(const std::string& name, LvThickeningLaw* law) {
  if (name == "designed") {
    *law = LvThickeningLaw::kDesigned;
  } else if (name == "incompressible") {
    *law = LvThickeningLaw::kIncompressible;
  } else {
    return false;
  }
  return true;
}

std::string LvThickeningLawName(LvThickeningLaw law) {
  return law == LvThickeningLaw::kIncompressible ? "incompressible"
                                                 : "designed";
}

double RadialFactor(const LvDeformation& design, LvThickeningLaw law,
                    const LvLawRadii& radii, double h, double w, double p) {
  if (law == LvThickeningLaw::kDesigned) {
    return 1.0 - DesignedRadialContraction(design, h, w) * p;
  }
  const double c_epi =
      DesignedRadialContraction(design, h, 0.0) - design.radial_epi_less;
  const double half = 0.5 * radii.wall_mm;
  const double big_epi = radii.midwall_mm + half;
  const double big = radii.midwall_mm + w * half;
  const double epi = (1.0 - c_epi * p) * big_epi;
  const double lambda = 1.0 - design.longitudinal_shortening * p;
  const double square = epi * epi - (big_epi * big_epi - big * big) / lambda;
  return std::sqrt(std::max(square, 0.0)) / big;
}

Eigen::Vector3d DeformedBodyPoint(const LvDeformation& design,
                                  const LvMaterialPoint& point, double p,
                                  LvThickeningLaw law,
                                  const LvLawRadii& radii) {
  double contraction =
      1.0 - RadialFactor(design, law, radii, point.h, point.w, p);
  if (design.lesion) {
    // Longitude from -x, counter-clockwise about +z.
    const double lambda_deg = (point.phi + kPi) / kRadians;
    contraction *= 1.0 - design.lesion_loss *
                             LesionWeight(design, point.h, lambda_deg, point.w);
  }
  const double radius = (1.0 - contraction) * point.radius;
  const double turned =
      point.phi + DesignedRotationDeg(design, point.h) * kRadians * p;
  return {radius * std::cos(turned), radius * std::sin(turned),
          (1.0 - design.longitudinal_shortening * p) * point.z};
}

bool ParseLvKinematics(const std::string& name, LvKinematics* kinematics) {
  for (const NamedKinematics& named : kNames) {
    if (name == named.name) {
      *kinematics = named.kinematics;
      return true;
    }
  }
  return false;
}

std::string LvKinematicsName(LvKinematics kinematics) {
  for (const NamedKinematics& named : kNames) {
    if (named.kinematics == kinematics) return named.name;
  }
  return "";
}

int DefaultFrameCount(LvKinematics kinematics) {
  return kinematics == LvKinematics::kCycle ? 9 : 5;
}

LvFrameMotion ScenarioMotion(LvKinematics kinematics, int t, int num_frames,
                             bool breathing) {
  const double s =
      num_frames > 1 ? static_cast<double>(t) / (num_frames - 1) : 0.0;
  LvFrameMotion motion;
  double breath = -1.0;  // Phase of one breath, none when negative.
  switch (kinematics) {
    case LvKinematics::kSystole:
      motion.progress = s;
      breath = 0.5 * s;
      break;
    case LvKinematics::kCycle:
      // The last frame is s = 1 exactly: p and the breath are back to 0.
      motion.progress =
          t == num_frames - 1 ? 0.0 : std::pow(std::sin(kPi * s), 2);
      breath = t == num_frames - 1 ? 0.0 : s;
      break;
    case LvKinematics::kRigidAxial:
      motion.rigid.axial_shift_mm = 8.0 * s;
      break;
    case LvKinematics::kRigidLateral:
      motion.rigid.lateral_shift_mm = 5.0 * s;
      break;
    case LvKinematics::kRigidTilt:
      motion.rigid.tilt_deg = 8.0 * s;
      break;
    case LvKinematics::kRigidSpin:
      motion.rigid.spin_deg = 10.0 * s;
      break;
    case LvKinematics::kStatic:
      break;
  }
  if (breathing && breath >= 0.0) {
    const double rise = std::pow(std::sin(kPi * breath), 2);
    motion.rigid.axial_shift_mm = 4.0 * rise;
    motion.rigid.lateral_shift_mm = 2.0 * std::sin(kPi * breath);
    motion.rigid.tilt_deg = 2.0 * rise;
  }
  return motion;
}

Eigen::Isometry3d RigidBodyMotion(const LvShape& shape,
                                  const LvRigidMotion& motion) {
  const Eigen::Vector3d centre(0.0, 0.0, 0.5 * shape.base_z());
  const Eigen::Matrix3d turn =
      (Eigen::AngleAxisd(motion.spin_deg * kRadians, Eigen::Vector3d::UnitZ()) *
       Eigen::AngleAxisd(motion.tilt_deg * kRadians, kLvTiltAxis))
          .toRotationMatrix();
  Eigen::Isometry3d result = Eigen::Isometry3d::Identity();
  result.linear() = turn;
  result.translation() = centre - turn * centre +
                         motion.axial_shift_mm * Eigen::Vector3d::UnitZ() +
                         motion.lateral_shift_mm * kLvLateral;
  return result;
}

Eigen::Isometry3d LvWorldPose() {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() =
      Eigen::AngleAxisd(50.0 * kRadians,
                        Eigen::Vector3d(-0.4, 0.7, 0.6).normalized())
          .toRotationMatrix();
  pose.translation() = Eigen::Vector3d(20.0, -35.0, 60.0);
  return pose;
}

}  // namespace pfdm
