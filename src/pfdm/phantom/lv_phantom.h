// A second, independent synthetic LV (`pfdm simulate --phantom lv`): an
// analytic thick-walled LV with tracked SPAMM-like tags and measured truth.
//
// Why it exists: phantom.h builds its data from the model's own equations,
// so a fit of it cannot show a wrong gauge, or a parameter function that
// absorbs another's motion (twist taken up by the pose, breathing by the
// offsets or a3). This phantom never includes model/: the shape is a
// truncated prolate spheroidal shell (lv_shape.h), the motion is written
// per material point (lv_motion.h) and the truth is measured on dense
// material points (lv_truth.h), with definitions close to the clinical
// numbers the fit reports.
//
// Default geometry (ED): mid-wall 95 mm from apex pole to base plane,
// 27 mm radius at the equator (nu = 90 deg; the base plane at nu = 120 deg,
// radius 23.4 mm), wall 10 mm thick at the equator (about 4 mm at the
// apex); mid-wall volume 163 ml, endocardial cavity 107 ml (44 ml at
// end-systole: ejection fraction 59 %). The mid-wall at ED is an
// ellipsoid cut at latitude 30 degrees above its equator, which the paper
// model (u up to pi/6) can take exactly: its frame-0 fit should sit at
// the noise floor, so what it misses later is motion.
// Default systole (p = 1): longitudinal shortening 17 % about the apex,
// mid-wall radial contraction 24 % (apex) to 20 % (base), endocardium 8
// points more, epicardium 15.5 less (the myocardium keeps its volume);
// rotation -10 deg at the apex to +3 deg at
// the base (net twist 13 deg); breathing 4 mm along the axis, 2 mm across
// it and 2 deg of tilt by end-systole; the body in an oblique world pose.
// Segments at end-systole (contraction %, rotation deg): basal 20.68, 0.79;
// mid 21.99, -3.46; apical 23.26, -7.61 (+-0.02 deg from the tilt). With
// the lesion (mid 2 = segment 8; 20-degree, 0.1-height edges): mid 1..6
// contract 22.54, 15.89, 22.54, 21.42, 20.86, 21.42 % and turn -4.18,
// -3.45, -2.75, -2.76, -3.45, -4.18 deg (inside the lesion 6.6 %); basal
// and apical segments are unchanged (lv_truth.h says why the other mid
// segments move).
//
// Tags: each a fixed material point, id = index, in every frame; half on
// short-axis planes (height uniform, longitude uniform), half on long-axis
// planes through the axis (uniform along the meridian arc from the apex
// pole, longitude uniform); on the mid-wall, or through the wall with w
// uniform in [-1, 1]; Gaussian noise per coordinate. Placement and noise
// draw from separate streams of `seed`, so noise_mm = 0 gives the same
// tags without noise.
//
// Partial data (--region, --sampling): `midventricular` keeps the tags to
// ED heights 30-72 % of the length (a squat segment 40 mm long and 45-54
// mm across at the mid-wall, 64 mm with the wall; no apex), as the three
// short-axis tag slices of many clinical studies; `sax-slices` gives
// untracked contour points (ids unique per frame) where a few parallel
// image planes, fixed in the world, cut the moving wall (lv_slices.h):
// the mid-wall, or with wall tags the endocardium and epicardium (their
// WallLayer set, which points.csv does not carry); noise in the image
// plane only.  The truth is the whole LV's, as for full data.
//
// Outliers (outlier_fraction > 0; tags only, not sax-slices contours):
// each frame's tags are drawn
// independently, each an outlier with that probability, moved by a
// distance uniform in [outlier_min_mm, outlier_max_mm] in a uniformly
// random direction on top of its noise, as a tracker that loses a tag in
// one frame puts it.  Their draws have a third stream, made for every
// point whatever the fraction: the data of the inliers are those without
// outliers, and a higher fraction moves a superset of the points, each
// the same way.  A tag moved at frame 0 also misplaces its material point
// for a fit that takes it from frame 0 (pfdm's does), so such a fit sees
// it off in every frame; LvFrameTruth::outlier_ids says which were moved
// where.
#ifndef PFDM_PHANTOM_LV_PHANTOM_H_
#define PFDM_PHANTOM_LV_PHANTOM_H_

#include <string>
#include <vector>

#include "Eigen/Core"
#include "pfdm/phantom/lv_cylinder.h"
#include "pfdm/phantom/lv_motion.h"
#include "pfdm/phantom/lv_shape.h"
#include "pfdm/phantom/lv_truth.h"
#include "pfdm/util/point_data.h"

