#include "pfdm/report/clinical_summary.h"

#include <cmath>

#include "pfdm/model/model_surface.h"
#include "pfdm/report/material_rings.h"

namespace pfdm {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDegreesPerRadian = 180.0 / kPi;

double ApexToBaseRim(const Model& model) {
  const Eigen::Vector3d apex = model.WorldPoint(model.config.u_min, 0.0);
  return (SampleRing(model, model.config.u_max).centroid - apex).norm();
}

// Rotation (degrees) of surface w's ring at height fraction h.
double RingRotationDeg(const Model& reference, const Model& current, double h,
                       double w) {
  const double u = RingAtHeightFraction(reference, h, w);
  return MeanRotation(SampleRing(reference, u, kRingSamples, w),
                      SampleRing(current, u, kRingSamples, w),
                      LongAxis(reference)) *
         kDegreesPerRadian;
}

// Mean over the contraction rings of 1 - r / r0 on surface w, percent.
double RadialContractionPercent(const Model& reference, const Model& current,
                                double w) {
  double percent = 0.0;
  for (int i = 0; i < kContractionRings; ++i) {
    const double u =
        RingAtHeightFraction(reference, (i + 0.5) / kContractionRings, w);
    percent +=
        100.0 *
        (1.0 - MeanRadius(SampleRing(current, u, kRingSamples, w)) /
                   MeanRadius(SampleRing(reference, u, kRingSamples, w))) /
        kContractionRings;
  }
  return percent;
}

// Mean wall thickness (mm) around the material ring at u.
double RingThickness(const Model& model, double u) {
  double sum = 0.0;
  for (int j = 0; j < kRingSamples; ++j) {
    sum += WallThickness(model, u, -kPi + 2.0 * kPi * (j + 0.5) / kRingSamples);
  }
  return sum / kRingSamples;
}

void SummarizeWall(const Model& reference, const Model& current,
                   ClinicalSummary* summary) {
  summary->solid = true;
  summary->endo_apex_rotation_deg =
      RingRotationDeg(reference, current, kApicalRingFraction, -1.0);
  summary->endo_base_rotation_deg =
      RingRotationDeg(reference, current, kBasalRingFraction, -1.0);
  summary->endo_net_twist_deg =
      summary->endo_base_rotation_deg - summary->endo_apex_rotation_deg;
  summary->epi_apex_rotation_deg =
      RingRotationDeg(reference, current, kApicalRingFraction, 1.0);
  summary->epi_base_rotation_deg =
      RingRotationDeg(reference, current, kBasalRingFraction, 1.0);
  summary->epi_net_twist_deg =
      summary->epi_base_rotation_deg - summary->epi_apex_rotation_deg;
  summary->endo_radial_contraction_percent =
      RadialContractionPercent(reference, current, -1.0);
  summary->epi_radial_contraction_percent =
      RadialContractionPercent(reference, current, 1.0);
  double thickness = 0.0, thickening = 0.0;
  for (int i = 0; i < kContractionRings; ++i) {
    const double u =
        RingAtHeightFraction(reference, (i + 0.5) / kContractionRings);
    const double now = RingThickness(current, u);
    thickness += now / kContractionRings;
    thickening +=
        100.0 * (now / RingThickness(reference, u) - 1.0) / kContractionRings;
  }
  summary->wall_thickness_mm = thickness;
  summary->wall_thickening_percent = thickening;
  summary->volume_ml = CavityVolumeMl(current, nullptr, -1.0);
  summary->myocardial_volume_ml =
      CavityVolumeMl(current, nullptr, 1.0) - summary->volume_ml;
  summary->lv_mass_g = kMyocardialDensity * summary->myocardial_volume_ml;
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
  summary.radial_contraction_percent =
      RadialContractionPercent(reference, current, 0.0);
  summary.longitudinal_shortening_percent =
      100.0 * (1.0 - ApexToBaseRim(current) / ApexToBaseRim(reference));
  if (current.config.Solid()) {
    SummarizeWall(reference, current, &summary);
  } else {
    summary.volume_ml = CavityVolumeMl(current);
  }
  return summary;
}

void LeaveOutRotation(ClinicalSummary* summary) {
  for (double* value :
       {&summary->apex_rotation_deg, &summary->base_rotation_deg,
        &summary->net_twist_deg, &summary->torsion_deg_per_cm,
        &summary->shear_angle_deg, &summary->endo_apex_rotation_deg,
        &summary->endo_base_rotation_deg, &summary->endo_net_twist_deg,
        &summary->epi_apex_rotation_deg, &summary->epi_base_rotation_deg,
        &summary->epi_net_twist_deg}) {
    *value = kNotMeasured;
  }
}

void LeaveOutApexRing(ClinicalSummary* summary) {
  for (double* value :
       {&summary->apex_rotation_deg, &summary->net_twist_deg,
        &summary->torsion_deg_per_cm, &summary->shear_angle_deg,
        &summary->endo_apex_rotation_deg, &summary->endo_net_twist_deg,
        &summary->epi_apex_rotation_deg, &summary->epi_net_twist_deg}) {
    *value = kNotMeasured;
  }
}

std::vector<ClinicalSummary> SummarizeSequence(const std::vector<Model>& frames,
                                               int reference) {
  std::vector<ClinicalSummary> summaries;
  for (size_t t = 0; t < frames.size(); ++t) {
    summaries.push_back(
        SummarizeFrame(static_cast<int>(t), frames.at(reference), frames[t]));
  }
  return summaries;
}

EjectionFraction EjectionFractionOf(
    const std::vector<ClinicalSummary>& summaries, int ed_frame) {
  EjectionFraction ef;
  if (ed_frame < 0 || static_cast<size_t>(ed_frame) >= summaries.size()) {
    return ef;
  }
  ef.ed_frame = summaries[ed_frame].frame;
  ef.edv_ml = summaries[ed_frame].volume_ml;
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
