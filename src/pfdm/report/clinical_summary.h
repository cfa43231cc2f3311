// The numbers a cardiologist reads off a fit: twist and contraction.
#ifndef PFDM_REPORT_CLINICAL_SUMMARY_H_
#define PFDM_REPORT_CLINICAL_SUMMARY_H_

#include <cmath>
#include <limits>
#include <vector>

#include "pfdm/model/model.h"
#include "pfdm/report/reference_rings.h"

namespace pfdm {

// A number the data cannot determine, "n/a" in the outputs (null in
// fit.json): NaN, so that nothing can read it as a measurement.
inline constexpr double kNotMeasured = std::numeric_limits<double>::quiet_NaN();
inline bool Measured(double value) { return !std::isnan(value); }

// Where the summary's rings sit: height fractions of frame 0's length from
// the apex pole (0) to the base rim (1), in the apical and basal thirds and
// clear of the apex cap and the rim, where tags are sparse.
constexpr double kApicalRingFraction = 0.2;
constexpr double kBasalRingFraction = 0.85;
// Radial contraction is the mean over rings at h = 0.05, 0.15, ..., 0.95
// (of a RingSpan: evenly spaced within it likewise).
constexpr int kContractionRings = 10;

// The height fractions (of frame 0's apex-to-rim length) the ring means
// (radial contraction of each layer, thickness, thickening) are taken over:
// the whole length, or where frame 0 has data.  A mid-ventricular segment
// (no apex) fills only the model's upper half or less; over the whole
// length the means took in rings the fit only extrapolates, whose walls
// follow no data (thickening 58 % against 34 % on a cylindrical segment,
// docs/gauge.md "Rings without data").
struct RingSpan {
  double low = 0.0, high = 1.0;
  double At(int i) const {
    return low + (high - low) * (i + 0.5) / kContractionRings;
  }
};
// Myocardial density, g/ml, for the LV mass.
constexpr double kMyocardialDensity = 1.05;

// Every number but the per-knot ratios is measured on the fitted model's
// material points (world coordinates) against frame 0's, so it means the
// same whatever share of the motion the pose, a3, bending or the offsets
// carry (report/material_rings.h).
struct ClinicalSummary {
  int frame = 0;
  // From the trigger, when the input gave it (PointSequence::time_ms).
  double time_ms = kNotMeasured;
  // Rotation of the apical and basal material rings (kApicalRingFraction,
  // kBasalRingFraction) about frame 0's long axis, degrees, right-handed
  // about the apex-to-base axis: seen from the apex a normal apex turns
  // counter-clockwise, i.e. apex rotation < 0.  The mean turn of the ring's
  // points about its centroid.
  double apex_rotation_deg = 0.0;
  double base_rotation_deg = 0.0;
  double net_twist_deg = 0.0;  // base minus apex: about +10..15 at normal ES.
  // Net twist over frame 0's distance between the two rings' centroids.
  double torsion_deg_per_cm = 0.0;
  // Circumferential-longitudinal shear angle on frame 0's geometry:
  // atan(net twist (rad) (r_apex + r_base) / (2 D)), r the rings' mean
  // radii and D their distance.
  double shear_angle_deg = 0.0;
  // Per knot, a1, a2, a3 relative to frame 0 (the paper's Fig. 5).
  std::vector<double> radial_ratio_x;
  std::vector<double> radial_ratio_y;
  std::vector<double> longitudinal_ratio;
  // Mean over kContractionRings rings of 1 - r / r0, percent, r the mean
  // distance of a ring's material points from their centroid.
  double radial_contraction_percent = 0.0;
  // 1 - L / L0, percent, L the distance from the apex pole's material point
  // to the centroid of the base rim's material points.
  double longitudinal_shortening_percent = 0.0;
  // Inside the fitted surface closed at the base rim (CavityVolumeMl): the
  // cavity (the endocardium, w = -1) of a solid; of a single surface,
  // whatever its data are (SequenceFit::surface).
  double volume_ml = 0.0;

