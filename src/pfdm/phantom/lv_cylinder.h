// The LV phantom's second geometry (`--geometry cylinder`): a cylindrical
// mid-ventricular segment, no apex, no base, its truth written down rather
// than measured.
//
// Why: on the prolate shell (lv_shape.h) the wall is thin toward the apex
// and its truth is measured on material points; a cylinder of constant
// wall, which only a segment of the LV is, shows a fit's thickness and its
// endocardial motion where nothing else varies, and its numbers are exact.
//
// Body frame as the prolate phantom's: the axis along +z, heights measured
// from a virtual apex pole at z = 0, h = z / length_mm.  The mid-wall has
// radius radius_mm, the wall wall_mm (LvShapeSize's equatorial values, 27
// and 10 mm), between the mid-ventricular region's heights (LvHeights 0.30
// to 0.72: 40 mm of a 95 mm LV).  w = (R - radius_mm) / (wall_mm / 2).
// The motion is lv_motion.h's at (h, w): longitudinal shortening about
// z = 0, twist theta(h), radial contraction by the thickening law.
//
// Truth, analytic (the motion keeps each material ring a circle about the
// axis and each transmural line radial): per ring height, radial
// contraction 100 (1 - r / R) of each layer, thickening 100 ((r_epi -
// r_endo) / (R_epi - R_endo) - 1), rotation theta(h) p; volumes of the
// segment integrated over its heights.  With the designed law's defaults at
// mid height, ES: endocardium 30 %, epicardium 6.5 %, thickening 45 %; with
// the incompressible law, 29 %, 6.5 % and 43 %.  Rings outside the segment
// carry the same formulas (no material lies there).
#ifndef PFDM_PHANTOM_LV_CYLINDER_H_
#define PFDM_PHANTOM_LV_CYLINDER_H_

#include "Eigen/Core"
#include "pfdm/phantom/lv_motion.h"
#include "pfdm/phantom/lv_shape.h"
#include "pfdm/phantom/lv_truth.h"

namespace pfdm {

enum class LvGeometry { kProlate, kCylinder };
// "prolate" or "cylinder"; false if unknown.
bool ParseLvGeometry(const std::string& name, LvGeometry* geometry);
std::string LvGeometryName(LvGeometry geometry);

struct LvCylinder {
  double radius_mm = 27.0;  // Mid-wall.
  double wall_mm = 10.0;
  double length_mm = 95.0;         // Of the virtual LV: h = z / length_mm.
  double low = 0.30, high = 0.72;  // The segment's heights, fractions.

  double Radius(double w) const { return radius_mm + 0.5 * w * wall_mm; }
  Eigen::Vector3d Position(double h, double phi, double w) const;
  LvMaterialPoint MaterialPoint(const Eigen::Vector3d& ed_body) const;
  LvLawRadii LawRadii() const { return {radius_mm, wall_mm}; }
};

// The cylinder's default motion: about 30 % thickening, as a mid-ventricular
// segment's (LvDeformation's prolate defaults thicken a cylinder 45 %):
// longitudinal shortening 12 %, at mid height (h = 0.5) endocardium 24 %,
// epicardium 6 %, thickening 33.6 % (designed law); 22.4 %, 6 % and 30.2 %
// (incompressible law).
LvDeformation CylinderDeformation();

// The segment of an LV of that size between heights low and high.
LvCylinder CylinderOf(const LvShapeSize& size, double low, double high);

// The measured-free truth at progress p (no lesion): rings, contraction,
// shortening, rotations and volumes as lv_truth.h defines them, segments
// empty.  The frame's bookkeeping (frame, rigid, pose) is the caller's.
LvFrameTruth CylinderTruth(const LvCylinder& cylinder,
                           const LvDeformation& design, LvThickeningLaw law,
                           double p);

}  // namespace pfdm

#endif  // PFDM_PHANTOM_LV_CYLINDER_H_
