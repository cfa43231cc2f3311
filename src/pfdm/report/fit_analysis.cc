#include "pfdm/report/fit_analysis.h"

#include "pfdm/model/model_surface.h"
#include "pfdm/report/plausibility.h"

namespace pfdm {

std::string VolumeSurfaceName(const SequenceFit& fit) {
  if (fit.config.Solid() || fit.surface == WallLayer::kEndocardium) {
    return "cavity";
  }
  return fit.surface == WallLayer::kEpicardium ? "epicardial" : "midwall";
}

std::vector<bool> RotationMeasured(const SequenceFit& fit) {
  std::vector<bool> measured;
  for (const FrameFit& frame : fit.frames) {
    measured.push_back(fit.frames.front().tracked && frame.tracked);
  }
  return measured;
}

namespace {

// kNotMeasured in every number of frame t that a turn about the axis makes.
void LeaveOutFrameRotation(size_t t, FitAnalysis* analysis) {
  LeaveOutRotation(&analysis->clinical[t]);
  for (RegionMotion& motion : analysis->region_motion[t]) {
    motion.rotation_deg = kNotMeasured;
    motion.ecl_percent = kNotMeasured;
  }
  analysis->strain[t].gcl_percent = kNotMeasured;
}

// kNotMeasured in every number of the apex cap (segment 17), the
// model's continuation below the data when they do not reach the apex.
void LeaveOutApexCap(FitAnalysis* analysis) {
  for (size_t r = 0; r < analysis->regions.size(); ++r) {
    if (analysis->regions[r].level != kApex) continue;
    for (std::vector<RegionMotion>& frame : analysis->region_motion) {
      const double area = frame[r].area_mm2;
      frame[r] = {kNotMeasured, kNotMeasured, kNotMeasured, kNotMeasured,
                  kNotMeasured, kNotMeasured, area};
    }
  }
}

}  // namespace

FitAnalysis AnalyzeFit(const SequenceFit& fit,
                       const std::vector<BasePlane>& base_planes,
                       const RegionLayout& layout) {
  FitAnalysis analysis;
  for (size_t t = 0; t < fit.frames.size(); ++t) {
    analysis.models.push_back(fit.ModelAt(static_cast<int>(t)));
  }
  analysis.clinical = SummarizeSequence(analysis.models);
  analysis.volume_surface = VolumeSurfaceName(fit);
  if (base_planes.size() == fit.frames.size()) {
    analysis.base_planes = base_planes;
    const bool solid = fit.config.Solid();
    for (size_t t = 0; t < fit.frames.size(); ++t) {
      ClinicalSummary& c = analysis.clinical[t];
      const Model& model = analysis.models[t];
      c.volume_ml = CavityVolumeMl(model, &base_planes[t], solid ? -1.0 : 0.0);
      if (solid) {
        c.myocardial_volume_ml =
            CavityVolumeMl(model, &base_planes[t], 1.0) - c.volume_ml;
        c.lv_mass_g = kMyocardialDensity * c.myocardial_volume_ml;
      }
    }
  }
  analysis.ejection_fraction = EjectionFractionOf(analysis.clinical);
  for (size_t t = 0; t < fit.frames.size(); ++t) {
    analysis.verdicts.push_back(fit.frames[t].verdict);
    analysis.verdicts.back().Add(JudgeClinical(analysis.clinical,
                                               analysis.ejection_fraction,
                                               analysis.volume_surface, t));
  }
  analysis.layout = layout;
  analysis.regions = Regions(layout);
  const ReferenceSamples reference =
      SampleReference(analysis.models.front(), layout);
  for (const Model& model : analysis.models) {
    analysis.region_motion.push_back(SummarizeRegions(reference, model));
    analysis.strain.push_back(
        SummarizeStrain(analysis.regions, analysis.region_motion.back()));
  }
  // After the levels' strain, which keeps the cap as the apical third.
  analysis.apex_cap_measured = fit.apex_in_data;
  if (!fit.apex_in_data) LeaveOutApexCap(&analysis);
  analysis.rotation_measured = RotationMeasured(fit);
  for (size_t t = 0; t < fit.frames.size(); ++t) {
    if (!analysis.rotation_measured[t]) LeaveOutFrameRotation(t, &analysis);
  }
  return analysis;
}

}  // namespace pfdm
