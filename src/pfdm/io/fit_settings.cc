#include "pfdm/io/fit_settings.h"

#include <cmath>
#include <cstdlib>
#include <sstream>

#include "ceres/types.h"
#include "pfdm/fit/residuals/robust_loss.h"
#include "pfdm/io/mitral_valve_planes.h"
#include "pfdm/model/local_field.h"
#include "pfdm/solvers/damping_groups.h"
#include "pfdm/util/error.h"
#include "pfdm/util/input_file.h"

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

// A --loss_scale number: positive and finite (scale 0 once left the model
// unmoved with exit 0).
double LossScale(const std::string& text) {
  char* end = nullptr;
  const double scale = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !(scale > 0.0) ||
      !std::isfinite(scale)) {
    throw InputError(
        "--loss_scale must be auto or a positive number of mm, got '" +
        Clip(text) + "'");
  }
  return scale;
}

}  // namespace

ModelConfig ModelConfigFrom(const FitSettings& settings) {
  return ModelConfig::FromName(settings.model, settings.knots);
}

FitOptions FitOptionsFrom(const FitSettings& s) {
  FitOptions options;
  options.smoothness_weight = Weight("smoothness", s.smoothness);
  options.prior_weight = Weight("prior", s.prior);
  options.untracked_prior_weight = Weight("untracked_prior", s.untracked_prior);
  options.wall = WallModelFromName(s.wall);
  CheckLossName(s.loss);
  options.loss = s.loss;
  options.loss_scale_auto = s.loss_scale == "auto";
  if (!options.loss_scale_auto) options.loss_scale_mm = LossScale(s.loss_scale);
  if (s.threads < 1 || s.threads > 256) {
    throw InputError("--threads must be between 1 and 256, got " +
                     std::to_string(s.threads));
  }
  options.solver.num_threads = s.threads;
  options.solver.kind = SolverFromName(s.solver);
  if (!ceres::StringToLinearSolverType(s.linear_solver,
                                       &options.solver.linear_solver)) {
    throw InputError("unknown --linear_solver '" + s.linear_solver + "'");
  }
  // 1e-300 once "converged" on a step lost in rounding, the model unmoved.
  if (!(s.time_step == 0.0 || (s.time_step >= 1e-6 && s.time_step <= 1e12))) {
    throw InputError(
        "--time_step must be 0 (default) or between 1e-6 and 1e12, got " +
        Show(s.time_step));
  }
  options.solver.time_step = s.time_step;
  if (!(s.rest_tolerance > 0.0) || !std::isfinite(s.rest_tolerance)) {
    throw InputError("--rest_tolerance must be positive");
  }
  options.solver.rest_tolerance = s.rest_tolerance;
  if (s.max_steps < 1) throw InputError("--max_steps must be at least 1");
  options.solver.max_steps = s.max_steps;
  options.solver.damping = DampingFromName(s.damping);
  options.damping_groups = DampingGroupsFromText(s.damping_scale);
  options.jacobian = JacobianFromName(s.jacobian);
  if (s.local != "on" && s.local != "off") {
    throw InputError("--local must be on or off, got '" + Clip(s.local) + "'");
  }
  options.local.enabled = s.local == "on";
  const LocalGrid grid = ParseLocalGrid(Clip(s.local_grid));
  options.local.rows = grid.rows;
  options.local.cols = grid.cols;
  options.local.stiffness = Weight("local_stiffness", s.local_stiffness);
  if (s.apex.empty() != s.base.empty()) {
    throw InputError("--apex and --base go together");
  }
  if (!s.apex.empty()) {
    options.hint =
        AxisHint{ParsePoint("apex", s.apex), ParsePoint("base", s.base)};
    if ((options.hint->apex - options.hint->base_center).norm() < 1.0) {
      throw InputError("--apex and --base must be at least 1 mm apart");
    }
  }
  return options;
}

VtkFormat VtkFormatFrom(const FitSettings& settings) {
  return VtkFormatFromName(settings.vtk_format);
}

std::vector<BasePlane> BasePlanesFrom(const FitSettings& settings,
                                      const std::string& points) {
  if (settings.base_plane == "rim") return {};
  if (settings.base_plane != "auto") {
    throw InputError("unknown --base_plane '" + settings.base_plane +
                     "' (expected auto or rim)");
  }
  if (points.empty()) return {};
  return MitralValvePlanes(points);
}

}  // namespace pfdm
