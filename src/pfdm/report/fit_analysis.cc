#include "pfdm/report/fit_analysis.h"

#include <algorithm>
#include <limits>

#include "pfdm/fit/stages/frame_verdict.h"
#include "pfdm/model/model_surface.h"
#include "pfdm/report/local_field_noise.h"
#include "pfdm/report/number_uncertainty.h"
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

// kNotMeasured in frame t's thickening of each third of the wall: only
// tracked tags through the wall place the layers inside it; contours lie
// on the walls, and the thirds then split the wall's thickening evenly
// (the LV phantom's slices: 42 % in each against 5, 41 and 85).
void LeaveOutFrameThirds(size_t t, FitAnalysis* analysis) {
  if (analysis->region_layers.empty()) return;
  for (RegionLayers& region : analysis->region_layers[t]) {
    for (LayerStrain& layer : region.layers) {
      layer.thickening_percent = kNotMeasured;
    }
  }
}

// Without data near the apex: the cap, and each level whose middle height
// (a fraction of frame 0's length from the apex pole; thirds, the apical
// one above the cap: wall_motion.h) lies below the lowest data point.
void FindExtrapolated(const SequenceFit& fit, const RegionLayout& layout,
                      FitAnalysis* analysis) {
  if (fit.apex_in_data) return;
  analysis->level_extrapolated[kApex] = true;
  const double middle[3] = {5.0 / 6.0, 0.5,
                            (layout.apex_cap_fraction + 1.0 / 3.0) / 2.0};
  for (int level : {kBasal, kMid, kApical}) {
    analysis->level_extrapolated[level] =
        fit.lowest_data_height > middle[level];
  }
  analysis->apex_ring_extrapolated =
      fit.lowest_data_height > kApicalRingFraction;
}

void LeaveOutLayers(RegionLayers* region) {
  region->err_percent = kNotMeasured;
  for (LayerStrain& layer : region->layers) {
    layer.ecc_percent = layer.ell_percent = layer.thickening_percent =
        kNotMeasured;
  }
}

void LeaveOutRegion(RegionMotion* motion) {
  for (double* value :
       {&motion->rotation_deg, &motion->radial_contraction_percent,
        &motion->ecc_percent, &motion->ell_percent, &motion->ecl_percent,
        &motion->thickening_percent}) {
    *value = kNotMeasured;
  }
}

// kNotMeasured in frame t's numbers measured where frame 0 has no data.
void LeaveOutExtrapolated(size_t t, FitAnalysis* analysis) {
  if (analysis->apex_ring_extrapolated) {
    LeaveOutApexRing(&analysis->clinical[t]);
  }
  for (size_t r = 0; r < analysis->regions.size(); ++r) {
    if (analysis->level_extrapolated[analysis->regions[r].level]) {
      LeaveOutRegion(&analysis->region_motion[t][r]);
      if (!analysis->region_layers.empty()) {
        LeaveOutLayers(&analysis->region_layers[t][r]);
      }
    }
  }
  for (int level : {kBasal, kMid, kApical}) {
    if (!analysis->level_extrapolated[level]) continue;
    analysis->strain[t].level_ecc_percent[level] = kNotMeasured;
    analysis->strain[t].level_ell_percent[level] = kNotMeasured;
  }
}

// Without data near the apex, the volumes, the mass and the ejection
// fraction take in the model's continuation below the data, whose place
// the apex convention holds (docs/gauge.md): their noise's interval would
// be that of a cap the data never saw (on a mid-ventricular segment of the
// LV phantom, EDV +-0.9 ml about an invented apex), so they have none.
void LeaveOutCapIntervals(FitAnalysis* analysis) {
  NumberSd& sd = analysis->sd;
  if (analysis->apex_cap_measured || !sd.computed) return;
  for (ClinicalSummary& frame : sd.clinical) {
    frame.volume_ml = frame.myocardial_volume_ml = frame.lv_mass_g =
        kNotMeasured;
  }
  sd.ejection_fraction.ratio = sd.ejection_fraction.edv_ml =
      sd.ejection_fraction.esv_ml = kNotMeasured;
}

