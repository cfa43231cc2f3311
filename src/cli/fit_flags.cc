// Flags shared by the commands that read points and fit.
#include <filesystem>
#include <sstream>

#include "commands.h"
#include "pfdm/error.h"
#include "pfdm/point_reader.h"
#include "pfdm/solver.h"

DEFINE_string(points, "",
              "input points: a frame,id,x,y,z CSV, or a biv-me "
              "GPFile_*.txt or a folder of them");
DEFINE_string(format, "auto", "csv, gpfile or auto (by name)");
DEFINE_string(contours, "lv-endo",
              "GPFile contour types to keep, "
              "comma-separated; lv-endo and lv-epi are aliases");
DEFINE_string(out, "", "output folder (simulate: output CSV)");
DEFINE_string(model, "paper", "paper or superellipsoid");
DEFINE_int32(knots, 17, "knots per parameter function");
DEFINE_double(smoothness, 1.0,
              "smoothness weight, relative to one knot's data");
DEFINE_double(prior, 0.001, "pull toward the previous frame, same units");
DEFINE_string(loss, "none", "none, huber or cauchy");
DEFINE_double(loss_scale, 1.0, "robust loss scale, mm");
DEFINE_int32(threads, 1, "Ceres threads");
DEFINE_string(apex, "", "optional apex hint x,y,z (mm), with --base");
DEFINE_string(base, "", "optional base-centre hint x,y,z (mm), with --apex");
DEFINE_string(solver, "direct", "direct, damped or integrator");
DEFINE_string(jacobian, "analytic", "analytic, autodiff or numeric");

namespace pfdm {
namespace {

Eigen::Vector3d ParsePoint(const std::string& flag, const std::string& text) {
  Eigen::Vector3d point;
  std::istringstream in(text);
  char comma1 = 0, comma2 = 0;
  in >> point.x() >> comma1 >> point.y() >> comma2 >> point.z();
  if (!in || comma1 != ',' || comma2 != ',' || !(in >> std::ws).eof() ||
      !point.allFinite()) {
    throw InputError("--" + flag + " must be x,y,z in mm, got '" + text + "'");
  }
  return point;
}

}  // namespace

PointSequence PointsFromFlags() {
  if (FLAGS_points.empty()) throw InputError("--points FILE is required");
  std::string format = FLAGS_format;
  if (format == "auto") {
    const std::filesystem::path path(FLAGS_points);
    format = std::filesystem::is_directory(path) ||
                     path.filename().string().rfind("GPFile", 0) == 0
                 ? "gpfile"
                 : "csv";
  }
  if (format == "csv") return ReadPointsCsv(FLAGS_points);
  if (format == "gpfile") {
    return ReadGpFiles(FLAGS_points, ExpandContourAlias(FLAGS_contours));
  }
  throw InputError("unknown --format '" + FLAGS_format +
                   "' (expected csv, gpfile or auto)");
}

ModelConfig ModelConfigFromFlags() {
  return ModelConfig::FromName(FLAGS_model, FLAGS_knots);
}

FitOptions FitOptionsFromFlags() {
  FitOptions options;
  options.smoothness_weight = FLAGS_smoothness;
  options.prior_weight = FLAGS_prior;
  options.loss = FLAGS_loss;
  options.loss_scale_mm = FLAGS_loss_scale;
  options.solver.num_threads = FLAGS_threads;
  options.solver.kind = SolverFromName(FLAGS_solver);
  options.jacobian = JacobianFromName(FLAGS_jacobian);
  if (FLAGS_apex.empty() != FLAGS_base.empty()) {
    throw InputError("--apex and --base go together");
  }
  if (!FLAGS_apex.empty()) {
    options.hint = AxisHint{ParsePoint("apex", FLAGS_apex),
                            ParsePoint("base", FLAGS_base)};
  }
  return options;
}

}  // namespace pfdm
