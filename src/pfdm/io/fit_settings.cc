#include "pfdm/io/fit_settings.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
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

// A length measured from the data: 0.397, 39.7, 39692.
std::string ShowMm(double value) {
  char text[32];
  std::snprintf(text, sizeof(text), value >= 100.0 ? "%.0f" : "%.3g", value);
  return text;
}

// Written so that NaN fails: "--FLAG must be between RANGE, got V".
double InRange(const char* flag, double value, double low, double high,
               const std::string& range) {
  if (!(value >= low && value <= high)) {
    throw InputError(std::string("--") + flag + " must be between " + range +
                     ", got " + Show(value));
  }
  return value;
}

int IntInRange(const char* flag, int value, int low, int high) {
  if (value < low || value > high) {
    throw InputError(std::string("--") + flag + " must be between " +
                     std::to_string(low) + " and " + std::to_string(high) +
                     ", got " + std::to_string(value));
  }
  return value;
}

// A finite weight in [0, 1e6]: beyond that the square roots Ceres is given
// overflow and the data no longer count.
double Weight(const char* flag, double value) {
  return InRange(flag, value, 0.0, 1e6, "0 and 1e6");
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

void SetSolverOptions(const FitSettings& s, FitOptions* options) {
  options->solver.num_threads = IntInRange("threads", s.threads, 1, 256);
  options->solver.kind = SolverFromName(s.solver);
  if (!ceres::StringToLinearSolverType(s.linear_solver,
                                       &options->solver.linear_solver)) {
    throw InputError("unknown --linear_solver '" + s.linear_solver + "'");
  }
  // 1e-300 once "converged" on a step lost in rounding, the model unmoved.
  if (!(s.time_step == 0.0 || (s.time_step >= 1e-6 && s.time_step <= 1e12))) {
    throw InputError(
        "--time_step must be 0 (default) or between 1e-6 and 1e12, got " +
        Show(s.time_step));
  }
  options->solver.time_step = s.time_step;
  // 1e308 stopped the integrator at once; 0.1 already stops it a frame
  // 2.3 mm RMS short of 0.74 mm (0.01: 0.90 mm).  Below 1e-12 it would
  // only ever stop at --max_steps.
  options->solver.rest_tolerance = InRange("rest_tolerance", s.rest_tolerance,
                                           1e-12, 0.01, "1e-12 and 0.01");
  // The default 20,000 steps per solve are a few seconds; 50 times as many
  // is as long as anyone waits.
  options->solver.max_steps = IntInRange("max_steps", s.max_steps, 1, 1000000);
  options->solver.damping = DampingFromName(s.damping);
  options->solver.integrator = IntegratorFromName(s.integrator);
  options->damping_groups = DampingGroupsFromText(s.damping_scale);
}

void SetLocalOptions(const FitSettings& s, FitOptions* options) {
  options->local.enabled = s.local == "on";
  options->local.transmural = s.local_transmural == "on";
  const LocalGrid grid = ParseLocalGrid(Clip(s.local_grid));
  options->local.rows = grid.rows;
  options->local.cols = grid.cols;
  // 0 leaves the field free where the data do not hold it: 67,888 ml on the
  // model phantom's 500 tags, 1e-8 already 189 ml where the default gives
  // 116 (1e-4: within 0.1 ml of the default's).
  options->local.stiffness =
      InRange("local_stiffness", s.local_stiffness, 1e-4, 1e6,
              "1e-4 and 1e6 (--local off: no local deformations)");
}

void SetAxisHint(const FitSettings& s, FitOptions* options) {
  if (s.apex.empty() != s.base.empty()) {
    throw InputError("--apex and --base go together");
  }
  if (s.apex.empty()) return;
  options->hint =
      AxisHint{ParsePoint("apex", s.apex), ParsePoint("base", s.base)};
  if ((options->hint->apex - options->hint->base_center).norm() < 1.0) {
    throw InputError("--apex and --base must be at least 1 mm apart");
  }
}

// A setting that the chosen solver, loss or local field does not use was
// once ignored without a word (`--time_step` with the direct solver); it is
// refused instead.  Told from the default by its value, so that the CLI and
// the Python keywords refuse alike; compare-solvers runs every solver.
void CheckSettingsApply(const FitSettings& s, bool every_solver) {
  const FitSettings d;
  const bool dynamics = every_solver || s.solver != "direct";
  const bool integrator = every_solver || s.solver == "integrator";
  const bool ceres_solve = every_solver || s.solver != "integrator";
  struct Use {
    const char* flag;
    bool given;
    bool applies;
    const char* needs;
    std::string chosen;
  };
  const std::string solver = "--solver " + s.solver;
  const Use uses[] = {
      {"time_step", s.time_step != d.time_step, dynamics,
       "--solver damped or integrator", solver},
      {"rest_tolerance", s.rest_tolerance != d.rest_tolerance, dynamics,
       "--solver damped or integrator", solver},
      {"max_steps", s.max_steps != d.max_steps, dynamics,
       "--solver damped or integrator", solver},
      {"damping", s.damping != d.damping, integrator, "--solver integrator",
       solver},
      {"integrator", s.integrator != d.integrator, integrator,
       "--solver integrator", solver},
      {"damping_scale", s.damping_scale != d.damping_scale, integrator,
       "--solver integrator", solver},
      {"linear_solver", s.linear_solver != d.linear_solver, ceres_solve,
       "--solver direct or damped", solver},
      {"loss_scale", s.loss_scale != d.loss_scale, s.loss != "none",
       "--loss huber or cauchy", "--loss " + s.loss},
      {"local_grid", s.local_grid != d.local_grid, s.local == "on",
       "--local on", "--local " + s.local},
      {"local_stiffness", s.local_stiffness != d.local_stiffness,
       s.local == "on", "--local on", "--local " + s.local},
      {"local_transmural", s.local_transmural != d.local_transmural,
       s.local == "on", "--local on", "--local " + s.local},
  };
  for (const Use& use : uses) {
    if (use.given && !use.applies) {
      throw InputError(std::string("--") + use.flag + " applies to " +
                       use.needs + ", not " + use.chosen);
    }
  }
}

// --surface declares one surface (FitOptions::surface); a solid has two.
void SetSurface(const FitSettings& s, FitOptions* options) {
  const SurfaceChoice choices[] = {
      SurfaceChoice::kAuto, SurfaceChoice::kEndocardium,
      SurfaceChoice::kMidwall, SurfaceChoice::kEpicardium};
  const auto it = std::find_if(
      std::begin(choices), std::end(choices),
      [&](SurfaceChoice c) { return s.surface == SurfaceChoiceName(c); });
  if (it == std::end(choices)) {
    throw InputError("--surface must be auto, endo, midwall or epi, got '" +
                     Clip(s.surface) + "'");
  }
  options->surface = *it;
  if (*it != SurfaceChoice::kAuto && options->wall == WallModel::kSolid) {
    throw InputError("--surface " + s.surface +
                     " declares one surface; --wall solid fits two");
  }
  if (s.ed_frame < 0) {
    throw InputError("--ed_frame must be a frame number from 0, got " +
                     std::to_string(s.ed_frame));
  }
  options->ed_frame = s.ed_frame;
}

FitOptions OptionsFrom(const FitSettings& s, bool every_solver) {
  FitOptions options;
  options.smoothness_weight = Weight("smoothness", s.smoothness);
  options.prior_weight = Weight("prior", s.prior);
  options.untracked_prior_weight = Weight("untracked_prior", s.untracked_prior);
  options.untracked_prior_covered_radii_scale = InRange(
      "untracked_prior_radii", s.untracked_prior_radii, 0.0, 1.0, "0 and 1");
  options.temporal_prior_weight = Weight("temporal_prior", s.temporal_prior);
  options.incompressible_weight = Weight("incompressible", s.incompressible);
  options.wall = WallModelFromName(s.wall);
  CheckLossName(s.loss);
  SetSurface(s, &options);
  options.loss = s.loss;
  // The choices the other settings depend on, then whether those apply,
  // then their values.
  SolverFromName(s.solver);
  if (s.local != "on" && s.local != "off") {
    throw InputError("--local must be on or off, got '" + Clip(s.local) + "'");
  }
  if (s.local_transmural != "on" && s.local_transmural != "off") {
    throw InputError("--local_transmural must be on or off, got '" +
                     Clip(s.local_transmural) + "'");
  }
  if (s.tag_depths != "held" && s.tag_depths != "ranked") {
    throw InputError("--tag_depths must be held or ranked, got '" +
                     Clip(s.tag_depths) + "'");
  }
  options.hold_tag_depths = s.tag_depths == "held";
  if (s.uncertainty != "on" && s.uncertainty != "off") {
    throw InputError("--uncertainty must be on or off, got '" +
                     Clip(s.uncertainty) + "'");
  }
  options.uncertainty = s.uncertainty == "on";
  CheckSettingsApply(s, every_solver);
  // A number is bounded further by the data's scale
  // (CheckOptionsAgainstPoints).
  options.loss_scale_auto = s.loss_scale == "auto";
  if (!options.loss_scale_auto) options.loss_scale_mm = LossScale(s.loss_scale);
  SetSolverOptions(s, &options);
  options.jacobian = JacobianFromName(s.jacobian);
  SetLocalOptions(s, &options);
  SetAxisHint(s, &options);
  return options;
}

std::string ShowPoint(const Eigen::Vector3d& p) {
  return Show(p.x()) + "," + Show(p.y()) + "," + Show(p.z());
}

}  // namespace

