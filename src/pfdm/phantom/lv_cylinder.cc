#include "pfdm/phantom/lv_cylinder.h"

#include <cmath>
#include <string>

#include "pfdm/util/angles.h"

namespace pfdm {
namespace {

// Midpoint-rule slices of the segment's height for its volumes: exact for
// the designed law's radii, which are linear in h (areas quadratic: the
// midpoint rule's error 1e-5 relative).
constexpr int kVolumeSlices = 200;

// Volume (ml) inside layer w of the segment at progress p.
double LayerVolumeMl(const LvCylinder& cylinder, const LvDeformation& design,
                     LvThickeningLaw law, double w, double p) {
  const double dh = (cylinder.high - cylinder.low) / kVolumeSlices;
  const double stretch = 1.0 - design.longitudinal_shortening * p;
  double volume = 0.0;
  for (int k = 0; k < kVolumeSlices; ++k) {
    const double h = cylinder.low + (k + 0.5) * dh;
    const double r = RadialFactor(design, law, cylinder.LawRadii(), h, w, p) *
                     cylinder.Radius(w);
    volume += kPi * r * r * stretch * dh * cylinder.length_mm;
  }
  return volume / 1000.0;
}

}  // namespace

bool ParseLvGeometry(const std::string& name, LvGeometry* geometry) {
  if (name == "prolate") {
    *geometry = LvGeometry::kProlate;
  } else if (name == "cylinder") {
    *geometry = LvGeometry::kCylinder;
  } else {
    return false;
  }
  return true;
}

std::string LvGeometryName(LvGeometry geometry) {
  return geometry == LvGeometry::kCylinder ? "cylinder" : "prolate";
}

Eigen::Vector3d LvCylinder::Position(double h, double phi, double w) const {
  const double r = Radius(w);
  return {r * std::cos(phi), r * std::sin(phi), h * length_mm};
}

LvMaterialPoint LvCylinder::MaterialPoint(
    const Eigen::Vector3d& ed_body) const {
  LvMaterialPoint point;
  point.radius = std::hypot(ed_body.x(), ed_body.y());
  point.h = ed_body.z() / length_mm;
  point.w = (point.radius - radius_mm) / (0.5 * wall_mm);
  point.phi = std::atan2(ed_body.y(), ed_body.x());
  point.z = ed_body.z();
  return point;
}

LvDeformation CylinderDeformation() {
  LvDeformation design;
  design.longitudinal_shortening = 0.12;
  design.radial_endo_extra = 0.02;
  design.radial_epi_less = 0.16;
  return design;
}

LvCylinder CylinderOf(const LvShapeSize& size, double low, double high) {
  LvCylinder cylinder;
  cylinder.radius_mm = size.radius_mm;
  cylinder.wall_mm = size.wall_mm;
  cylinder.length_mm = size.length_mm;
  cylinder.low = low;
  cylinder.high = high;
  return cylinder;
}

LvFrameTruth CylinderTruth(const LvCylinder& cylinder,
                           const LvDeformation& design, LvThickeningLaw law,
                           double p) {
  LvFrameTruth truth;
  truth.progress = p;
  const LvLawRadii radii = cylinder.LawRadii();
  auto factor = [&](double h, double w) {
    return RadialFactor(design, law, radii, h, w, p);
  };
  LvLayerRings* layers[3] = {&truth.endo, &truth.midwall, &truth.epi};
  double in_segment = 0.0, count = 0.0;
  for (double h : LvRingHeights()) {
    for (int k = 0; k < 3; ++k) {
      layers[k]->rotation_deg.push_back(DesignedRotationDeg(design, h) * p);
      layers[k]->radial_contraction_percent.push_back(
          100.0 * (1.0 - factor(h, k - 1.0)));
    }
    const double endo = factor(h, -1.0) * cylinder.Radius(-1.0);
    const double epi = factor(h, 1.0) * cylinder.Radius(1.0);
    truth.wall_thickening_percent.push_back(
        100.0 * ((epi - endo) / cylinder.wall_mm - 1.0));
    if (h >= cylinder.low && h <= cylinder.high) {
      in_segment += 100.0 * (1.0 - factor(h, 0.0));
      count += 1.0;
    }
  }
  truth.mean_radial_contraction_percent = count > 0 ? in_segment / count : 0;
  truth.length_mm = (1.0 - design.longitudinal_shortening * p) * cylinder.high *
                    cylinder.length_mm;
  truth.longitudinal_shortening_percent =
      100.0 * design.longitudinal_shortening * p;
  truth.apex_rotation_deg = DesignedRotationDeg(design, 0.0) * p;
  truth.base_rotation_deg = DesignedRotationDeg(design, 1.0) * p;
  truth.net_twist_deg = truth.base_rotation_deg - truth.apex_rotation_deg;
  truth.volume_ml = LayerVolumeMl(cylinder, design, law, 0.0, p);
  truth.endo_volume_ml = LayerVolumeMl(cylinder, design, law, -1.0, p);
  truth.epi_volume_ml = LayerVolumeMl(cylinder, design, law, 1.0, p);
  truth.myocardial_volume_ml = truth.epi_volume_ml - truth.endo_volume_ml;
  return truth;
}

}  // namespace pfdm
