#include "pfdm/report/clinical_summary.h"

#include <cmath>

#include "pfdm/model/model_surface.h"
#include "pfdm/report/material_myocardium.h"
#include "pfdm/report/material_rings.h"
#include "pfdm/report/reference_rings.h"
#include "pfdm/util/angles.h"

namespace pfdm {
namespace {

double ApexToBaseRim(const Model& model, const MaterialRing& rim) {
  const Eigen::Vector3d apex = model.WorldPoint(model.config.u_min, 0.0);
  return (rim.centroid - apex).norm();
}

double ApexToBaseRim(const Model& model) {
  return ApexToBaseRim(model, SampleRing(model, model.config.u_max));
}

// Rotation (degrees) of surface w's ring at height fraction h.
double RingRotationDeg(ReferenceRings& rings, const Model& current, double h,
                       double w) {
  const Model& reference = rings.model();
  const double u = rings.At(h, w);
  return MeanRotation(rings.Ring(u, kRingSamples, w),
                      SampleRing(current, u, kRingSamples, w),
                      LongAxis(reference)) *
         kDegreesPerRadian;
}

// Mean over the contraction rings of 1 - r / r0 on surface w, percent.
double RadialContractionPercent(ReferenceRings& rings, const Model& current,
                                double w, const RingSpan& span) {
  double percent = 0.0;
  for (int i = 0; i < kContractionRings; ++i) {
    const double u = rings.At(span.At(i), w);
    percent += 100.0 *
               (1.0 - MeanRadius(SampleRing(current, u, kRingSamples, w)) /
                          MeanRadius(rings.Ring(u, kRingSamples, w))) /
               kContractionRings;
  }
  return percent;
}

void SummarizeWall(ReferenceRings& rings, const Model& current,
                   const RingSpan& span, bool flat_lid_volumes,
                   ClinicalSummary* summary) {
  summary->solid = true;
  summary->endo_apex_rotation_deg =
      RingRotationDeg(rings, current, kApicalRingFraction, -1.0);
  summary->endo_base_rotation_deg =
      RingRotationDeg(rings, current, kBasalRingFraction, -1.0);
  summary->endo_net_twist_deg =
      summary->endo_base_rotation_deg - summary->endo_apex_rotation_deg;
  summary->epi_apex_rotation_deg =
      RingRotationDeg(rings, current, kApicalRingFraction, 1.0);
  summary->epi_base_rotation_deg =
      RingRotationDeg(rings, current, kBasalRingFraction, 1.0);
  summary->epi_net_twist_deg =
      summary->epi_base_rotation_deg - summary->epi_apex_rotation_deg;
  summary->endo_radial_contraction_percent =
      RadialContractionPercent(rings, current, -1.0, span);
  summary->epi_radial_contraction_percent =
      RadialContractionPercent(rings, current, 1.0, span);
  double thickness = 0.0, thickening = 0.0;
  for (int i = 0; i < kContractionRings; ++i) {
    const double u = rings.At(span.At(i));
    const double now = MeanWallThickness(current, u);
    thickness += now / kContractionRings;
    thickening += 100.0 * (now / rings.Thickness(u) - 1.0) / kContractionRings;
  }
  summary->wall_thickness_mm = thickness;
  summary->wall_thickening_percent = thickening;
  if (flat_lid_volumes) {
    summary->volume_ml = CavityVolumeMl(current, nullptr, -1.0);
    summary->myocardial_volume_ml =
        CavityVolumeMl(current, nullptr, 1.0) - summary->volume_ml;
    summary->lv_mass_g = kMyocardialDensity * summary->myocardial_volume_ml;
  }
  const double u_low = rings.At(span.low);
  const double u_high = rings.At(span.high);
  summary->material_myocardium_ml =
      MaterialMyocardiumMl(current, u_low, u_high);
  summary->myocardial_volume_change_percent =
      100.0 *
      (summary->material_myocardium_ml / rings.MyocardiumMl(u_low, u_high) -
       1.0);
}

ClinicalSummary Summarize(int frame, ReferenceRings& rings,
                          const Model& current, const RingSpan& span,
                          bool flat_lid_volumes) {
  const Model& reference = rings.model();
  const KnotGrid grid = current.config.Grid();
  const Eigen::Vector3d axis = LongAxis(reference);
  ClinicalSummary summary;
  summary.frame = frame;

  const double u_apex = rings.At(kApicalRingFraction);
  const double u_base = rings.At(kBasalRingFraction);
  const MaterialRing& apex0 = rings.Ring(u_apex);
  const MaterialRing& base0 = rings.Ring(u_base);
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
      RadialContractionPercent(rings, current, 0.0, span);
  summary.longitudinal_shortening_percent =
      100.0 *
      (1.0 - ApexToBaseRim(current) /
                 ApexToBaseRim(reference, rings.Ring(reference.config.u_max)));
  if (current.config.Solid()) {
    SummarizeWall(rings, current, span, flat_lid_volumes, &summary);
  } else if (flat_lid_volumes) {
    summary.volume_ml = CavityVolumeMl(current);
  }
  return summary;
}

}  // namespace

ClinicalSummary SummarizeFrame(int frame, const Model& reference,
                               const Model& current, const RingSpan& span,
                               bool flat_lid_volumes) {
  ReferenceRings rings(reference);
  return Summarize(frame, rings, current, span, flat_lid_volumes);
}

ClinicalSummary SummarizeFrame(int frame, ReferenceRings& rings,
                               const Model& current, const RingSpan& span,
                               bool flat_lid_volumes) {
  return Summarize(frame, rings, current, span, flat_lid_volumes);
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
                                               int reference,
                                               const RingSpan& span,
                                               bool flat_lid_volumes) {
  ReferenceRings rings(frames.at(reference));
  std::vector<ClinicalSummary> summaries;
  for (size_t t = 0; t < frames.size(); ++t) {
    summaries.push_back(Summarize(static_cast<int>(t), rings, frames[t], span,
                                  flat_lid_volumes));
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
  bool every_volume = true;
  for (const ClinicalSummary& s : summaries) {
    every_volume = every_volume && Measured(s.volume_ml);
    if (s.volume_ml < ef.esv_ml) {
      ef.es_frame = s.frame;
      ef.esv_ml = s.volume_ml;
    }
  }
  if (!every_volume) {
    // The frame without a volume may be end-systole's: the least of the
    // others would read a smaller ejection fraction than the heart's.
    ef.esv_ml = ef.ratio = kNotMeasured;
  } else if (ef.edv_ml > 0.0) {
    ef.ratio = (ef.edv_ml - ef.esv_ml) / ef.edv_ml;
  }
  return ef;
}

}  // namespace pfdm
