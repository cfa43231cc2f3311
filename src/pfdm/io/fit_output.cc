#include "pfdm/io/fit_output.h"

#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "ceres/types.h"
#include "nlohmann/json.hpp"
#include "pfdm/io/vtp_writer.h"
#include "pfdm/model/model_surface.h"
#include "pfdm/report/bullseye_plot.h"
#include "pfdm/report/clinical_summary.h"
#include "pfdm/report/fit_plots.h"
#include "pfdm/report/fit_report.h"
#include "pfdm/report/global_strain.h"
#include "pfdm/util/atomic_file.h"
#include "pfdm/util/error.h"

namespace pfdm {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDegreesPerRadian = 180.0 / kPi;

constexpr const char* kGaugeConvention =
    "a0 (scale) is set on frame 0 so that the model, a3 = 0.8 there, spans "
    "the data from its fitted apex to the highest point along the axis, and "
    "is held afterwards; frame 0 fits the pose with tau = 0 and no bending; "
    "in every frame the axis is the least-squares line of the ring centres "
    "(offsets e1o, e2o with zero mean and zero linear trend over the knots; "
    "e3o = 0), so translation and tilt are the pose's; later frames fit the "
    "pose but not its spin about frame 0's long axis, so tau(u, t) is "
    "rotation about the LV axis relative to frame 0; bending has zero mean "
    "over every ring, so a ring's axial position is a3's and the pose's; b1 "
    "and b3 are shifted by multiples of 2 (negating b0 or b2 for odd ones, "
    "the same bend) until their knot means lie in [0, 2).";

constexpr const char* kEjectionDefinition =
    "(EDV - ESV) / EDV; ED is frame 0, ES the frame of least volume; the "
    "volumes are the frames' cavity_volume_ml, closed as cavity_closure "
    "says.";

constexpr const char* kVolumeFractionDefinition =
    "(V_ED - V_ES) / V_ED of the volume the fitted surface encloses, which "
    "is not the cavity (volume_surface says what it is: a surface through "
    "the middle of the wall encloses the cavity and about half the "
    "myocardium), so this is not the ejection fraction: fit tags through "
    "the wall or contours of both walls (--wall solid) for that; ED is frame "
    "0, ES the frame of least volume.";

constexpr const char* kWallDefinition =
    "A solid (model.wall): x(u, v, w) with w from -1 (endocardium) to +1 "
    "(epicardium), the layer w = 0 displaced along the ellipsoid normal n by "
    "w h / 2 + w^2 shift, the twist tau + w dtau / 2; tags get their w from "
    "their rank across the wall in every frame (docs/gauge.md, The wall).  "
    "cavity_volume_ml is inside the endocardium, myocardial_volume_ml "
    "between the walls (each closed as cavity_closure says), lv_mass_g at "
    "1.05 g/ml; endo_* and epi_* rotations and radial contraction are "
    "measured like the mid-wall's on each wall's rings in the same frame-0 "
    "short-axis planes; wall_thickness_mm is the endocardial-to-epicardial "
    "vector of a material point along the mid-wall's normal, the mean over "
    "the ten contraction rings, and wall_thickening_percent the mean of "
    "100 (T / T0 - 1) over them (per segment: regions' "
    "thickening_percent).";

constexpr const char* kRegionsConvention =
    "AHA-style segments: thirds of frame 0's axis from the base rim to the "
    "apex (segments 1-6 basal, 7-12 mid, 13-16 apical), each cut into equal "
    "sectors of longitude v counted counter-clockwise about +z (seen from "
    "the base) from v = -180 degrees, the model's -x axis, not the RV "
    "insertion; per frame, rotation_deg is the mean turn of the segment's "
    "material points about frame 0's long axis (about their ring's "
    "centroid) and radial_contraction_percent the mean of 1 - r / r(frame "
    "0), r a material point's distance from its ring's centroid.";

constexpr const char* kStrainDefinition =
    "Lagrangian (Green-Lagrange) surface strain of the fitted model's "
    "material points against frame 0, percent: at each material point the "
    "surface deformation gradient F maps frame 0's tangent plane to frame "
    "t's, E = (F^T F - I) / 2 in frame 0's orthonormal basis e_c (along the "
    "circle of latitude, v increasing) and e_l (in the plane, perpendicular "
    "to e_c, apex to base): Ecc, Ell, Ecl.  Regions: area-weighted means "
    "over each segment (frame 0's area).  gcs_percent and gls_percent (per "
    "frame in clinical): area-weighted means of Ecc and Ell over the whole "
    "surface from the apex pole to the base rim; the peaks are the most "
    "negative over the frames; levels: the same means over each third.";

constexpr const char* kClinicalDefinition =
    "Measured on the fitted model's material points against frame 0's, "
    "whatever share of the motion the pose and the functions carry: "
    "apex_rotation_deg and base_rotation_deg, the mean turn about frame 0's "
    "long axis (right-handed, apex to base) of the material rings at 0.2 and "
    "0.85 of frame 0's length from the apex pole to the base rim; "
    "net_twist_deg = base - apex; torsion_deg_per_cm, net twist over frame "
    "0's distance between the two rings; shear_angle_deg, the "
    "circumferential-longitudinal shear angle atan(twist (r_apex + r_base) / "
    "(2 D)) on frame 0's geometry; radial_contraction_percent, the mean over "
    "ten rings (0.05 to 0.95 of the length) of 1 - r / r0, r the mean "
    "distance of a ring's material points from their centroid; "
    "longitudinal_shortening_percent, 1 - L / L0, L from the apex pole to the "
    "centroid of the base rim's material points.  The *_per_knot ratios are "
    "a1, a2, a3 against frame 0 (the paper's Fig. 5).";

std::string CavityClosure(const FitAnalysis& analysis) {
  if (analysis.base_planes.empty()) {
    return "flat lid: a fan of triangles from the base rim to its centroid";
  }
  return "each frame's mitral valve plane (least squares through its " +
         std::to_string(analysis.base_planes.front().num_points) +
         " MITRAL_VALVE guide points on frame 0), the model continued past "
         "its base rim with its functions held at their base values";
}

bool IsLength(int f) {
  return f == kA0 || f == kA1 || f == kA2 || f == kA3 || f == kB0 || f == kB2 ||
         f == kE1o || f == kE2o || f == kE3o || f == kH || f == kWallShift;
}

double KnotRingZ(const Model& model, double u) {
  return model.state.globals[kA0] * model.FunctionAt(kA3, u) * std::sin(u) +
         model.FunctionAt(kE3o, u);
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

const std::regex& OutputNamePattern() {
  static const std::regex pattern(
      "(fit\\.json|parameters\\.csv|parameters\\.svg|report\\.html|"
      "fit\\.pvd|frame_[0-9]+\\.vtk|frame_[0-9]+\\.vtp)(\\.tmp\\.[0-9]+)?");
  return pattern;
}

// The names of the output files and temporaries in dir.
std::vector<std::string> OutputNamesIn(const std::string& dir) {
  std::vector<std::string> names;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(dir, error)) {
    const std::string name = entry.path().filename().string();
    if (IsFitOutputName(name)) names.push_back(name);
  }
  if (error) {
    throw InputError(dir + ": cannot list the folder: " + error.message());
  }
  return names;
}

// Removes dir/name if it is there; a folder or a failure is an error, as
// the set could not be replaced whole.
void RemoveOutputFile(const std::string& dir, const std::string& name) {
  const std::string path = dir + "/" + name;
  std::error_code error;
  const auto status = std::filesystem::symlink_status(path, error);
  if (!std::filesystem::exists(status)) return;
  if (std::filesystem::is_directory(status)) {
    throw InputError(path + ": is a folder where pfdm writes a file");
  }
  if (std::remove(path.c_str()) != 0 && errno != ENOENT) {
    throw InputError(
        path + ": cannot remove the older output: " + std::strerror(errno));
  }
}

}  // namespace

