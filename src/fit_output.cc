#include "pfdm/fit_output.h"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "nlohmann/json.hpp"
#include "pfdm/atomic_file.h"
#include "pfdm/clinical_summary.h"
#include "pfdm/vtk_writer.h"

namespace pfdm {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kSurfaceRings = 33;
constexpr int kSurfaceMeridians = 48;

constexpr const char* kGaugeConvention =
    "a0 (scale) is set on frame 0 so that the model, a3 = 0.8 there, spans "
    "the data from its fitted apex to the highest point along the axis, and "
    "is held afterwards; the pose is fitted on frame 0 with tau = 0 and no "
    "bending, the axis being the least-squares line of the ring centres "
    "(offsets e1o, e2o with zero mean and zero linear trend over the knots), "
    "and held in later frames, so tau(u, t) is rotation about the LV axis "
    "relative to frame 0 and offsets, bending and a1..a3 are motion relative "
    "to frame 0's axis.";

bool IsLength(int f) {
  return f == kA0 || f == kA1 || f == kA2 || f == kA3 || f == kB0 ||
         f == kB2 || f == kE1o || f == kE2o || f == kE3o;
}

// Function value in its reported unit (see ParametersCsv).
double Reported(const Model& model, int f, double u) {
  const double value = model.FunctionAt(f, u);
  if (f == kA1 || f == kA2 || f == kA3) return value * model.state.globals[kA0];
  return value;
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

}  // namespace

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
            << KnotRingZ(model, u) << ',' << Reported(model, f, u) << '\n';
      }
    }
  }
  return out.str();
}

std::string FitJson(const PointSequence& points, const SequenceFit& fit,
                    const FitOptions& options) {
  using json = nlohmann::ordered_json;
  json settings = {{"points", points.source},
                   {"smoothness_weight", options.smoothness_weight},
                   {"prior_weight", options.prior_weight},
                   {"loss", options.loss},
                   {"loss_scale_mm", options.loss_scale_mm},
                   {"max_correspondence_rounds",
                    options.max_correspondence_rounds},
                   {"correspondence_tolerance_mm",
                    options.correspondence_tolerance_mm},
                   {"max_iterations", options.solver.max_iterations},
                   {"threads", options.solver.num_threads}};
  if (options.hint) {
    const auto& h = *options.hint;
    settings["apex_hint"] = {h.apex.x(), h.apex.y(), h.apex.z()};
    settings["base_hint"] = {h.base_center.x(), h.base_center.y(),
                             h.base_center.z()};
  }
  json functions = json::object();
  for (int f = 0; f < kNumFunctions; ++f) {
    functions[FunctionName(f)] = {
        {"mode", ModeName(fit.config.modes[f])},
        {"unit", f == kTau ? "rad" : IsLength(f) ? "mm" : "1"}};
  }
  json model = {{"name", fit.config.name},
                {"knots", fit.config.num_knots},
                {"u_min", fit.config.u_min},
                {"u_max", fit.config.u_max},
                {"functions", functions}};

  json frames = json::array();
  const Model reference = fit.ModelAt(0);
  for (size_t t = 0; t < fit.frames.size(); ++t) {
    const FrameFit& frame = fit.frames[t];
    const Model current = fit.ModelAt(t);
    const ClinicalSummary summary = SummarizeFrame(frame.frame, reference,
                                                   current);
    frames.push_back(
        {{"frame", frame.frame},
         {"n_points", frame.residuals.size()},
         {"rms_mm", frame.rms_mm},
         {"mean_distance_mm", frame.mean_distance_mm},
         {"max_distance_mm", frame.max_distance_mm},
         {"iterations", frame.iterations},
         {"correspondence_rounds", frame.correspondence_rounds},
         {"solve_seconds", frame.solve_seconds},
         {"termination", frame.termination},
         {"pose",
          {{"center_mm", frame.state.center},
           {"quaternion_wxyz", frame.state.quaternion}}},
         {"clinical",
          {{"net_twist_deg", summary.net_twist_deg},
           {"apex_rotation_deg", summary.apex_rotation_deg},
           {"base_rotation_deg", summary.base_rotation_deg},
           {"radial_contraction_x_percent",
            summary.radial_contraction_x_percent},
           {"radial_contraction_y_percent",
            summary.radial_contraction_y_percent},
           {"longitudinal_shortening_percent",
            summary.longitudinal_shortening_percent},
           {"radial_ratio_x_per_knot", summary.radial_ratio_x},
           {"radial_ratio_y_per_knot", summary.radial_ratio_y},
           {"longitudinal_ratio_per_knot", summary.longitudinal_ratio}}}});
  }
  json document = {{"pfdm_version", "0.1.0"},
                   {"settings", settings},
                   {"model", model},
                   {"gauge_convention", kGaugeConvention},
                   {"frames", frames}};
  return document.dump(2) + "\n";
}