namespace pfdm {

// Where tags (or contours) lie: on the mid-wall, through the wall (both
// walls' contours), on the endocardium alone (its contours: a cavity's,
// as biv-me's lv-cavity), or on the epicardium alone.
enum class LvTagLayer { kMidwall, kWall, kEndocardium, kEpicardium };
// "midwall", "wall", "endo" or "epi"; false if unknown.
bool ParseLvTagLayer(const std::string& name, LvTagLayer* layer);
std::string LvTagLayerName(LvTagLayer layer);

enum class LvRegion { kFull, kMidventricular };
// "full" or "midventricular"; false if unknown.
bool ParseLvRegion(const std::string& name, LvRegion* region);
std::string LvRegionName(LvRegion region);

enum class LvSampling { kTags, kSaxSlices };
// "tags" or "sax-slices"; false if unknown.
bool ParseLvSampling(const std::string& name, LvSampling* sampling);
std::string LvSamplingName(LvSampling sampling);

struct LvPhantomOptions {
  LvKinematics kinematics = LvKinematics::kSystole;
  LvTagLayer tags = LvTagLayer::kMidwall;
  int num_frames = 0;  // 0: DefaultFrameCount(kinematics).
  int num_tags = 2000;
  double noise_mm = 0.5;          // Gaussian, per coordinate.
  double outlier_fraction = 0.0;  // 0 to 1, per point and frame.
  double outlier_min_mm = 5.0;
  double outlier_max_mm = 10.0;
  unsigned seed = 1;
  bool breathing = true;  // Systole and cycle only.
  LvShapeSize shape;
  LvDeformation deformation;  // deformation.lesion: off by default.
  // The shell's shape and how its wall thickens (lv_cylinder.h,
  // lv_motion.h).  A cylinder is a mid-ventricular segment of tags (region
  // and sampling stay at their defaults); its truth is analytic.
  LvGeometry geometry = LvGeometry::kProlate;
  LvThickeningLaw law = LvThickeningLaw::kDesigned;
  LvRegion region = LvRegion::kFull;
  LvSampling sampling = LvSampling::kTags;
  // sax-slices: planes per frame; 0: 3 for a mid-ventricular region, 9
  // for the full LV.
  int num_slices = 0;
  // sax-slices: long-axis planes too, through frame 0's long axis, 180 / n
  // degrees apart (biv-me's views: 3), each one contour of both sides.
  int num_long_axis_planes = 0;
};

// The region's ED heights, fractions of the mid-wall's length from its apex
// pole: tags lie between them.  Full: 0 and 1.
struct LvHeights {
  double low = 0.0, high = 1.0;
};
LvHeights LvRegionHeights(LvRegion region);
// The short-axis slices' ED heights, fractions likewise, evenly spaced from
// the region's lowest to its highest (full: 0.05 to 0.9, the apex pole and
// the base plane left out, as in a short-axis stack).
std::vector<double> LvSliceHeights(const LvPhantomOptions& options);

// The RV insertion the phantom's AHA segments hang on: the anterior at body
// longitude phi = atan2(y, x) = kLvAnteriorInsertionDeg, the inferior 120
// degrees on clockwise seen from the base (as the septum runs from the
// anterior insertion in a right-handed patient frame), at the body's -x.
// AHA segment 8 (mid anteroseptal) then spans phi -120 to -60 degrees,
// longitude lambda 60 to 120 from -x: the default lesion's.
inline constexpr double kLvAnteriorInsertionDeg = -60.0;
inline constexpr double kLvInferiorInsertionDeg = -180.0;
// The insertion points' ED height fraction, on the mid-wall.
inline constexpr double kLvInsertionHeight = 0.6;

struct LvPhantom {
  LvPhantomOptions options;  // num_frames resolved.
  // The RV insertion points at frame 0, world (see kLvAnteriorInsertionDeg).
  Eigen::Vector3d rv_anterior = Eigen::Vector3d::Zero();
  Eigen::Vector3d rv_inferior = Eigen::Vector3d::Zero();
  // source "lv-phantom"; id = tag index (sax-slices: frame x num_tags +
  // the point's index in its frame).
  PointSequence points;
  std::vector<Eigen::Vector3d> tag_material;  // ED body position per tag.
  std::vector<LvFrameTruth> truth;            // Per frame.
};

// Throws InputError for num_frames < 0, num_tags < 1, noise_mm < 0,
// num_slices < 0, fewer tags than slice contours (sax-slices), an
// outlier_fraction outside [0, 1] or an outlier range not 0 <= min <= max.
LvPhantom MakeLvPhantom(const LvPhantomOptions& options);

// World position at frame `motion` of the material point at ED body
// position X (noise-free), on the prolate shell.
Eigen::Vector3d LvWorldPoint(const LvShape& shape,
                             const LvDeformation& deformation,
                             const LvFrameMotion& motion,
                             const Eigen::Vector3d& ed_body,
                             LvThickeningLaw law = LvThickeningLaw::kDesigned);

}  // namespace pfdm

#endif  // PFDM_PHANTOM_LV_PHANTOM_H_