bool IsFitOutputName(const std::string& name) {
  return std::regex_match(name, OutputNamePattern());
}

void CheckFitOutputFolder(const std::string& dir,
                          const std::string& input_path) {
  // The outermost folder this makes, removed again after the probe: a
  // failed run should leave no trace, and the writer makes it anyway.
  std::filesystem::path created;
  std::error_code missing;
  for (std::filesystem::path p = std::filesystem::absolute(dir, missing);
       !p.empty() && !std::filesystem::exists(p, missing);
       p = p.parent_path()) {
    created = p;
    if (p == p.parent_path()) break;
  }
  EnsureDirectory(dir);
  const std::string probe = dir + "/fit.json.tmp." + std::to_string(getpid());
  {
    errno = 0;
    std::ofstream out(probe, std::ios::binary | std::ios::trunc);
    out << "{}\n";
    out.close();
    if (!out) {
      std::remove(probe.c_str());
      throw InputError(dir + ": cannot write in this folder: " +
                       (errno != 0 ? std::strerror(errno) : "write failed"));
    }
  }
  std::remove(probe.c_str());
  if (!created.empty()) {
    // Only empty folders go, innermost first.
    for (std::filesystem::path p = std::filesystem::absolute(dir, missing);
         std::filesystem::remove(p, missing) && p != created;
         p = p.parent_path()) {
    }
    return;  // Nothing in it to check, and the input cannot be there.
  }
  for (const char* name : {"fit.json", "parameters.csv", "parameters.svg",
                           "report.html", "fit.pvd"}) {
    const std::string path = dir + "/" + name;
    std::error_code error;
    const auto status = std::filesystem::symlink_status(path, error);
    if (std::filesystem::exists(status) &&
        !std::filesystem::is_regular_file(status) &&
        !std::filesystem::is_symlink(status)) {
      throw InputError(path + ": is a folder or other non-file where pfdm " +
                       "writes a file");
    }
  }
  if (input_path.empty()) return;
  std::error_code error;
  const auto input = std::filesystem::weakly_canonical(input_path, error);
  const auto folder = std::filesystem::weakly_canonical(dir, error);
  if (!error && input.parent_path() == folder &&
      IsFitOutputName(input.filename().string())) {
    throw InputError(input_path + ": the input is one of the outputs " + dir +
                     " would be given; choose another --out");
  }
}

