// Everything derived from a fitted sequence that the outputs report.
#ifndef PFDM_REPORT_FIT_ANALYSIS_H_
#define PFDM_REPORT_FIT_ANALYSIS_H_

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "pfdm/fit/stages/sequence_fit.h"
#include "pfdm/model/base_plane.h"
#include "pfdm/model/model.h"
#include "pfdm/report/clinical_summary.h"
#include "pfdm/report/global_strain.h"
#include "pfdm/report/interval_calibration.h"
#include "pfdm/report/layer_strain.h"
#include "pfdm/report/number_sd.h"
#include "pfdm/report/regional_limit.h"
#include "pfdm/report/segment_timing.h"
#include "pfdm/report/wall_motion.h"
#include "pfdm/segmentation/segmentation_record.h"
#include "pfdm/util/verdict.h"

namespace pfdm {

struct FitAnalysis {
  std::vector<Model> models;           // Per frame.
  std::vector<BasePlane> base_planes;  // Empty: flat lid at the rim.
  // Without base planes, per frame of a solid whose data end at one
  // short-axis slice (the verdict's top_slice): the plane of the lowest
  // wall's rim, which the fit put at that slice, where both walls' volumes
  // end (LowestRimPlane); empty elsewhere.  VolumePlaneOf picks the plane.
  std::vector<std::optional<BasePlane>> slice_planes;
  std::vector<ClinicalSummary> clinical;  // Per frame, against frame 0.
  EjectionFraction ejection_fraction;
  RegionLayout layout;
  std::vector<WallRegion> regions;
  std::vector<std::vector<RegionMotion>> region_motion;  // [frame][region]
  std::vector<GlobalStrain> strain;                      // Per frame.
  // A solid's strain per layer (layer_strain.h), [frame][region] against
  // the ED frame; empty without a wall.  Where a region's numbers are left
  // out (below), so are its layers'; where a frame's rotation is, the
  // thirds' thickening (contours place no layer inside the wall).
  std::vector<std::vector<RegionLayers>> region_layers;
  // What the segments cannot show through the wall (regional_limit.h);
  // the report and fit.json say it.
  RegionalLimit regional_limit = RegionalLimit::kNone;
  // Per frame, whether its turn about the long axis is measured
  // (RotationMeasured).  Where it is not, clinical's rotations, twists,
  // torsion and shear angle, the regions' rotation and Ecl and strain's
  // gcl are kNotMeasured: contours show no turn about the axis, and the
  // circumferential-longitudinal shear is a twist's gradient.
  std::vector<bool> rotation_measured;
  // Per frame, false where its data span much less of the axis than frame
  // 0's (the fit's short_span warning; unless --extrapolated): its volumes,
  // mass and myocardial volume change are kNotMeasured, and so are the
  // ejection fraction's ESV and ratio.
  std::vector<bool> volume_measured;
  // Per frame, false where nothing places a solid's walls (the fit's
  // walls_unseen warning: mid-wall tags, no contours): its volumes, mass,
  // thickening, each wall's motion, the segments' thickening and the
  // layers' strains are kNotMeasured.  The ejection fraction's end-systole
  // is then the frame of least volume inside the mid-wall, and its ratio
  // is kNotMeasured when that frame's walls or ED's are not measured
  // (EjectionFraction::es_by_midwall).
  std::vector<bool> walls_measured;
  // Without data near the apex (SequenceFit::apex_in_data), what lies
  // where frame 0 has no data is the model's continuation of the data
  // above: a level (kBasal, kMid, kApical) whose middle height lies below
  // frame 0's lowest data point, the apex cap (kApex, segment 17) always,
  // and the apical ring (kApicalRingFraction) when it lies below it.  Unless
  // AnalyzeFit is asked to show them, their numbers are kNotMeasured: the
  // level's regions and strains, and the ring's rotations, net twist, torsion
  // and shear angle (LeaveOutApexRing).
  std::array<bool, 4> level_extrapolated{};  // By RegionLevel.
  bool apex_ring_extrapolated = false;
  bool extrapolated_shown = false;
  // Whether the apex cap's (segment 17's) numbers are given: frame 0's
  // data reach the apex (SequenceFit::apex_in_data), or they are shown
  // anyway.  Where not, its entries in region_motion are kNotMeasured (its
  // area kept); the levels' and global strains still take the model's cap
  // in.
  bool apex_cap_measured = true;
  // The heights clinical's ring means are taken over (ClinicalRingSpan).
  RingSpan ring_span;
  // What clinical[t].volume_ml encloses: "cavity" (a solid's endocardium,
  // or a surface fitted to endocardial contours), "epicardial" or "midwall"
  // (VolumeSurfaceName).
  std::string volume_surface;
  // Per frame: the fit's verdict (FrameFit::verdict) and the clinical
  // numbers' (JudgeClinical).
  std::vector<Verdict> verdicts;
  // Each segment's time to peak Ecc and their spread (segment_timing.h),
  // over the segments measured after the above.
  Dyssynchrony dyssynchrony;
  // The report's footer: what made the fit (the command line, or "Python")
  // and when (UtcMinuteNow); empty: no footer.  Set by the caller.
  std::string made_by;
  std::string made_utc;
  // Every number's standard deviation, by the delta method over the
  // frames' covariances (report/number_uncertainty.h); computed false
  // without them (--uncertainty off).
  NumberSd sd;
  // Each number's bias from the local field's noise, in sd's layout
  // (report/local_field_noise.h): the 95 % interval is centred on the
  // number minus it.  computed false without the field's draws.
  NumberSd noise_bias;
  // The kind of data fitted, which says which intervals are calibrated
  // (interval_calibration.h).
  IntervalData interval_data = IntervalData::kOther;
  // The label map the points came from (pfdm fit --segmentation), else
  // nullopt.  Set by the caller (AttachSegmentation).
  std::optional<SegmentationRecord> segmentation;
};

// "cavity", "epicardial" or "midwall": see FitAnalysis::volume_surface.
std::string VolumeSurfaceName(const SequenceFit& fit);

// Per frame: whether it and frame 0, the reference of every rotation, have
// tracked points (FrameFit::tracked).
std::vector<bool> RotationMeasured(const SequenceFit& fit);

// Where clinical's ring means are taken: the whole length when frame 0's
// data reach the apex (or show_extrapolated), else from the lowest data
// point to the highest (clamped to the rim): the rings frame 0 has data in.
RingSpan ClinicalRingSpan(const SequenceFit& fit, bool show_extrapolated);

// The plane frame t's volumes are closed at: its base plane, else its
// slice plane; nullptr for each surface's flat lid at its own rim.
const BasePlane* VolumePlaneOf(const FitAnalysis& analysis, size_t t);
// Whether some frame's volumes end at its slice plane.
bool HasSlicePlanes(const FitAnalysis& analysis);

// base_planes: one per frame to close the cavity there (see
// CavityVolumeMl), or empty for the flat lid at the base rim.
// show_extrapolated: keep the numbers measured where frame 0 has no data
// (FitAnalysis::level_extrapolated; --extrapolated).
FitAnalysis AnalyzeFit(const SequenceFit& fit,
                       const std::vector<BasePlane>& base_planes = {},
                       const RegionLayout& layout = RegionLayout(),
                       bool show_extrapolated = false);

}  // namespace pfdm

#endif  // PFDM_REPORT_FIT_ANALYSIS_H_
