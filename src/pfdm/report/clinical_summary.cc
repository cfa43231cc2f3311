#include "pfdm/report/clinical_summary.h"

#include <cmath>

#include "pfdm/model/model_surface.h"
#include "pfdm/report/material_rings.h"

namespace pfdm {
namespace {

constexpr double kDegreesPerRadian = 180.0 / 3.14159265358979323846;

double ApexToBaseRim(const Model& model) {
  const Eigen::Vector3d apex = model.WorldPoint(model.config.u_min, 0.0);
  return (SampleRing(model, model.config.u_max).centroid - apex).norm();
}

}  // namespace

ClinicalSummary SummarizeFrame(int frame, const Model& reference,
                               const Model& current) {
  const KnotGrid grid = current.config.Grid();
  const Eigen::Vector3d axis = LongAxis(reference);
  ClinicalSummary summary;
  summary.frame = frame;

  const double u_apex = RingAtHeightFraction(reference, kApicalRingFraction);
  const double u_base = RingAtHeightFraction(reference, kBasalRingFraction);
  const MaterialRing apex0 = SampleRing(reference, u_apex);
  const MaterialRing base0 = SampleRing(reference, u_base);
  summary.apex_rotation_deg =
      MeanRotation(apex0, SampleRing(current, u_apex), axis) *
      kDegreesPerRadian;
  summary.base_rotation_deg =
      MeanRotation(base0, SampleRing(current, u_base), axis) *
      kDegreesPerRadian;
  summary.net_twist_deg = summary.base_rotation_deg - summary.apex_rotation_deg;
  const double distance_mm = (base0.centroid - apex0.centroid).norm();
  summary.torsion_deg_per_cm = summary.net_twist_deg / (0.1 * distance_mm);
  summary.shear_angle_deg =
      std::atan(summary.net_twist_deg / kDegreesPerRadian *
                (MeanRadius(apex0) + MeanRadius(base0)) / (2.0 * distance_mm)) *
      kDegreesPerRadian;

  for (int k = 0; k < grid.num_knots(); ++k) {
    const double u = grid.KnotU(k);
    auto ratio = [&](int f) {
      return current.FunctionAt(f, u) / reference.FunctionAt(f, u);
    };
    summary.radial_ratio_x.push_back(ratio(kA1));
    summary.radial_ratio_y.push_back(ratio(kA2));
    summary.longitudinal_ratio.push_back(ratio(kA3));
  }
  for (int i = 0; i < kContractionRings; ++i) {
    const double u =
        RingAtHeightFraction(reference, (i + 0.5) / kContractionRings);
    summary.radial_contraction_percent +=
        100.0 *
        (1.0 - MeanRadius(SampleRing(current, u)) /
                   MeanRadius(SampleRing(reference, u))) /
        kContractionRings;
  }
  summary.longitudinal_shortening_percent =
      100.0 * (1.0 - ApexToBaseRim(current) / ApexToBaseRim(reference));
  summary.volume_ml = CavityVolumeMl(current);
  return summary;
}

std::vector<ClinicalSummary> SummarizeSequence(
    const std::vector<Model>& frames) {
  std::vector<ClinicalSummary> summaries;
  for (size_t t = 0; t < frames.size(); ++t) {
    summaries.push_back(
        SummarizeFrame(static_cast<int>(t), frames.front(), frames[t]));
  }
  return summaries;
}

EjectionFraction EjectionFractionOf(
    const std::vector<ClinicalSummary>& summaries) {
  EjectionFraction ef;
  if (summaries.empty()) return ef;
  ef.ed_frame = summaries.front().frame;
  ef.edv_ml = summaries.front().volume_ml;
  ef.es_frame = ef.ed_frame;
  ef.esv_ml = ef.edv_ml;
  for (const ClinicalSummary& s : summaries) {
    if (s.volume_ml < ef.esv_ml) {
      ef.es_frame = s.frame;
      ef.esv_ml = s.volume_ml;
    }
  }
  if (ef.edv_ml > 0.0) ef.ratio = (ef.edv_ml - ef.esv_ml) / ef.edv_ml;
  return ef;
}

}  // namespace pfdm