double ReportedValue(const Model& model, int f, double u) {
  const double value = model.FunctionAt(f, u);
  if (f == kA1 || f == kA2 || f == kA3) return value * model.state.globals[kA0];
  return value;
}

const char* ReportedUnit(int f) {
  return f == kTau || f == kDtau ? "rad" : IsLength(f) ? "mm" : "1";
}

std::string ParametersCsv(const std::vector<Model>& frames) {
  std::ostringstream out;
  out.precision(10);
  out << "frame,function,knot,u,z_mm,value\n";
  for (size_t t = 0; t < frames.size(); ++t) {
    const Model& model = frames[t];
    const KnotGrid grid = model.config.Grid();
    for (int f = 0; f < kNumFunctions; ++f) {
      for (int k = 0; k < grid.num_knots(); ++k) {
        const double u = grid.KnotU(k);
        out << t << ',' << FunctionName(f) << ',' << k << ',' << u << ','
            << KnotRingZ(model, u) << ',' << ReportedValue(model, f, u) << '\n';
      }
    }
  }
  return out.str();
}

std::string FitJson(const PointSequence& points, const SequenceFit& fit,
                    const FitOptions& options) {
  return FitJson(points, fit, options, AnalyzeFit(fit));
}

std::string FitJson(const PointSequence& points, const SequenceFit& fit,
                    const FitOptions& options, const FitAnalysis& analysis) {
  using json = nlohmann::ordered_json;
  json settings = {
      {"points", points.source},
      {"smoothness_weight", options.smoothness_weight},
      {"wall", WallModelName(options.wall)},
      {"prior_weight", options.prior_weight},
      {"untracked_prior_weight", options.untracked_prior_weight},
      {"loss", options.loss},
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
      {"local_stiffness", options.local.stiffness}};
  if (!points.contour_types.empty()) {
    settings["contour_types"] = points.contour_types;
  }
  if (options.solver.kind != SolverKind::kDirect) {
    const SolverOptions& s = options.solver;
    settings["time_step"] = s.time_step;  // 0: the solver's default.
    settings["rest_tolerance"] = s.rest_tolerance;
    settings["max_steps"] = s.max_steps;
  }
  if (options.solver.kind == SolverKind::kIntegrator) {
    const DampingGroups& g = options.damping_groups;
    settings["damping"] =
        options.solver.damping == DampingKind::kJacobi ? "jacobi" : "unit";
    settings["damping_scale"] = {{"pose", g.pose},
                                 {"shape", g.shape},
                                 {"twist", g.twist},
                                 {"bending", g.bending},
                                 {"offsets", g.offsets}};
  }
  if (options.hint) {
    const auto& h = *options.hint;
    settings["apex_hint"] = {h.apex.x(), h.apex.y(), h.apex.z()};
    settings["base_hint"] = {h.base_center.x(), h.base_center.y(),
                             h.base_center.z()};
  }
  json functions = json::object();
  for (int f = 0; f < kNumFunctions; ++f) {
    functions[FunctionName(f)] = {{"mode", ModeName(fit.config.modes[f])},
                                  {"unit", ReportedUnit(f)}};
  }
  json model = {{"name", fit.config.name},
                {"knots", fit.config.num_knots},
                {"u_min", fit.config.u_min},
                {"u_max", fit.config.u_max},
                {"wall", fit.config.Solid() ? "solid" : "midwall"},
                {"wall_reason", fit.wall_reason},
                {"tag_noise_mm", fit.tag_noise_mm},
                {"volume_surface", analysis.volume_surface},
                {"functions", functions}};
  const bool solid = fit.config.Solid();
  const std::string volume_key = analysis.volume_surface + "_volume_ml";

  json frames = json::array();
  for (size_t t = 0; t < fit.frames.size(); ++t) {
    const FrameFit& frame = fit.frames[t];
    const ClinicalSummary& summary = analysis.clinical[t];
    const GlobalStrain& strain = analysis.strain[t];
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
                  {volume_key, summary.volume_ml}};
    if (solid) {
      entry["myocardial_volume_ml"] = summary.myocardial_volume_ml;
      entry["lv_mass_g"] = summary.lv_mass_g;
    }
    entry.update(json{
        {"pose",
         {{"center_mm", frame.state.center},
          {"quaternion_wxyz", frame.state.quaternion}}},
        {"clinical",
         {{"net_twist_deg", summary.net_twist_deg},
          {"apex_rotation_deg", summary.apex_rotation_deg},
          {"base_rotation_deg", summary.base_rotation_deg},
          {"torsion_deg_per_cm", summary.torsion_deg_per_cm},
          {"shear_angle_deg", summary.shear_angle_deg},
          {"radial_contraction_percent", summary.radial_contraction_percent},
          {"longitudinal_shortening_percent",
           summary.longitudinal_shortening_percent},
          {"gcs_percent", strain.gcs_percent},
          {"gls_percent", strain.gls_percent},
          {"gcl_percent", strain.gcl_percent},
          {"radial_ratio_x_per_knot", summary.radial_ratio_x},
          {"radial_ratio_y_per_knot", summary.radial_ratio_y},
          {"longitudinal_ratio_per_knot", summary.longitudinal_ratio}}}});
    if (solid) {
      json& clinical = entry["clinical"];
      clinical["endo_apex_rotation_deg"] = summary.endo_apex_rotation_deg;
      clinical["endo_base_rotation_deg"] = summary.endo_base_rotation_deg;
      clinical["endo_net_twist_deg"] = summary.endo_net_twist_deg;
      clinical["epi_apex_rotation_deg"] = summary.epi_apex_rotation_deg;
      clinical["epi_base_rotation_deg"] = summary.epi_base_rotation_deg;
      clinical["epi_net_twist_deg"] = summary.epi_net_twist_deg;
      clinical["endo_radial_contraction_percent"] =
          summary.endo_radial_contraction_percent;
      clinical["epi_radial_contraction_percent"] =
          summary.epi_radial_contraction_percent;
      clinical["wall_thickness_mm"] = summary.wall_thickness_mm;
      clinical["wall_thickening_percent"] = summary.wall_thickening_percent;
    }
    frames.push_back(std::move(entry));
  }
  const EjectionFraction& ef = analysis.ejection_fraction;
  const bool cavity = analysis.volume_surface == "cavity";
  json ejection = {
      {"ratio", ef.ratio},
      {"ed_frame", ef.ed_frame},
      {"es_frame", ef.es_frame},
      {"edv_ml", ef.edv_ml},
      {"esv_ml", ef.esv_ml},
      {"definition", cavity ? kEjectionDefinition : kVolumeFractionDefinition},
      {"cavity_closure", CavityClosure(analysis)}};
  const std::vector<double> peak_ecc = PeakRegionEcc(analysis.region_motion);
  json regions = json::array();
  for (size_t r = 0; r < analysis.regions.size(); ++r) {
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
    regions.push_back(
        {{"segment", region.segment},
         {"name", region.Name()},
         {"v_range_deg",
          {region.v_begin * kDegreesPerRadian,
           region.v_end * kDegreesPerRadian}},
         {"rotation_deg", rotation},
         {"radial_contraction_percent", radial},
         {"ecc_percent", ecc},
         {"ell_percent", ell},
         {"ecl_percent", ecl},
         {"peak_ecc_percent", peak_ecc[r]},
         {"area_mm2", analysis.region_motion.empty()
                          ? 0.0
                          : analysis.region_motion[0][r].area_mm2}});
    if (solid) regions.back()["thickening_percent"] = thickening;
  }
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
  const StrainPeak gcs = PeakGcs(analysis.strain);
  const StrainPeak gls = PeakGls(analysis.strain);
  json strain = {
      {"definition", kStrainDefinition}, {"peak_gcs_percent", gcs.percent},
      {"peak_gcs_frame", gcs.frame},     {"peak_gls_percent", gls.percent},
      {"peak_gls_frame", gls.frame},     {"levels", levels}};
  json document = {{"pfdm_version", "0.1.0"},
                   {"settings", settings},
                   {"model", model},
                   {"gauge_convention", kGaugeConvention},
                   {"clinical_definition", kClinicalDefinition}};
  if (solid) document["wall_definition"] = kWallDefinition;
  document[cavity ? "ejection_fraction"
                  : analysis.volume_surface + "_volume_fraction"] = ejection;
  document.update(json{{"regions_convention", kRegionsConvention},
                       {"regions", regions},
                       {"strain", strain},
                       {"frames", frames}});
  return document.dump(2) + "\n";
}

