// Flags shared by the commands that read points and fit.
#include <cmath>
#include <sstream>

#include "ceres/types.h"
#include "pfdm/cli/commands.h"
#include "pfdm/io/point_source.h"
#include "pfdm/solvers/solver.h"
#include "pfdm/util/error.h"
#include "pfdm/util/input_file.h"

DEFINE_string(points, "",
              "input points: a frame,id,x,y,z CSV, or a biv-me "
              "GPFile_*.txt or a folder of them");
DEFINE_string(format, "auto", "csv, gpfile or auto (by name)");
DEFINE_string(contours, "lv-cavity",
              "GPFile contour types to keep, comma-separated; lv-endo, "
              "lv-epi and lv-cavity (lv-endo and AORTA_VALVE) are aliases");
DEFINE_string(out, "", "output folder (simulate: output CSV)");
DEFINE_string(model, "paper", "paper or superellipsoid");
DEFINE_int32(knots, 17, "knots per parameter function, 2 to 100");
DEFINE_double(smoothness, 1.0,
              "smoothness weight, relative to one knot's data, 0 to 1e6");
DEFINE_double(prior, 0.001,
              "pull toward the previous frame, same units, 0 to 1e6");
DEFINE_string(loss, "none", "none, huber or cauchy");
DEFINE_double(loss_scale, 1.0, "robust loss scale, mm, positive");
DEFINE_int32(threads, 1, "Ceres threads, 1 to 256");
DEFINE_string(apex, "", "optional apex hint x,y,z (mm), with --base");
DEFINE_string(base, "", "optional base-centre hint x,y,z (mm), with --apex");
DEFINE_string(solver, "direct", "direct, damped or integrator");
DEFINE_string(linear_solver, "SPARSE_NORMAL_CHOLESKY",
              "Ceres linear solver, e.g. SPARSE_NORMAL_CHOLESKY, "
              "DENSE_NORMAL_CHOLESKY, DENSE_QR");
DEFINE_double(time_step, 0.0,
              "damped and integrator: pseudo-time step, 1e-6 to 1e12; 0 = "
              "default (integrator: 0.9 of its stability bound, damped: "
              "1000)");
DEFINE_double(rest_tolerance, pfdm::SolverOptions().rest_tolerance,
              "damped and integrator: at rest when the energy dissipated per "
              "unit pseudo-time is below rest_tolerance^2 of the initial");
DEFINE_int32(max_steps, pfdm::SolverOptions().max_steps,
             "damped and integrator: most steps per solve");
DEFINE_string(damping, "jacobi",
              "integrator: damping D = jacobi (diag J^T J) or unit");
DEFINE_string(damping_scale, "",
              "integrator: multipliers of D per group, e.g. "
              "twist=10,offsets=2 (groups pose shape twist bending offsets)");
DEFINE_string(jacobian, "analytic", "analytic, autodiff or numeric");

namespace pfdm {
namespace {

Eigen::Vector3d ParsePoint(const std::string& flag, const std::string& text) {
  Eigen::Vector3d point;
  std::istringstream in(text);
  char comma1 = 0, comma2 = 0;
  in >> point.x() >> comma1 >> point.y() >> comma2 >> point.z();
  if (!in || comma1 != ',' || comma2 != ',' || !(in >> std::ws).eof() ||
      !point.allFinite() || point.cwiseAbs().maxCoeff() > kMaxCoordinateMm) {
    throw InputError("--" + flag + " must be x,y,z in mm, got '" + Clip(text) +
                     "'");
  }
  return point;
}

// A number as typed, short (std::to_string gives 1e308 in 309 digits).
std::string Show(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

// A finite weight in [0, 1e6]: beyond that the square roots Ceres is given
// overflow and the data no longer count.
double Weight(const char* flag, double value) {
  if (!(value >= 0.0 && value <= 1e6)) {
    throw InputError(std::string("--") + flag +
                     " must be between 0 and 1e6, got " + Show(value));
  }
  return value;
}

}  // namespace

PointSequence PointsFromFlags() {
  if (FLAGS_points.empty()) throw InputError("--points FILE is required");
  return ReadPoints(FLAGS_points, FLAGS_format, FLAGS_contours);
}

ModelConfig ModelConfigFromFlags() {
  return ModelConfig::FromName(FLAGS_model, FLAGS_knots);
}

FitOptions FitOptionsFromFlags() {
  FitOptions options;
  options.smoothness_weight = Weight("smoothness", FLAGS_smoothness);
  options.prior_weight = Weight("prior", FLAGS_prior);
  options.loss = FLAGS_loss;
  // Scale 0 once left the model unmoved with exit 0.
  if (!(FLAGS_loss_scale > 0.0) || !std::isfinite(FLAGS_loss_scale)) {
    throw InputError("--loss_scale must be a positive number of mm, got " +
                     Show(FLAGS_loss_scale));
  }
  options.loss_scale_mm = FLAGS_loss_scale;
  if (FLAGS_threads < 1 || FLAGS_threads > 256) {
    throw InputError("--threads must be between 1 and 256, got " +
                     std::to_string(FLAGS_threads));
  }
  options.solver.num_threads = FLAGS_threads;
  options.solver.kind = SolverFromName(FLAGS_solver);
  if (!ceres::StringToLinearSolverType(FLAGS_linear_solver,
                                       &options.solver.linear_solver)) {
    throw InputError("unknown --linear_solver '" + FLAGS_linear_solver + "'");
  }
  // 1e-300 once "converged" on a step lost in rounding, the model unmoved.
  if (!(FLAGS_time_step == 0.0 ||
        (FLAGS_time_step >= 1e-6 && FLAGS_time_step <= 1e12))) {
    throw InputError(
        "--time_step must be 0 (default) or between 1e-6 and 1e12, got " +
        Show(FLAGS_time_step));
  }
  options.solver.time_step = FLAGS_time_step;
  if (!(FLAGS_rest_tolerance > 0.0) || !std::isfinite(FLAGS_rest_tolerance)) {
    throw InputError("--rest_tolerance must be positive");
  }
  options.solver.rest_tolerance = FLAGS_rest_tolerance;
  if (FLAGS_max_steps < 1) throw InputError("--max_steps must be at least 1");
  options.solver.max_steps = FLAGS_max_steps;
  options.solver.damping = DampingFromName(FLAGS_damping);
  options.damping_groups = DampingGroupsFromText(FLAGS_damping_scale);
  options.jacobian = JacobianFromName(FLAGS_jacobian);
  if (FLAGS_apex.empty() != FLAGS_base.empty()) {
    throw InputError("--apex and --base go together");
  }
  if (!FLAGS_apex.empty()) {
    options.hint = AxisHint{ParsePoint("apex", FLAGS_apex),
                            ParsePoint("base", FLAGS_base)};
    if ((options.hint->apex - options.hint->base_center).norm() < 1.0) {
      throw InputError("--apex and --base must be at least 1 mm apart");
    }
  }
  return options;
}

}  // namespace pfdm
