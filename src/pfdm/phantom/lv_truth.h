// The analytic LV phantom's ground truth, measured: dense noise-free
// material points of the phantom are moved like the tags and measured in
// world coordinates, relative to frame 0, without using the designed
// constants — a second, independent check of the kinematics.
//
// Definitions (all on mid-wall material points, w = 0, unless said):
// - longitudinal_shortening_percent = 100 (1 - L / L0), L the distance from
//   the apex pole's material point to the centroid of the base ring's
//   (h = 1) material points.
// - Rings: material rings at ED height fractions h = 0.05, 0.10, ..., 1.00
//   of the mid-wall's apex-to-base length (LvRingHeights()), on the
//   mid-wall, endocardium (w = -1) and epicardium (w = +1).
//   rotation_deg: mean over the ring's points of the angle turned about the
//   frame-0 long axis (measured: apex pole to base-ring centroid, frame 0,
//   world) through the ring's own centroid, right-handed; so a spin about
//   the axis reads fully, a translation not at all and a tilt a little.
//   radial_contraction_percent: 100 (1 - r / r0), r the mean distance of
//   the ring's points from their centroid.
// - apex_rotation_deg: the mid-wall rings' rotation extrapolated linearly
//   to h = 0 from h = 0.05 and 0.10 (the pole itself turns no ring);
//   base_rotation_deg: the ring at h = 1; net_twist_deg = base - apex.
//   mean_radial_contraction_percent: the mid-wall rings' mean (equal
//   weights, h = 0.05 ... 1.00).
// - volume_ml: inside the mid-wall surface closed by the plane of its base
//   ring (a closed triangulation, divergence theorem); endo_volume_ml the
//   endocardial cavity likewise, epi_volume_ml the epicardium's,
//   myocardial_volume_ml = epi - endo.
// - segments: the 16 AHA-style segments of report/wall_motion without an
//   RV insertion (thirds of the ED axis, basal first, 6/6/4 sectors of
//   longitude counted counter-clockwise about +z from the body's -x; by the
//   phantom's RV insertion, lv_phantom.h, basal and mid sector k is AHA
//   sector (2 - k) mod 6, so "mid 2" is mid anteroseptal either way):
//   area-weighted means (ED mid-wall area) of each point's rotation as above
//   and of 100 (1 - rho / rho0), rho its distance from its ring's centroid.
//   wall_thickening_percent (segments and per ring): 100 (T / T0 - 1), T
//   the wall's thickness at a mid-wall material point: the vector from the
//   endocardial to the epicardial material point at its (nu, phi) (a
//   coordinate line of mu, normal to every surface at ED) along the
//   mid-wall's current normal there; the segment's area-weighted mean, the
//   ring's plain mean.
//   A lesion pulls its rings' centroids ~0.6 mm toward itself by
//   end-systole, so, by these definitions, the other mid segments read up
//   to 2 points of contraction and 1.3 degrees of rotation away from the
//   design (a fitted ring centre moves likewise; a fitted ring twist does
//   not vary around the ring).
#ifndef PFDM_PHANTOM_LV_TRUTH_H_
#define PFDM_PHANTOM_LV_TRUTH_H_

#include <string>
#include <vector>

#include "Eigen/Core"
#include "Eigen/Geometry"
#include "pfdm/phantom/lv_motion.h"
#include "pfdm/phantom/lv_shape.h"

namespace pfdm {

// 0.05, 0.10, ..., 1.00.
std::vector<double> LvRingHeights();

// A ring array's value at height fraction h: linear between the rings,
// extrapolated linearly from the two nearest below 0.05 (exact for the
// default design, linear in h), 0 <= h <= 1.
double LvRingValueAt(const std::vector<double>& values, double h);

struct LvLayerRings {  // One entry per LvRingHeights().
  std::vector<double> rotation_deg;
  std::vector<double> radial_contraction_percent;
};

struct LvSegmentTruth {
  int segment = 0;   // 1-16.
  std::string name;  // "basal 1" .. "apical 4", as report/wall_motion.
  double rotation_deg = 0.0;
  double radial_contraction_percent = 0.0;
  double wall_thickening_percent = 0.0;
};

// The AHA segment (0-based; a fit's segments hung on the phantom's RV
// insertion) of the phantom's basal or mid sector `phantom_segment`
// (0-based, as LvFrameTruth::segments), and back: the map is its own
// inverse.  Basal and mid sector k is AHA sector (2 - k) mod 6.
inline int LvAhaSegmentIndex(int phantom_segment) {
  const int level = phantom_segment < 6 ? 0 : 6;
  return level + ((2 - (phantom_segment - level)) % 6 + 6) % 6;
}

struct LvFrameTruth {
  int frame = 0;
  double progress = 0.0;  // Designed p.
  LvRigidMotion rigid;    // Designed, in body terms (lv_motion.h).
  Eigen::Isometry3d world_from_body = Eigen::Isometry3d::Identity();
  // Measured:
  double length_mm = 0.0;  // L
  double longitudinal_shortening_percent = 0.0;
  double apex_rotation_deg = 0.0;
  double base_rotation_deg = 0.0;
  double net_twist_deg = 0.0;
  double mean_radial_contraction_percent = 0.0;
  double volume_ml = 0.0;
  double endo_volume_ml = 0.0;
  double epi_volume_ml = 0.0;
  double myocardial_volume_ml = 0.0;
  LvLayerRings midwall, endo, epi;
  // Per LvRingHeights(), at the mid-wall ring's nu.
  std::vector<double> wall_thickening_percent;
  std::vector<LvSegmentTruth> segments;
  // Ids of the tags moved as outliers in this frame (LvPhantomOptions),
  // ascending.
  std::vector<int> outlier_ids;
};

// Lays out the material samples once; Measure() takes them moved to the
// world at frame 0 and at the frame measured.
class LvTruthMeter {
 public:
  explicit LvTruthMeter(const LvShape& shape);

  // ED body positions of every sample.
  const std::vector<Eigen::Vector3d>& material() const { return material_; }
  // Fills the measured fields; world0 and world are material() moved.
  LvFrameTruth Measure(const std::vector<Eigen::Vector3d>& world0,
                       const std::vector<Eigen::Vector3d>& world) const;

 private:
  struct Grid {  // A pole, then rows x cols points.
    int begin = 0, rows = 0, cols = 0;
  };
  void AddGrid(const LvShape& shape, double w, Grid* grid);

  std::vector<Eigen::Vector3d> material_;
  std::vector<int> ring_begin_[3];  // Endo, mid, epi.
  Grid surface_[3];
  int segment_begin_ = 0;
  // Transmural lines: per ring, kLinePoints (endo, epi) pairs; per segment
  // cell likewise, one pair.
  int line_begin_ = 0;
  int cell_line_begin_ = 0;
  std::vector<double> segment_weight_;
  std::vector<int> segment_of_;  // Per cell, 0-based.
};

}  // namespace pfdm

#endif  // PFDM_PHANTOM_LV_TRUTH_H_