VtkPolyData FramePolyData(const Model& model, const Frame& frame,
                          const FrameFit& fit) {
  const ModelSurface surface =
      MakeModelSurface(model, kSurfaceRings, kSurfaceMeridians);
  VtkPolyData data;
  data.points = surface.mesh.points;
  data.triangles = surface.mesh.triangles;
  std::vector<double> u_values = surface.u, v_values = surface.v;
  std::vector<double> w_values(data.points.size(), 0.0);
  // A solid's walls go in as two more surfaces, told apart by w.
  for (double w : model.config.Solid() ? std::vector<double>{-1.0, 1.0}
                                       : std::vector<double>{}) {
    const ModelSurface wall =
        MakeModelSurface(model, kSurfaceRings, kSurfaceMeridians, {}, w);
    const int offset = static_cast<int>(data.points.size());
    data.points.insert(data.points.end(), wall.mesh.points.begin(),
                       wall.mesh.points.end());
    for (auto triangle : wall.mesh.triangles) {
      for (int& corner : triangle) corner += offset;
      data.triangles.push_back(triangle);
    }
    u_values.insert(u_values.end(), wall.u.begin(), wall.u.end());
    v_values.insert(v_values.end(), wall.v.begin(), wall.v.end());
    w_values.insert(w_values.end(), wall.u.size(), w);
  }
  std::vector<double> is_data(data.points.size(), 0.0);
  std::vector<Eigen::Vector3d> residuals(data.points.size(),
                                         Eigen::Vector3d::Zero());
  for (size_t i = 0; i < frame.points.size(); ++i) {
    data.vertices.push_back(static_cast<int>(data.points.size()));
    data.points.push_back(frame.points[i].position);
    u_values.push_back(fit.material[i].u);
    v_values.push_back(fit.material[i].v);
    w_values.push_back(fit.material[i].w);
    is_data.push_back(1.0);
    residuals.push_back(fit.residuals[i]);
  }
  std::vector<double> twist;
  for (double u : u_values) {
    twist.push_back(model.FunctionAt(kTau, u) * kDegreesPerRadian);
  }
  data.point_scalars = {{"u", u_values},
                        {"v", v_values},
                        {"w", w_values},
                        {"twist_deg", twist},
                        {"is_data", is_data}};
  data.point_vectors = {{"residual", residuals}};
  return data;
}