ModelConfig ModelConfigFrom(const FitSettings& settings) {
  return ModelConfig::FromName(settings.model, settings.knots);
}

FitOptions FitOptionsFrom(const FitSettings& settings) {
  return OptionsFrom(settings, false);
}

FitOptions FitOptionsForEverySolver(const FitSettings& settings) {
  return OptionsFrom(settings, true);
}

void CheckOptionsAgainstPoints(const FitOptions& options,
                               const PointSequence& points) {
  if (!points.frames.empty() &&
      options.ed_frame >= static_cast<int>(points.frames.size())) {
    throw InputError("--ed_frame " + std::to_string(options.ed_frame) +
                     " is not a frame of " + points.source + " (frames 0 to " +
                     std::to_string(points.frames.size() - 1) + ")");
  }
  // Too few points, or all at one place, are the data's fault, which the
  // fit's start names (StartSequence): no scale to measure here.
  if (points.frames.empty() ||
      static_cast<int>(points.frames[0].points.size()) < options.min_points) {
    return;
  }
  const std::vector<DataPoint>& frame0 = points.frames[0].points;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const DataPoint& p : frame0) centre += p.position;
  centre /= static_cast<double>(frame0.size());
  double sum_squares = 0.0, farthest = 0.0;
  for (const DataPoint& p : frame0) {
    const double r = (p.position - centre).norm();
    sum_squares += r * r;
    farthest = std::max(farthest, r);
  }
  const double rms_radius = std::sqrt(sum_squares / frame0.size());
  if (!(rms_radius > 1e-6)) return;
  // Cauchy at 1e12 mm, or at 0.1 mm on tags with 0.5 mm noise (RMS radius
  // 39.7 mm), left the model near its start: a scale is a residual's size,
  // between a tag's noise and the heart's.  A scale measured from the data
  // (--loss_scale auto) is not checked: it is measured per frame.
  if (options.loss != "none" && !options.loss_scale_auto) {
    InRange("loss_scale", options.loss_scale_mm, 1e-2 * rms_radius,
            1e3 * rms_radius,
            ShowMm(1e-2 * rms_radius) + " and " + ShowMm(1e3 * rms_radius) +
                " mm (1e-2 to 1e3 times the RMS radius of frame 0's points, " +
                ShowMm(rms_radius) + " mm)");
  }
  if (!options.hint) return;
  // 900000,0,0 gave an EDV of 3.6e12 ml.  An apex lies at the data's edge,
  // a base centre inside: twice the farthest point is room enough.
  const double reach = 2.0 * farthest;
  const std::pair<const char*, Eigen::Vector3d> hints[] = {
      {"apex", options.hint->apex}, {"base", options.hint->base_center}};
  for (const auto& [flag, point] : hints) {
    const double distance = (point - centre).norm();
    if (distance > reach) {
      throw InputError(
          std::string("--") + flag + " must lie within " + ShowMm(reach) +
          " mm of the centroid of frame 0's points (twice the "
          "farthest point's distance), got " +
          ShowPoint(point) + ", " + ShowMm(distance) + " mm from it");
    }
  }
}

VtkOutput VtkOutputFrom(const FitSettings& settings) {
  return VtkOutputFromNames(settings.vtk_format, settings.vtk_precision);
}

std::vector<BasePlane> BasePlanesFrom(const FitSettings& settings,
                                      const std::string& points) {
  if (settings.base_plane == "rim") return {};
  if (settings.base_plane != "auto") {
    throw InputError("unknown --base_plane '" + settings.base_plane +
                     "' (expected auto or rim)");
  }
  if (points.empty()) return {};
  return MitralValvePlanes(points, settings.format);
}

}  // namespace pfdm
