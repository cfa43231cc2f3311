#include "pfdm/io/fit_output.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <regex>
#include <sstream>
#include <utility>

#include "pfdm/io/fit_json.h"
#include "pfdm/io/vtp_writer.h"
#include "pfdm/model/model_surface.h"
#include "pfdm/report/bullseye_plot.h"
#include "pfdm/report/fit_plots.h"
#include "pfdm/report/fit_report.h"
#include "pfdm/report/material_rings.h"
#include "pfdm/util/angles.h"
#include "pfdm/util/atomic_file.h"
#include "pfdm/util/error.h"

namespace pfdm {
namespace {

bool IsLength(int f) {
  return f == kA0 || f == kA1 || f == kA2 || f == kA3 || f == kB0 || f == kB2 ||
         f == kE1o || f == kE2o || f == kE3o || f == kH || f == kWallShift ||
         f == kWallSqueeze;
}

const std::regex& OutputNamePattern() {
  static const std::regex pattern(
      "(fit\\.json|parameters\\.csv|parameters\\.svg|report\\.html|"
      "slices\\.svg|"
      "fit\\.pvd|frame_[0-9]+\\.vtk|frame_[0-9]+\\.vtp)(\\.tmp\\.[A-Za-z0-9.-]+"
      ")?");
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

// A folder where a file goes, of the older set or the new one (names),
// stops the write before anything is touched.
void RefuseFoldersInTheWay(const std::string& dir,
                           const std::vector<std::string>& names) {
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
}

// No fit.json, no set: from here until the new one is in place a kill, or
// a failure, leaves a folder that says "not done".  The older set goes
// first: new files written while it was still there (to keep it until
// gnuplot had finished) made the writing of 50,000 tags' meshes take
// half as long again.
void RemoveOlderSet(const std::string& dir) {
  RemoveOutputFile(dir, "fit.json");
  for (const std::string& name : OutputNamesIn(dir)) {
    RemoveOutputFile(dir, name);
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
  CheckFolderTakesFiles(dir, "fit.json");
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

double ReportedSd(const Model& model, const FrameCovariance& covariance, int f,
                  int k, double length_variance) {
  const int i = covariance.FunctionIndex(model.config, f, k);
  const auto variance = [&](int a, int b) {
    return a < 0 || b < 0 ? 0.0 : covariance.covariance(a, b);
  };
  if (f != kA1 && f != kA2 && f != kA3) return std::sqrt(variance(i, i));
  // d(a0 a_i) = a_i da0 + a0 da_i.
  const double a0 = model.state.globals[kA0];
  const double ai = model.FunctionAt(f, model.config.Grid().KnotU(k));
  const int j = covariance.FunctionIndex(model.config, kA0, k);
  const double length = f == kA3 ? a0 * a0 * ai * ai * length_variance : 0.0;
  return std::sqrt(std::max(0.0, a0 * a0 * variance(i, i) +
                                     ai * ai * variance(j, j) +
                                     2.0 * a0 * ai * variance(i, j) + length));
}

std::string ParametersCsv(const std::vector<Model>& frames,
                          const SequenceFit* fit) {
  std::ostringstream out;
  out.precision(10);
  out << "frame,function,knot,u,z_mm,value" << (fit ? ",sd" : "") << '\n';
  for (size_t t = 0; t < frames.size(); ++t) {
    const Model& model = frames[t];
    const KnotGrid grid = model.config.Grid();
    for (int f = 0; f < kNumFunctions; ++f) {
      for (int k = 0; k < grid.num_knots(); ++k) {
        const double u = grid.KnotU(k);
        out << t << ',' << FunctionName(f) << ',' << k << ',' << u << ','
            << RingHeight(model, u) << ',' << ReportedValue(model, f, u);
        if (fit != nullptr) {
          const FrameCovariance& covariance = fit->frames[t].covariance;
          out << ',';
          if (covariance.computed) {
            out << ReportedSd(model, covariance, f, k, LengthVariance(*fit, t));
          }
        }
        out << '\n';
      }
    }
  }
  return out.str();
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
  // For display: a flag, a weight and degrees to see the twist by.
  data.float32_scalars = {"is_data", "loss_weight", "twist_deg"};
  if (!fit.loss_weights.empty()) {
    // The surface's vertices weigh 1, as data points the loss trusts.
    std::vector<double> weights(data.points.size() - frame.points.size(), 1.0);
    weights.insert(weights.end(), fit.loss_weights.begin(),
                   fit.loss_weights.end());
    data.point_scalars.emplace_back("loss_weight", std::move(weights));
  }
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
                     const VtkOutput& vtk_output) {
  // gnuplot starts while the fit is analysed.
  SvgRendering plots;
  WriteFitOutputs(dir, points, fit, AnalyzeFit(fit, base_planes), options,
                  vtk_output, &plots);
}

void WriteFitOutputs(const std::string& dir, const PointSequence& points,
                     const SequenceFit& fit, const FitAnalysis& analysis,
                     const FitOptions& options, const VtkOutput& vtk_output,
                     SvgRendering* plots, const std::string& slices_svg) {
  // The frames' meshes are formatted and written while gnuplot renders the
  // plots (one gnuplot for both: its start-up, not the plotting, was
  // most of their time).
  std::vector<FrameCovariance> covariances;
  for (const FrameFit& frame : fit.frames) {
    covariances.push_back(frame.covariance);
  }
  plots->Render(
      {ParameterPlots(analysis.models, analysis.rotation_measured, covariances,
                      analysis.ejection_fraction.es_frame),
       Bullseye(analysis.regions, ClinicalBullseyeMaps(analysis))});
  std::vector<std::string> frame_names;
  std::vector<std::pair<double, std::string>> timesteps;
  for (const FrameFit& frame : fit.frames) {
    char name[32];
    std::snprintf(name, sizeof(name), "frame_%03d", frame.frame);
    frame_names.push_back(name);
    // ParaView's time: the trigger time (ms) where the input gave one.
    const bool timed = fit.time_ms.size() == fit.frames.size();
    timesteps.emplace_back(timed ? fit.time_ms[frame.frame] : frame.frame,
                           std::string(name) + ".vtp");
  }
  std::vector<std::string> names = {"parameters.csv", "parameters.svg",
                                    "report.html", "fit.json"};
  if (vtk_output.Vtp()) names.push_back("fit.pvd");
  for (const std::string& name : frame_names) {
    if (vtk_output.Vtk()) names.push_back(name + ".vtk");
    if (vtk_output.Vtp()) names.push_back(name + ".vtp");
  }
  if (!slices_svg.empty()) names.push_back("slices.svg");

  EnsureDirectory(dir);
  RefuseFoldersInTheWay(dir, names);
  CreateFileIfAbsent(dir + "/" + kOutputMarker, kOutputMarkerText);
  RemoveOlderSet(dir);
  std::vector<std::string> written;
  AtomicWriteOptions keep_listing_out;
  keep_listing_out.remove_abandoned = false;  // RemoveOlderSet did.
  const auto write = [&](const std::string& name, const std::string& contents) {
    WriteFileAtomically(dir + "/" + name, contents, keep_listing_out);
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
      if (vtk_output.Vtk()) {
        write(name + ".vtk",
              ToLegacyVtk(data, "pfdm " + name, vtk_output.format,
                          vtk_output.precision));
      }
      if (vtk_output.Vtp()) {
        write(name + ".vtp",
              ToVtkXmlPolyData(data, vtk_output.format, vtk_output.precision));
      }
    }
    write("parameters.csv", ParametersCsv(analysis.models, &fit));
    if (vtk_output.Vtp()) write("fit.pvd", PvdCollection(timesteps));
    const std::string json = FitJson(points, fit, options, analysis);
    const std::vector<std::string> svgs = plots->Finish();
    write("parameters.svg", svgs[0]);
    if (!slices_svg.empty()) write("slices.svg", slices_svg);
    write("report.html",
          FitReportHtml(points, fit, analysis, svgs[0], svgs[1], slices_svg));
    write("fit.json", json);  // Last: marks the set.
  } catch (const InputError&) {
    for (const std::string& name : written) {
      std::remove((dir + "/" + name).c_str());
    }
    throw;
  }
}

}  // namespace pfdm