std::string FrameVtk(const Model& model, const Frame& frame,
                     const FrameFit& fit) {
  return ToLegacyVtk(FramePolyData(model, frame, fit),
                     "pfdm frame " + std::to_string(frame.index));
}

void WriteFitOutputs(const std::string& dir, const PointSequence& points,
                     const SequenceFit& fit, const FitOptions& options,
                     const std::vector<BasePlane>& base_planes,
                     VtkFormat vtk_format) {
  // gnuplot starts while the fit is analysed.
  SvgRendering plots;
  WriteFitOutputs(dir, points, fit, AnalyzeFit(fit, base_planes), options,
                  vtk_format, &plots);
}

void WriteFitOutputs(const std::string& dir, const PointSequence& points,
                     const SequenceFit& fit, const FitAnalysis& analysis,
                     const FitOptions& options, VtkFormat vtk_format,
                     SvgRendering* plots) {
  // The frames' meshes are formatted and written while gnuplot renders the
  // plots (one gnuplot for the four: its start-up, not the plotting, was
  // most of their time).
  plots->Render({ParameterPlots(analysis.models),
                 CycleCurves(analysis.clinical, analysis.volume_surface),
                 StrainCurves(analysis.strain),
                 Bullseye(analysis.regions, ClinicalBullseyeMaps(analysis))});
  std::vector<std::string> frame_names;
  std::vector<std::pair<double, std::string>> timesteps;
  for (const FrameFit& frame : fit.frames) {
    char name[32];
    std::snprintf(name, sizeof(name), "frame_%03d", frame.frame);
    frame_names.push_back(name);
    timesteps.emplace_back(frame.frame, std::string(name) + ".vtp");
  }
  std::vector<std::string> names = {
      "parameters.csv", "fit.pvd", "parameters.svg", "report.html", "fit.json"};
  for (const std::string& name : frame_names) {
    names.push_back(name + ".vtk");
    names.push_back(name + ".vtp");
  }

  EnsureDirectory(dir);
  // A folder where a file goes stops the write before anything is touched.
  std::vector<std::string> older = OutputNamesIn(dir);
  older.insert(older.end(), names.begin(), names.end());
  for (const std::string& name : older) {
    std::error_code error;
    if (std::filesystem::is_directory(
            std::filesystem::symlink_status(dir + "/" + name, error))) {
      throw InputError(dir + "/" + name +
                       ": is a folder where pfdm writes a file");
    }
  }
  // No fit.json, no set: from here until the new one is in place a kill, or
  // a failure, leaves a folder that says "not done".  The older set goes
  // first: new files written while it was still there (to keep it until
  // gnuplot had finished) made the writing of 50,000 tags' meshes take
  // half as long again.
  RemoveOutputFile(dir, "fit.json");
  for (const std::string& name : OutputNamesIn(dir)) {
    RemoveOutputFile(dir, name);
  }
  std::vector<std::string> written;
  const auto write = [&](const std::string& name, const std::string& contents) {
    WriteFileAtomically(dir + "/" + name, contents);
    written.push_back(name);
  };
  try {
    // Each frame's meshes are written as soon as they are formatted, so
    // the next frame's reuse their memory: held until the end, the
    // megabytes of every frame were fresh pages, and their faults were
    // half of the writing.
    for (size_t t = 0; t < fit.frames.size(); ++t) {
      const VtkPolyData data =
          FramePolyData(analysis.models[t], points.frames[t], fit.frames[t]);
      const std::string& name = frame_names[t];
      write(name + ".vtk", ToLegacyVtk(data, "pfdm " + name, vtk_format));
      write(name + ".vtp", ToVtkXmlPolyData(data, vtk_format));
    }
    write("parameters.csv", ParametersCsv(analysis.models));
    write("fit.pvd", PvdCollection(timesteps));
    const std::string json = FitJson(points, fit, options, analysis);
    const std::vector<std::string> svgs = plots->Finish();
    write("parameters.svg", svgs[0]);
    write("report.html", FitReportHtml(points, fit, analysis, svgs[0], svgs[1],
                                       svgs[2], svgs[3]));
    write("fit.json", json);  // Last: marks the set.
  } catch (const InputError&) {
    for (const std::string& name : written) {
      std::remove((dir + "/" + name).c_str());
    }
    throw;
  }
}

}  // namespace pfdm