std::string FrameVtk(const Model& model, const Frame& frame,
                     const FrameFit& fit) {
  VtkPolyData data;
  std::vector<double> u_values, v_values, is_data;
  std::vector<Eigen::Vector3d> residuals;
  for (int i = 0; i < kSurfaceRings; ++i) {
    const double u = model.config.u_min +
                     (model.config.u_max - model.config.u_min) * i /
                         (kSurfaceRings - 1);
    for (int j = 0; j < kSurfaceMeridians; ++j) {
      const double v = -kPi + 2.0 * kPi * j / kSurfaceMeridians;
      data.points.push_back(model.WorldPoint(u, v));
      u_values.push_back(u);
      v_values.push_back(v);
      is_data.push_back(0.0);
      residuals.push_back(Eigen::Vector3d::Zero());
    }
  }
  for (int i = 0; i + 1 < kSurfaceRings; ++i) {
    for (int j = 0; j < kSurfaceMeridians; ++j) {
      const int a = i * kSurfaceMeridians + j;
      const int b = i * kSurfaceMeridians + (j + 1) % kSurfaceMeridians;
      data.triangles.push_back({a, b, b + kSurfaceMeridians});
      data.triangles.push_back({a, b + kSurfaceMeridians, a + kSurfaceMeridians});
    }
  }
  for (size_t i = 0; i < frame.points.size(); ++i) {
    data.vertices.push_back(static_cast<int>(data.points.size()));
    data.points.push_back(frame.points[i].position);
    u_values.push_back(fit.material[i].u);
    v_values.push_back(fit.material[i].v);
    is_data.push_back(1.0);
    residuals.push_back(fit.residuals[i]);
  }
  data.point_scalars = {{"u", u_values}, {"v", v_values}, {"is_data", is_data}};
  data.point_vectors = {{"residual", residuals}};
  return ToLegacyVtk(data, "pfdm frame " + std::to_string(frame.index));
}

void WriteFitOutputs(const std::string& dir, const PointSequence& points,
                     const SequenceFit& fit, const FitOptions& options) {
  // Everything is rendered before the first file is written, so a failure
  // leaves no partial set behind.
  std::vector<std::pair<std::string, std::string>> files;
  files.emplace_back("fit.json", FitJson(points, fit, options));
  std::vector<Model> models;
  for (size_t t = 0; t < fit.frames.size(); ++t) models.push_back(fit.ModelAt(t));
  files.emplace_back("parameters.csv", ParametersCsv(models));
  for (size_t t = 0; t < fit.frames.size(); ++t) {
    char name[32];
    std::snprintf(name, sizeof(name), "frame_%03d.vtk", fit.frames[t].frame);
    files.emplace_back(name, FrameVtk(models[t], points.frames[t], fit.frames[t]));
  }
  EnsureDirectory(dir);
  for (const auto& [name, contents] : files) {
    WriteFileAtomically(dir + "/" + name, contents);
  }
}

}  // namespace pfdm