  // A solid's walls (model/transmural.h); all zero for a single surface.
  // Each wall's rings sit on the same frame-0 short-axis planes as the
  // mid-wall rings above (RingAtHeightFraction with w), measured likewise.
  bool solid = false;
  double endo_apex_rotation_deg = 0.0;
  double endo_base_rotation_deg = 0.0;
  double endo_net_twist_deg = 0.0;
  double epi_apex_rotation_deg = 0.0;
  double epi_base_rotation_deg = 0.0;
  double epi_net_twist_deg = 0.0;
  double endo_radial_contraction_percent = 0.0;
  double epi_radial_contraction_percent = 0.0;
  // Wall thickness (material_rings.h WallThickness), mean over the
  // kContractionRings mid-wall rings; thickening the mean of 100 (T / T0 -
  // 1) per ring, T0 frame 0's.
  double wall_thickness_mm = 0.0;
  double wall_thickening_percent = 0.0;
  // Between the epicardium and the endocardium, each closed at the base
  // rim; mass at kMyocardialDensity.
  double myocardial_volume_ml = 0.0;
  double lv_mass_g = 0.0;
  // The myocardium as material (material_myocardium.h): the wall between
  // the reference's mid-wall rings at the span's ends (the whole length,
  // or where frame 0 has data), ml, and its change from the reference's
  // (end-diastole), percent: what incompressibility keeps near zero, where
  // myocardial_volume_ml takes in the rim's motion across the base plane.
  double material_myocardium_ml = 0.0;
  double myocardial_volume_change_percent = 0.0;
};

// (EDV - ESV) / EDV with end-diastole the frame given (--ed_frame, frame 0
// unless said: the fit starts at ED, as tagged sequences do) and
// end-systole the frame of least volume.  When a frame has no volume
// (kNotMeasured), ESV and the ratio have none either, and es_frame is the
// least volume's of the frames that have one.
struct EjectionFraction {
  int ed_frame = 0;
  int es_frame = 0;
  double edv_ml = 0.0;
  double esv_ml = 0.0;
  double ratio = 0.0;
  // End-systole found by the volume inside the mid-wall, which the tags
  // place in every frame, where frames have no cavity (walls_unseen):
  // fit_analysis.h, EndSystoleByMidwall.
  bool es_by_midwall = false;
};

// Sets what only a turn about the axis measures to kNotMeasured: every
// rotation, twist, the torsion and the shear angle, of the mid-wall and of
// a solid's walls.
void LeaveOutRotation(ClinicalSummary* summary);

// Sets what the apical ring (kApicalRingFraction) measures to
// kNotMeasured: its rotations, the net twists, the torsion and the shear
// angle; the base ring's rotations stay.
void LeaveOutApexRing(ClinicalSummary* summary);

// reference is frame 0's model, current the frame's; flat_lid_volumes as
// SummarizeSequence's.
ClinicalSummary SummarizeFrame(int frame, const Model& reference,
                               const Model& current,
                               const RingSpan& span = RingSpan(),
                               bool flat_lid_volumes = true);

// The same with the reference's rings kept from one call to the next.
ClinicalSummary SummarizeFrame(int frame, ReferenceRings& rings,
                               const Model& current, const RingSpan& span,
                               bool flat_lid_volumes);

// SummarizeFrame of every frame against frames[reference] (end-diastole).
// Without flat_lid_volumes the volumes closed by a flat lid (volume_ml and,
// of a solid, myocardial_volume_ml and lv_mass_g) are left at their
// defaults, for a caller that closes them at the base planes instead.
std::vector<ClinicalSummary> SummarizeSequence(
    const std::vector<Model>& frames, int reference = 0,
    const RingSpan& span = RingSpan(), bool flat_lid_volumes = true);

// From the summaries' volumes, ED at summaries[ed_frame]; all zero for an
// empty list or an ed_frame outside it.
EjectionFraction EjectionFractionOf(
    const std::vector<ClinicalSummary>& summaries, int ed_frame = 0);

}  // namespace pfdm

#endif  // PFDM_REPORT_CLINICAL_SUMMARY_H_
