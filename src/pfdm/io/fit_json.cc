#include "pfdm/io/fit_json.h"

#include <string>
#include <vector>

#include "ceres/types.h"
#include "nlohmann/json.hpp"
#include "pfdm/io/fit_json_text.h"
#include "pfdm/io/fit_output.h"
#include "pfdm/io/intervals_json.h"
#include "pfdm/io/not_measured_json.h"
#include "pfdm/io/segmentation_json.h"
#include "pfdm/io/segments_json.h"
#include "pfdm/report/clinical_summary.h"
#include "pfdm/report/global_strain.h"
#include "pfdm/util/angles.h"
#include "pfdm/util/verdict.h"
#include "pfdm/util/version.h"

namespace pfdm {
namespace {

// Keys stay in the order they are inserted: fit.json reads top-down, from
// the settings to the frames.
using json = nlohmann::ordered_json;

// A number, or null where it is kNotMeasured.
json Value(double value) { return Measured(value) ? json(value) : json(); }

json Values(const std::vector<double>& values) {
  json array = json::array();
  for (double value : values) array.push_back(Value(value));
  return array;
}

std::string CavityClosure(const FitAnalysis& analysis) {
  if (analysis.base_planes.empty() && HasSlicePlanes(analysis)) {
    return "the highest short-axis slice: both walls cut by the plane of the "
           "lowest wall's base rim, which the fit puts there, each "
           "continued past its own rim with its "
           "functions held (frames whose data end at one slice; in any "
           "other, a flat lid at each wall's rim)";
  }
  if (analysis.base_planes.empty()) {
    return "flat lid: a fan of triangles from the base rim to its centroid";
  }
  return "each frame's mitral valve plane (least squares through its " +
         std::to_string(analysis.base_planes.front().num_points) +
         " MITRAL_VALVE guide points on frame 0), the model continued past "
         "its base rim with its functions held at their base values";
}

std::string ModeName(FunctionMode mode) {
  switch (mode) {
    case FunctionMode::kFree:
      return "free";
    case FunctionMode::kConstant:
      return "constant";
    case FunctionMode::kFixed:
      return "fixed";
  }
  return "";
}

// The solver's settings beyond the direct solve's: the stepping solvers'
// time step and rest, the integrator's damping.
void AddStepperSettings(const FitOptions& options, json* settings) {
  if (options.solver.kind != SolverKind::kDirect) {
    const SolverOptions& s = options.solver;
    (*settings)["time_step"] = s.time_step;  // 0: the solver's default.
    (*settings)["rest_tolerance"] = s.rest_tolerance;
    (*settings)["max_steps"] = s.max_steps;
  }
  if (options.solver.kind == SolverKind::kIntegrator) {
    const DampingGroups& g = options.damping_groups;
    (*settings)["integrator"] = IntegratorName(options.solver.integrator);
    (*settings)["damping"] = DampingName(options.solver.damping);
    (*settings)["damping_scale"] = {{"pose", g.pose},
                                    {"shape", g.shape},
                                    {"twist", g.twist},
                                    {"bending", g.bending},
                                    {"offsets", g.offsets}};
  }
}

// The loss: with one, "loss_scale" is "auto" or the number given and
// "loss_scale_mm" the scale used, measured per frame for auto (a list, a
// frame's FrameFit::loss_scale_mm each); without, "loss_scale_mm" is the
// option as given.
void AddLossSettings(const SequenceFit& fit, const FitOptions& options,
                     json* settings) {
  if (options.loss == "none") {
    settings->erase("loss_scale");
    return;
  }
  if (!options.loss_scale_auto) {
    (*settings)["loss_scale"] = options.loss_scale_mm;
    return;
  }
  (*settings)["loss_scale"] = "auto";
  json scales = json::array();
  for (const FrameFit& frame : fit.frames) {
    scales.push_back(frame.loss_scale_mm);
  }
  (*settings)["loss_scale_mm"] = scales;
}

json Settings(const PointSequence& points, const SequenceFit& fit,
              const FitOptions& options) {
  json settings = {
      {"points", points.source},
      {"smoothness_weight", options.smoothness_weight},
      {"wall", WallModelName(options.wall)},
      {"surface", SurfaceChoiceName(options.surface)},
      {"ed_frame", options.ed_frame},
      {"prior_weight", options.prior_weight},
      {"untracked_prior_weight", options.untracked_prior_weight},
      {"untracked_prior_covered_radii_scale",
       options.untracked_prior_covered_radii_scale},
      {"temporal_prior_weight", options.temporal_prior_weight},
      {"incompressible_weight", options.incompressible_weight},
      {"loss", options.loss},
      {"loss_scale", nullptr},
      {"loss_scale_mm", options.loss_scale_mm},
      {"max_correspondence_rounds", options.max_correspondence_rounds},
      {"correspondence_tolerance_mm", options.correspondence_tolerance_mm},
      {"solver", SolverName(options.solver.kind)},
      {"linear_solver",
       ceres::LinearSolverTypeToString(options.solver.linear_solver)},
      {"jacobian", JacobianName(options.jacobian)},
      {"max_iterations", options.solver.max_iterations},
      {"threads", options.solver.num_threads},
      {"local", options.local.enabled},
      {"local_grid", std::to_string(options.local.rows) + "x" +
                         std::to_string(options.local.cols)},
      {"local_stiffness", options.local.stiffness},
      {"local_transmural", options.local.transmural},
      {"tag_depths", options.hold_tag_depths ? "held" : "ranked"},
      {"uncertainty", options.uncertainty}};
  if (!points.contour_types.empty()) {
    settings["contour_types"] = points.contour_types;
  }
  AddLossSettings(fit, options, &settings);
  AddStepperSettings(options, &settings);
  if (options.hint) {
    const auto& h = *options.hint;
    settings["apex_hint"] = {h.apex.x(), h.apex.y(), h.apex.z()};
    settings["base_hint"] = {h.base_center.x(), h.base_center.y(),
                             h.base_center.z()};
  }
  return settings;
}

json ModelSection(const SequenceFit& fit, const FitAnalysis& analysis) {
  json functions = json::object();
  for (int f = 0; f < kNumFunctions; ++f) {
    functions[FunctionName(f)] = {{"mode", ModeName(fit.config.modes[f])},
                                  {"unit", ReportedUnit(f)}};
  }
  return {{"name", fit.config.name},
          {"knots", fit.config.num_knots},
          {"u_min", fit.config.u_min},
          {"u_max", fit.config.u_max},
          {"wall", fit.config.Solid() ? "solid" : "midwall"},
          {"wall_reason", fit.wall_reason},
          {"tag_noise_mm", fit.tag_noise_mm},
          {"axis_source", fit.axis_source},
          {"temporal_prior_weight_used", fit.temporal_prior_weight},
          {"apex_in_data", fit.apex_in_data},
          {"apex_data_distance_fraction", fit.apex_data_distance},
          {"lowest_data_height_fraction", fit.lowest_data_height},
          {"lowest_data_u", fit.lowest_data_u},
          {"highest_data_height_fraction", fit.highest_data_height},
          {"ring_span_height_fraction",
           {analysis.ring_span.low, analysis.ring_span.high}},
          {"volume_surface", analysis.volume_surface},
          {"functions", functions}};
}

// A frame's clinical numbers; a solid's endocardial and epicardial ones and
// its wall thickness follow the mid-wall's.
json FrameClinical(const ClinicalSummary& summary, const GlobalStrain& strain,
                   bool solid) {
  json clinical = {
      {"net_twist_deg", Value(summary.net_twist_deg)},
      {"apex_rotation_deg", Value(summary.apex_rotation_deg)},
      {"base_rotation_deg", Value(summary.base_rotation_deg)},
      {"torsion_deg_per_cm", Value(summary.torsion_deg_per_cm)},
      {"shear_angle_deg", Value(summary.shear_angle_deg)},
      {"radial_contraction_percent", summary.radial_contraction_percent},
      {"longitudinal_shortening_percent",
       summary.longitudinal_shortening_percent},
      {"gcs_percent", strain.gcs_percent},
      {"gls_percent", strain.gls_percent},
      {"gcl_percent", Value(strain.gcl_percent)},
      {"radial_ratio_x_per_knot", summary.radial_ratio_x},
      {"radial_ratio_y_per_knot", summary.radial_ratio_y},
      {"longitudinal_ratio_per_knot", summary.longitudinal_ratio}};
  if (solid) {
    clinical["endo_apex_rotation_deg"] = Value(summary.endo_apex_rotation_deg);
    clinical["endo_base_rotation_deg"] = Value(summary.endo_base_rotation_deg);
    clinical["endo_net_twist_deg"] = Value(summary.endo_net_twist_deg);
    clinical["epi_apex_rotation_deg"] = Value(summary.epi_apex_rotation_deg);
    clinical["epi_base_rotation_deg"] = Value(summary.epi_base_rotation_deg);
    clinical["epi_net_twist_deg"] = Value(summary.epi_net_twist_deg);
    clinical["endo_radial_contraction_percent"] =
        summary.endo_radial_contraction_percent;
    clinical["epi_radial_contraction_percent"] =
        summary.epi_radial_contraction_percent;
    clinical["wall_thickness_mm"] = summary.wall_thickness_mm;
    clinical["wall_thickening_percent"] = summary.wall_thickening_percent;
  }
  return clinical;
}

json ReasonsJson(const Verdict& verdict) {
  json reasons = json::array();
  for (const VerdictReason& reason : verdict.reasons()) {
    reasons.push_back({{"severity", QualityName(reason.severity)},
                       {"code", reason.code},
                       {"text", reason.text}});
  }
  return reasons;
}

// How many frames got each quality, and the worst.
json QualitySection(const FitAnalysis& analysis) {
  int count[3] = {0, 0, 0};
  for (const Verdict& verdict : analysis.verdicts) {
    ++count[static_cast<int>(verdict.quality())];
  }
  return {{"overall", QualityName(WorstQuality(analysis.verdicts))},
          {"frames_ok", count[0]},
          {"frames_warning", count[1]},
          {"frames_failed", count[2]},
          {"definition", fit_json_text::kQualityDefinition}};
}

// What the frame's covariance takes as known (docs/uncertainty.md): the
// intervals are conditional on these, and too narrow where they move.
std::vector<std::string> HeldByCovariance(const FrameFit& frame, bool solid) {
  std::vector<std::string> held = {"correspondences", "prior_target"};
  if (frame.kind == FrameKind::kTracked) {
    held.push_back("tracked_material_points");
  }
  if (solid) held.push_back("tag_depths");
  if (!frame.state.local.empty()) held.push_back("local_field");
  return held;
}

// One frame's fit errors, solve, verdict, volume (under volume_key, named
// after the surface measured), pose and clinical numbers; with
// --uncertainty on, what its covariance rests on (fit/problem/
// frame_covariance.h: the data's sigma, the directions left undetermined)
// and what it took.
json FrameEntry(const FrameFit& frame, const Verdict& verdict,
                const ClinicalSummary& summary, const GlobalStrain& strain,
                const std::string& volume_key, bool solid) {
  json entry = {{"frame", frame.frame},
                {"n_points", frame.residuals.size()},
                {"rms_mm", frame.rms_mm},
                {"mean_distance_mm", frame.mean_distance_mm},
                {"max_distance_mm", frame.max_distance_mm},
                {"iterations", frame.iterations},
                {"correspondence_rounds", frame.correspondence_rounds},
                {"correspondence_unsettled_mm", frame.unsettled_mm},
                {"solve_seconds", frame.solve_seconds},
                {"termination", frame.termination},
                {"final_cost",
                 {{"data", frame.costs.data},
                  {"smoothness", frame.costs.smoothness},
                  {"prior", frame.costs.prior},
                  {"gauge", frame.costs.gauge},
                  {"incompressibility", frame.costs.incompressibility}}},
                {"quality", QualityName(verdict.quality())},
                {"quality_reasons", ReasonsJson(verdict)},
                {volume_key, summary.volume_ml}};
  if (solid) {
    entry["myocardial_volume_ml"] = summary.myocardial_volume_ml;
    entry["lv_mass_g"] = summary.lv_mass_g;
    entry["material_myocardium_ml"] = summary.material_myocardium_ml;
    entry["myocardial_volume_change_percent"] =
        summary.myocardial_volume_change_percent;
    // A tracked frame's tags' depths: measured across the walls its
    // contours place, frame 0's held, or ranked in it.
    if (frame.kind == FrameKind::kTracked) {
      entry["tag_depths"] = frame.depths_measured ? "measured"
                            : frame.depths_held   ? "held"
                                                  : "ranked";
    }
  }
  // Only when the input gave times: a frame number is no time.
  if (Measured(summary.time_ms)) entry["time_ms"] = summary.time_ms;
  entry["pose"] = {{"center_mm", frame.state.center},
                   {"quaternion_wxyz", frame.state.quaternion}};
  entry["clinical"] = FrameClinical(summary, strain, solid);
  if (frame.covariance.computed) {
    const FrameCovariance& covariance = frame.covariance;
    entry["uncertainty"] = {
        {"sigma_mm", covariance.sigma_mm},
        {"noise_sigma_mm", covariance.NoiseSigma()},
        {"degrees_of_freedom", covariance.degrees_of_freedom},
        {"parameters", covariance.entries.size()},
        {"rank_deficiency", covariance.rank_deficiency},
        {"deficient_directions", covariance.deficient_directions},
        {"held", HeldByCovariance(frame, solid)},
        {"seconds", covariance.seconds}};
    // Where the noise was measured across the wall, the sd along it too:
    // mostly the ranked depths' error (directional_noise.h).
    if (covariance.tangent_sigma_mm > 0.0) {
      entry["uncertainty"]["normal_sigma_mm"] = covariance.normal_sigma_mm;
    }
  }
  return entry;
}

json Frames(const SequenceFit& fit, const FitAnalysis& analysis) {
  const bool solid = fit.config.Solid();
  const std::string volume_key = analysis.volume_surface + "_volume_ml";
  json frames = json::array();
  for (size_t t = 0; t < fit.frames.size(); ++t) {
    const Verdict& verdict = t < analysis.verdicts.size()
                                 ? analysis.verdicts[t]
                                 : fit.frames[t].verdict;
    frames.push_back(FrameEntry(fit.frames[t], verdict, analysis.clinical[t],
                                analysis.strain[t], volume_key, solid));
  }
  return frames;
}

// The ejection fraction of the cavity, or the same ratio of whatever
// surface the volumes are of, defined as what it is.
json EjectionSection(const FitAnalysis& analysis) {
  const EjectionFraction& ef = analysis.ejection_fraction;
  const bool cavity = analysis.volume_surface == "cavity";
  return {{"ratio", ef.ratio},
          {"ed_frame", ef.ed_frame},
          {"es_frame", ef.es_frame},
          {"edv_ml", ef.edv_ml},
          {"esv_ml", ef.esv_ml},
          {"es_by_midwall", ef.es_by_midwall},
          {"definition", cavity ? fit_json_text::kEjectionDefinition
                                : fit_json_text::kVolumeFractionDefinition},
          {"cavity_closure", CavityClosure(analysis)}};
}

// Segment r's motion and strain over the frames; thickening for a solid.
json RegionEntry(const FitAnalysis& analysis, size_t r, double peak_ecc,
                 bool solid) {
  const WallRegion& region = analysis.regions[r];
  std::vector<double> rotation, radial, ecc, ell, ecl, thickening;
  for (const auto& motion : analysis.region_motion) {
    thickening.push_back(motion[r].thickening_percent);
    rotation.push_back(motion[r].rotation_deg);
    radial.push_back(motion[r].radial_contraction_percent);
    ecc.push_back(motion[r].ecc_percent);
    ell.push_back(motion[r].ell_percent);
    ecl.push_back(motion[r].ecl_percent);
  }
  json entry = {
      {"segment", region.segment},
      {"name", region.Name()},
      {"v_range_deg",
       {region.v_begin * kDegreesPerRadian, region.v_end * kDegreesPerRadian}},
      {"rotation_deg", Values(rotation)},
      {"radial_contraction_percent", Values(radial)},
      {"ecc_percent", Values(ecc)},
      {"ell_percent", Values(ell)},
      {"ecl_percent", Values(ecl)},
      {"peak_ecc_percent", Value(peak_ecc)},
      {"area_mm2", analysis.region_motion.empty()
                       ? 0.0
                       : analysis.region_motion[0][r].area_mm2}};
  if (solid) entry["thickening_percent"] = Values(thickening);
  if (!analysis.region_layers.empty()) {
    entry["err_percent"] = RegionErrJson(analysis, r);
    entry["layers"] = RegionLayersJson(analysis, r);
  }
  return entry;
}

json Regions(const FitAnalysis& analysis, bool solid) {
  const std::vector<double> peak_ecc = PeakRegionEcc(analysis.region_motion);
  json regions = json::array();
  for (size_t r = 0; r < analysis.regions.size(); ++r) {
    regions.push_back(RegionEntry(analysis, r, peak_ecc[r], solid));
  }
  return regions;
}

// Ecc and Ell over the frames, per third of the axis.
json StrainLevels(const FitAnalysis& analysis) {
  json levels = json::object();
  static const char* const kLevelNames[] = {"basal", "mid", "apical"};
  for (int level = 0; level < 3; ++level) {
    std::vector<double> ecc, ell;
    for (const GlobalStrain& g : analysis.strain) {
      ecc.push_back(g.level_ecc_percent[level]);
      ell.push_back(g.level_ell_percent[level]);
    }
    levels[kLevelNames[level]] = {{"ecc_percent", ecc}, {"ell_percent", ell}};
  }
  return levels;
}

json StrainSection(const FitAnalysis& analysis) {
  const StrainPeak gcs = PeakGcs(analysis.strain);
  const StrainPeak gls = PeakGls(analysis.strain);
  return {{"definition", fit_json_text::kStrainDefinition},
          {"peak_gcs_percent", gcs.percent},
          {"peak_gcs_frame", gcs.frame},
          {"peak_gls_percent", gls.percent},
          {"peak_gls_frame", gls.frame},
          {"levels", StrainLevels(analysis)}};
}

}  // namespace

std::string FitJson(const PointSequence& points, const SequenceFit& fit,
                    const FitOptions& options) {
  return FitJson(points, fit, options, AnalyzeFit(fit));
}

std::string FitJson(const PointSequence& points, const SequenceFit& fit,
                    const FitOptions& options, const FitAnalysis& analysis) {
  const bool solid = fit.config.Solid();
  const bool cavity = analysis.volume_surface == "cavity";
  json document = {{"pfdm_version", PfdmVersion()},
                   {"settings", Settings(points, fit, options)},
                   {"model", ModelSection(fit, analysis)},
                   {"quality", QualitySection(analysis)},
                   {"timing",
                    {{"start_seconds", fit.start_seconds},
                     {"checks_seconds", fit.checks_seconds}}},
                   {"gauge_convention", fit_json_text::kGaugeConvention},
                   {"clinical_definition", fit_json_text::kClinicalDefinition}};
  if (solid) document["wall_definition"] = fit_json_text::kWallDefinition;
  if (!analysis.region_layers.empty()) {
    document["layers_definition"] = fit_json_text::kLayersDefinition;
  }
  const json not_measured = NotMeasured(analysis);
  if (!not_measured.is_null()) document["not_measured"] = not_measured;
  if (analysis.segmentation) {
    document["segmentation"] = SegmentationJson(*analysis.segmentation);
  }
  for (const LeftOutContour& c : points.left_out) {
    document["left_out_contours"].push_back(
        {{"frame", c.frame},
         {"contour", c.contour},
         {"points", c.points},
         {"coverage_deg", c.coverage_deg},
         {"why",
          "its slice holds the outflow tract, beside the axis, not the "
          "ventricle round it"}});
  }
  document[cavity ? "ejection_fraction"
                  : analysis.volume_surface + "_volume_fraction"] =
      EjectionSection(analysis);
  document.update(
      json{{"segments_anatomical", analysis.layout.anatomical},
           {"segments", SegmentsSection(analysis)},
           {"regions_convention", fit_json_text::kRegionsConvention},
           {"regions", Regions(analysis, solid)},
           {"dyssynchrony", DyssynchronySection(analysis)},
           {"strain", StrainSection(analysis)},
           {"frames", Frames(fit, analysis)}});
  AddIntervals(analysis, &document);
  return document.dump(2) + "\n";
}

}  // namespace pfdm
