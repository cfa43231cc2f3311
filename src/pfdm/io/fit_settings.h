// pfdm fit's settings under their flag names, with the flags' defaults.
// The CLI fills them from its flags and the Python module from keyword
// arguments; both turn them into the library's options here, so that the
// names, defaults, checks and messages are the same.
#ifndef PFDM_IO_FIT_SETTINGS_H_
#define PFDM_IO_FIT_SETTINGS_H_

#include <string>
#include <vector>

#include "pfdm/fit/fit_options.h"
#include "pfdm/io/vtk_output.h"
#include "pfdm/model/base_plane.h"
#include "pfdm/model/model.h"
#include "pfdm/solvers/solver.h"
#include "pfdm/util/point_data.h"

namespace pfdm {

struct FitSettings {
  // Reading the points (ReadPoints) and closing the cavity.
  std::string format = "auto";
  std::string contours = "lv-cavity";
  std::string base_plane = "auto";
  // The AHA segments' anchor (io/rv_insertion_source.h): "x,y,z[,x,y,z]"
  // anterior, inferior; empty: guide points' RV_INSERT, if any.
  std::string rv_insertion;
  // The model.
  std::string model = "paper";
  int knots = 17;
  std::string wall = "auto";
  std::string surface = "auto";  // auto, endo, midwall or epi.
  int ed_frame = 0;
  // The fit.
  double smoothness = 1.0;
  double prior = 0.001;
  double untracked_prior = FitOptions().untracked_prior_weight;
  double untracked_prior_radii =
      FitOptions().untracked_prior_covered_radii_scale;
  double temporal_prior = FitOptions().temporal_prior_weight;
  double incompressible = FitOptions().incompressible_weight;
  std::string loss = "none";
  // "auto" (measured: fit/stages/loss_scale.h) or a number of mm; refused
  // with a loss of none.
  std::string loss_scale = "auto";
  int threads = 1;
  std::string apex;  // "x,y,z" in mm, with base; empty: from the data.
  std::string base;
  std::string solver = "direct";
  std::string linear_solver = "DENSE_SCHUR";
  double time_step = 0.0;
  double rest_tolerance = SolverOptions().rest_tolerance;
  int max_steps = SolverOptions().max_steps;
  std::string damping = DampingName(SolverOptions().damping);
  std::string integrator = IntegratorName(SolverOptions().integrator);
  std::string damping_scale;
  std::string jacobian = "analytic";
  // Local deformations (fit/local_fit.h).
  std::string local = FitOptions().local.enabled ? "on" : "off";
  std::string local_grid = "13x24";  // LocalOptions' rows x cols.
  double local_stiffness = FitOptions().local.stiffness;
  // A solid's field through the wall (LocalOptions::transmural): on or off.
  std::string local_transmural = FitOptions().local.transmural ? "on" : "off";
  // A solid's tags' depths across the wall (FitOptions::hold_tag_depths):
  // held or ranked.
  std::string tag_depths = FitOptions().hold_tag_depths ? "held" : "ranked";
  // Each frame's parameter covariance (FitOptions::uncertainty): on or off.
  std::string uncertainty = FitOptions().uncertainty ? "on" : "off";
  // The outputs.
  std::string vtk_format = "vtp";  // VtkOutputFromNames.
  std::string vtk_precision = "float";
};

// Each throws InputError naming the flag at fault, its value and what it
// must be.  FitOptionsFrom also refuses a setting the chosen solver, loss or
// local field does not use (--time_step with --solver direct, --loss_scale
// with --loss none); FitOptionsForEverySolver only those of the loss and
// the local field (compare-solvers runs every solver).
ModelConfig ModelConfigFrom(const FitSettings& settings);
FitOptions FitOptionsFrom(const FitSettings& settings);
FitOptions FitOptionsForEverySolver(const FitSettings& settings);
// The settings whose sense depends on the data's scale, once the points are
// read: a robust loss's scale within 1e-2 to 1e3 times the RMS radius of
// frame 0's points about their centroid, and --apex and --base within twice
// the farthest of those points from it.  Throws InputError naming the flag.
void CheckOptionsAgainstPoints(const FitOptions& options,
                               const PointSequence& points);
VtkOutput VtkOutputFrom(const FitSettings& settings);
// Per frame, the plane closing the cavity: none for base_plane "rim", the
// mitral valve planes of the guide points at `points` for "auto" (none
// when they have none), whatever the file's name when settings.format says
// gpfile.  An empty `points` only checks base_plane.  Once fitted, the
// planes go through CheckPlanesBelowApex (io/mitral_valve_planes.h).
std::vector<BasePlane> BasePlanesFrom(const FitSettings& settings,
                                      const std::string& points);

}  // namespace pfdm

#endif  // PFDM_IO_FIT_SETTINGS_H_