// kNotMeasured in the volumes and the mass of each frame whose data span
// much less of the axis than frame 0's (its verdict's kShortSpanCode): the
// ventricle beyond them is not in the data.  On the LV phantom's three
// short-axis slices end-systole, which lost the basal one, read 137 ml
// against 83 (ejection fraction 0.18 against 0.59) while the length was
// held at frame 0's; with the length the data's, the model ends at the
// highest slice left, under the base, and the fraction reads 0.53 against
// 0.49 (LvPartialDataTest).
void LeaveOutVolumes(ClinicalSummary* c) {
  c->volume_ml = c->myocardial_volume_ml = c->lv_mass_g = kNotMeasured;
  c->material_myocardium_ml = c->myocardial_volume_change_percent =
      kNotMeasured;
}

void LeaveOutShortSpanVolumes(const SequenceFit& fit, FitAnalysis* analysis) {
  for (size_t t = 0; t < fit.frames.size(); ++t) {
    if (!fit.frames[t].verdict.Has(kShortSpanCode)) continue;
    analysis->volume_measured[t] = false;
    LeaveOutVolumes(&analysis->clinical[t]);
  }
}

// kNotMeasured in the walls' numbers of each frame that nothing places
// its walls in (its verdict's kWallsUnseenCode: mid-wall tags, no
// contours): its cavity, myocardium and mass, the wall's thickness and
// each wall's motion.
void LeaveOutUnseenWalls(const SequenceFit& fit, FitAnalysis* analysis) {
  for (size_t t = 0; t < fit.frames.size(); ++t) {
    if (!fit.frames[t].verdict.Has(kWallsUnseenCode)) continue;
    analysis->walls_measured[t] = false;
    ClinicalSummary& c = analysis->clinical[t];
    LeaveOutVolumes(&c);
    for (double* value :
         {&c.wall_thickness_mm, &c.wall_thickening_percent,
          &c.endo_radial_contraction_percent, &c.epi_radial_contraction_percent,
          &c.endo_apex_rotation_deg, &c.endo_base_rotation_deg,
          &c.endo_net_twist_deg, &c.epi_apex_rotation_deg,
          &c.epi_base_rotation_deg, &c.epi_net_twist_deg}) {
      *value = kNotMeasured;
    }
  }
}

// With frames whose walls nothing places (LeaveOutUnseenWalls) the least
// cavity of the others need not be end-systole's.  Their tags place the
// mid-wall, and the volume inside it is the cavity's and the inner half of
// the myocardium, which keeps its volume: its least frame is end-systole's,
// and the fraction is taken there where both its cavity and ED's are
// measured (contours at ED and ES, tags in every frame); else ES is still
// that frame and the fraction n/a.  A frame of short span has no mid-wall
// volume either.
void EndSystoleByMidwall(FitAnalysis* analysis) {
  const std::vector<bool>& walls = analysis->walls_measured;
  const std::vector<bool>& volume = analysis->volume_measured;
  if (std::find(walls.begin(), walls.end(), false) == walls.end() ||
      std::find(volume.begin(), volume.end(), false) != volume.end()) {
    return;
  }
  size_t es = 0;
  double least = std::numeric_limits<double>::infinity();
  for (size_t t = 0; t < analysis->models.size(); ++t) {
    const double midwall =
        CavityVolumeMl(analysis->models[t], VolumePlaneOf(*analysis, t), 0.0);
    if (midwall < least) {
      least = midwall;
      es = t;
    }
  }
  EjectionFraction& ef = analysis->ejection_fraction;
  ef.es_frame = analysis->clinical[es].frame;
  ef.es_by_midwall = true;
  ef.esv_ml = analysis->clinical[es].volume_ml;  // kNotMeasured if unseen.
  ef.ratio =
      ef.edv_ml > 0.0 ? (ef.edv_ml - ef.esv_ml) / ef.edv_ml : kNotMeasured;
}

