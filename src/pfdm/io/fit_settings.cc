#include "pfdm/io/fit_settings.h"

#include <cmath>
#include <sstream>

#include "ceres/types.h"
#include "pfdm/io/mitral_valve_planes.h"
#include "pfdm/solvers/damping_groups.h"
#include "pfdm/util/error.h"

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

ModelConfig ModelConfigFrom(const FitSettings& settings) {
  return ModelConfig::FromName(settings.model, settings.knots);
}

FitOptions FitOptionsFrom(const FitSettings& s) {
  FitOptions options;
  options.smoothness_weight = s.smoothness;
  options.prior_weight = s.prior;
  options.loss = s.loss;
  options.loss_scale_mm = s.loss_scale;
  options.solver.num_threads = s.threads;
  options.solver.kind = SolverFromName(s.solver);
  if (!ceres::StringToLinearSolverType(s.linear_solver,
                                       &options.solver.linear_solver)) {
    throw InputError("unknown --linear_solver '" + s.linear_solver + "'");
  }
  if (!(s.time_step >= 0.0) || !std::isfinite(s.time_step)) {
    throw InputError("--time_step must be 0 (default) or positive");
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
  if (s.apex.empty() != s.base.empty()) {
    throw InputError("--apex and --base go together");
  }
  if (!s.apex.empty()) {
    options.hint =
        AxisHint{ParsePoint("apex", s.apex), ParsePoint("base", s.base)};
  }
  return options;
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
