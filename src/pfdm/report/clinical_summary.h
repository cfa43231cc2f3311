// The numbers a cardiologist reads off a fit: twist and contraction.
#ifndef PFDM_REPORT_CLINICAL_SUMMARY_H_
#define PFDM_REPORT_CLINICAL_SUMMARY_H_

#include <vector>

#include "pfdm/model/model.h"

namespace pfdm {

struct ClinicalSummary {
  int frame = 0;
  // tau at the most apical ring (the first knot with a non-zero radius) and
  // at the base, in degrees, right-handed about the apex-to-base axis: seen
  // from the apex a normal apex turns counter-clockwise, i.e. tau < 0.
  double apex_rotation_deg = 0.0;
  double base_rotation_deg = 0.0;
  double net_twist_deg = 0.0;  // base minus apex: about +10..15 at normal ES.
  // Per knot, a1, a2, a3 relative to frame 0.
  std::vector<double> radial_ratio_x;
  std::vector<double> radial_ratio_y;
  std::vector<double> longitudinal_ratio;
  // Means over the knots with a non-zero radius of 1 - ratio, in percent.
  double radial_contraction_x_percent = 0.0;
  double radial_contraction_y_percent = 0.0;
  // 1 - L / L0 with L the axial distance from apex to base-ring centre.
  double longitudinal_shortening_percent = 0.0;
  // The cavity closed at the base rim (CavityVolumeMl).
  double volume_ml = 0.0;
};

// (EDV - ESV) / EDV with end-diastole the first frame and end-systole the
// frame of least volume: the fit starts at ED, as tagged sequences do.
struct EjectionFraction {
  int ed_frame = 0;
  int es_frame = 0;
  double edv_ml = 0.0;
  double esv_ml = 0.0;
  double ratio = 0.0;
};

// reference is frame 0's model, current the frame's.
ClinicalSummary SummarizeFrame(int frame, const Model& reference,
                               const Model& current);

// SummarizeFrame of every frame against frames[0].
std::vector<ClinicalSummary> SummarizeSequence(
    const std::vector<Model>& frames);

// From the summaries' volumes; all zero for an empty list.
EjectionFraction EjectionFractionOf(
    const std::vector<ClinicalSummary>& summaries);

// Index of the first knot whose ring has a non-zero radius.
int ApicalKnot(const ModelConfig& config);

}  // namespace pfdm

#endif  // PFDM_REPORT_CLINICAL_SUMMARY_H_