// The same frames' segments' thickening and their layers' strains.
void LeaveOutUnseenRegions(const SequenceFit& fit, FitAnalysis* analysis) {
  for (size_t t = 0; t < fit.frames.size(); ++t) {
    if (analysis->walls_measured[t]) continue;
    for (RegionMotion& motion : analysis->region_motion[t]) {
      motion.thickening_percent = kNotMeasured;
    }
    if (analysis->region_layers.empty()) continue;
    for (RegionLayers& region : analysis->region_layers[t]) {
      LeaveOutLayers(&region);
    }
  }
}

// Whether frame t's contours end at fixed image planes (JudgeClinical's
// slab): untracked, with no data near the apex or the highest data one
// short-axis slice.  Tags are material points, whose myocardium is theirs.
bool EndsAtImagePlanes(const SequenceFit& fit, size_t t) {
  const FrameFit& frame = fit.frames[t];
  return !frame.tracked &&
         (!fit.apex_in_data || frame.verdict.Has(kTopSliceCode));
}

// Per frame, a solid's slice plane where its data end at one short-axis
// slice and no base plane closes it (FitAnalysis::slice_planes): the
// lowest wall's rim, which the fit put at the slice (RimLift); the other
// wall's rim lies above it, along the mid-wall's normal.  Closed by a flat
// lid at each wall's own rim, the cavity of both walls' short-axis contours
// read 1.7 ml under the endocardial contours' alone (noise-free LV phantom,
// ED; 1.8 at ES).  The phantom's tags end on a surface across the wall, as
// the walls' rims do, and keep the flat lids.
std::vector<std::optional<BasePlane>> SlicePlanes(
    const SequenceFit& fit, const std::vector<Model>& models, bool planes) {
  std::vector<std::optional<BasePlane>> slice(fit.frames.size());
  if (planes || !fit.config.Solid()) return slice;
  for (size_t t = 0; t < fit.frames.size(); ++t) {
    if (fit.frames[t].verdict.Has(kTopSliceCode)) {
      slice[t] = LowestRimPlane(models[t]);
    }
  }
  return slice;
}

// The volumes of the frames with a plane (VolumePlaneOf), closed there.
void CloseVolumesAtPlanes(bool solid, FitAnalysis* analysis) {
  for (size_t t = 0; t < analysis->models.size(); ++t) {
    const BasePlane* plane = VolumePlaneOf(*analysis, t);
    if (plane == nullptr) continue;
    ClinicalSummary& c = analysis->clinical[t];
    const Model& model = analysis->models[t];
    c.volume_ml = CavityVolumeMl(model, plane, solid ? -1.0 : 0.0);
    if (solid) {
      c.myocardial_volume_ml = CavityVolumeMl(model, plane, 1.0) - c.volume_ml;
      c.lv_mass_g = kMyocardialDensity * c.myocardial_volume_ml;
    }
  }
}

}  // namespace

const BasePlane* VolumePlaneOf(const FitAnalysis& analysis, size_t t) {
  if (!analysis.base_planes.empty()) return &analysis.base_planes[t];
  if (t < analysis.slice_planes.size() && analysis.slice_planes[t]) {
    return &*analysis.slice_planes[t];
  }
  return nullptr;
}

bool HasSlicePlanes(const FitAnalysis& analysis) {
  return std::any_of(
      analysis.slice_planes.begin(), analysis.slice_planes.end(),
      [](const std::optional<BasePlane>& plane) { return plane.has_value(); });
}

RingSpan ClinicalRingSpan(const SequenceFit& fit, bool show_extrapolated) {
  RingSpan span;
  if (fit.apex_in_data || show_extrapolated) return span;
  span.low = std::clamp(fit.lowest_data_height, 0.0, 1.0);
  span.high = std::clamp(fit.highest_data_height, span.low, 1.0);
  if (span.high - span.low < 0.05) return RingSpan();  // Too few data.
  return span;
}

FitAnalysis AnalyzeFit(const SequenceFit& fit,
                       const std::vector<BasePlane>& base_planes,
                       const RegionLayout& layout, bool show_extrapolated) {
  FitAnalysis analysis;
  for (size_t t = 0; t < fit.frames.size(); ++t) {
    analysis.models.push_back(fit.ModelAt(static_cast<int>(t)));
  }
  const int ed = fit.ed_frame;
  analysis.ring_span = ClinicalRingSpan(fit, show_extrapolated);
  const bool planes = base_planes.size() == fit.frames.size();
  if (planes) analysis.base_planes = base_planes;
  analysis.slice_planes = SlicePlanes(fit, analysis.models, planes);
  // With a plane for every frame the volumes are closed there (below), and
  // the flat lids' are not measured: a third of the analysis's volumes.
  bool every_frame_planed = true;
  for (size_t t = 0; t < fit.frames.size(); ++t) {
    every_frame_planed =
        every_frame_planed && VolumePlaneOf(analysis, t) != nullptr;
  }
  analysis.clinical = SummarizeSequence(analysis.models, ed, analysis.ring_span,
                                        !every_frame_planed);
  if (fit.time_ms.size() == fit.frames.size()) {
    for (size_t t = 0; t < fit.frames.size(); ++t) {
      analysis.clinical[t].time_ms = fit.time_ms[t];
    }
  }
  analysis.volume_surface = VolumeSurfaceName(fit);
  analysis.interval_data = IntervalDataOf(fit);
  analysis.regional_limit = RegionalLimitOf(fit);
  CloseVolumesAtPlanes(fit.config.Solid(), &analysis);
  analysis.volume_measured.assign(fit.frames.size(), true);
  analysis.walls_measured.assign(fit.frames.size(), true);
  if (!show_extrapolated) LeaveOutShortSpanVolumes(fit, &analysis);
  LeaveOutUnseenWalls(fit, &analysis);
  analysis.ejection_fraction = EjectionFractionOf(analysis.clinical, ed);
  EndSystoleByMidwall(&analysis);
  for (size_t t = 0; t < fit.frames.size(); ++t) {
    analysis.verdicts.push_back(fit.frames[t].verdict);
    analysis.verdicts.back().Add(
        JudgeClinical(analysis.clinical, analysis.ejection_fraction,
                      analysis.volume_surface, t, EndsAtImagePlanes(fit, t)));
  }
  analysis.layout = layout;
  analysis.regions = Regions(layout);
  const ReferenceSamples reference =
      SampleReference(analysis.models.at(ed), layout);
  const LayerSamples layers = SampleLayers(analysis.models.at(ed), layout);
  for (const Model& model : analysis.models) {
    analysis.region_motion.push_back(SummarizeRegions(reference, model));
    analysis.strain.push_back(
        SummarizeStrain(analysis.regions, analysis.region_motion.back()));
    if (!layers.samples.empty()) {
      analysis.region_layers.push_back(SummarizeLayers(layers, model));
    }
  }
  analysis.rotation_measured = RotationMeasured(fit);
  for (size_t t = 0; t < fit.frames.size(); ++t) {
    if (analysis.rotation_measured[t]) continue;
    LeaveOutFrameRotation(t, &analysis);
    LeaveOutFrameThirds(t, &analysis);
  }
  FindExtrapolated(fit, layout, &analysis);
  analysis.extrapolated_shown = show_extrapolated;
  for (size_t t = 0; t < fit.frames.size() && !show_extrapolated; ++t) {
    LeaveOutExtrapolated(t, &analysis);
  }
  LeaveOutUnseenRegions(fit, &analysis);
  // The levels' strain, above, keeps the cap as part of the apical third.
  analysis.apex_cap_measured = fit.apex_in_data || show_extrapolated;
  analysis.dyssynchrony = MeasureDyssynchrony(
      analysis.regions, analysis.region_motion,
      fit.time_ms.size() == fit.frames.size() ? fit.time_ms
                                              : std::vector<double>(),
      ed);
  analysis.sd = PropagateUncertainty(fit, analysis);
  analysis.noise_bias = AddLocalFieldNoise(fit, analysis, &analysis.sd);
  LeaveOutCapIntervals(&analysis);
  return analysis;
}

}  // namespace pfdm
