// Flags shared by the commands that read points and fit; their names,
// defaults and checks are FitSettings' (io/fit_settings.h).
#include "pfdm/cli/commands.h"
#include "pfdm/io/fit_settings.h"
#include "pfdm/io/point_source.h"
#include "pfdm/util/error.h"

namespace {
const pfdm::FitSettings kDefaults;
}  // namespace

DEFINE_string(points, "",
              "input points: a frame,id,x,y,z CSV, or a biv-me "
              "GPFile_*.txt or a folder of them");
DEFINE_string(segmentation, "",
              "fit: input label map instead of --points: a 4D NIfTI (x, y, "
              "slice, time), a 3D one, or a folder of 3D files, one per "
              "frame in name order (only *_gt* files where there are some, "
              "as ACDC's); docs/segmentation.md");
DEFINE_string(labels, "acdc",
              "fit --segmentation: the label values, acdc (lv=3,myo=2,rv=1), "
              "mnms (lv=1,myo=2,rv=3) or lv=N,myo=N[,rv=N|none]");
DEFINE_string(format, kDefaults.format.c_str(),
              "csv, gpfile or auto (by name)");
DEFINE_string(contours, kDefaults.contours.c_str(),
              "GPFile contour types to keep, comma-separated; lv-endo, "
              "lv-epi and lv-cavity (lv-endo and AORTA_VALVE) are aliases");
DEFINE_string(out, "", "output folder (simulate: output CSV)");
DEFINE_string(model, kDefaults.model.c_str(), "paper or superellipsoid");
DEFINE_int32(knots, kDefaults.knots, "knots per parameter function, 2 to 100");
DEFINE_string(wall, kDefaults.wall.c_str(),
              "midwall (one surface), solid (endocardium to epicardium, "
              "wall thickness h and transmural twist dtau) or auto: solid "
              "for contours of both walls or tags spread across the wall");
DEFINE_string(surface, kDefaults.surface.c_str(),
              "the wall the points lie on, fitted as one surface: endo (its "
              "volume is the cavity's: an ejection fraction), midwall, epi, "
              "or auto (from the contour types or a mesh's surface column, "
              "else midwall)");
DEFINE_int32(ed_frame, kDefaults.ed_frame,
             "end-diastole: the frame the ejection fraction's EDV and the "
             "strains are measured from (ES: the least volume)");
DEFINE_double(smoothness, kDefaults.smoothness,
              "smoothness weight, relative to one knot's data, 0 to 1e6");
DEFINE_double(prior, kDefaults.prior,
              "pull toward the previous frame, same units, 0 to 1e6");
DEFINE_double(untracked_prior, kDefaults.untracked_prior,
              "frames without tracked points (contours): pull toward frame "
              "0, same units, 0 to 1e6");
DEFINE_double(untracked_prior_radii, kDefaults.untracked_prior_radii,
              "that pull's (and --temporal_prior's) share on the radii a1 "
              "and a2 at knots the points cover all round, 0 (the data's) "
              "to 1 (as elsewhere) (docs/gauge.md, Radii)");
DEFINE_double(temporal_prior, kDefaults.temporal_prior,
              "frames without tracked points, in sequences of 20 frames or "
              "more: pull toward the previous frame too, same units, 0 (off) "
              "to 1e6 (docs/contour_sequences.md)");
DEFINE_double(incompressible, kDefaults.incompressible,
              "a solid's wall keeps frame 0's volume, same units, 0 (off) to "
              "1e6 (docs/accuracy.md, \"The myocardium\")");
DEFINE_string(loss, kDefaults.loss.c_str(), "none, huber or cauchy");
DEFINE_string(loss_scale, kDefaults.loss_scale.c_str(),
              "--loss huber or cauchy: the loss's scale, auto (per frame, "
              "from the frame's fit without the loss: 1.4826 times its "
              "median distance, times 1.345 for huber, 2.385 for cauchy) or "
              "mm, 1e-2 to 1e3 times the RMS radius of frame 0's points");
DEFINE_int32(threads, kDefaults.threads,
             "threads: the solver's, the closest points' and "
             "--uncertainty's intervals', 1 to 256");
DEFINE_string(apex, "",
              "optional apex hint x,y,z (mm), with --base; within twice the "
              "farthest of frame 0's points from their centroid; without: "
              "biv-me's APEX_POINT and valve points, the normal of parallel "
              "slices, or the point cloud's best candidate axis");
DEFINE_string(base, "", "optional base-centre hint x,y,z (mm), with --apex");
DEFINE_string(rv_insertion, "",
              "the RV insertion at frame 0, x,y,z (anterior) or "
              "x,y,z,x,y,z (anterior, inferior), mm: places the AHA "
              "segments; without it biv-me's RV_INSERT points, else the "
              "segments are not anatomical");
DEFINE_string(solver, kDefaults.solver.c_str(), "direct, damped or integrator");
DEFINE_string(linear_solver, kDefaults.linear_solver.c_str(),
              "direct and damped: Ceres linear solver of the global "
              "functions' solve, e.g. "
              "DENSE_SCHUR, SPARSE_NORMAL_CHOLESKY, DENSE_QR (the "
              "local field's is SPARSE_NORMAL_CHOLESKY)");
DEFINE_double(time_step, kDefaults.time_step,
              "damped and integrator: pseudo-time step, 1e-6 to 1e12; 0 = "
              "default (euler: 0.9 of its stability bound, damped: 1000; "
              "rkc: its first step, then error-controlled)");
DEFINE_double(rest_tolerance, kDefaults.rest_tolerance,
              "damped and integrator: at rest when the energy dissipated per "
              "unit pseudo-time is below rest_tolerance^2 of the initial "
              "(rkc: and the last step's move below rest_tolerance of its "
              "square root), 1e-12 to 0.01");
DEFINE_string(integrator, kDefaults.integrator.c_str(),
              "integrator: rkc (Runge-Kutta-Chebyshev, error-controlled, "
              "comes to rest) or euler (forward Euler, the paper's)");
DEFINE_int32(max_steps, kDefaults.max_steps,
             "damped and integrator: most steps per solve, 1 to 1e6");
DEFINE_string(
    damping, kDefaults.damping.c_str(),
    "integrator: damping D = jacobi (diag J^T J), unit or model (J^T J)");
DEFINE_string(damping_scale, "",
              "integrator: multipliers of D per group, e.g. "
              "twist=10,offsets=2 (groups pose shape twist bending offsets)");
DEFINE_string(jacobian, kDefaults.jacobian.c_str(),
              "analytic, autodiff or numeric");
DEFINE_string(local, kDefaults.local.c_str(),
              "local deformations on top of the global functions: on or off");
DEFINE_string(local_grid, kDefaults.local_grid.c_str(),
              "local deformations' nodes, rows (apex pole to base) x "
              "columns (around), 3 to 40 x 4 to 72");
DEFINE_double(local_stiffness, kDefaults.local_stiffness,
              "local deformations' membrane and thin-plate weight, relative "
              "to one node's data, 1e-4 to 1e6 (--local off: none)");
DEFINE_string(local_transmural, kDefaults.local_transmural.c_str(),
              "a solid's local deformations vary through the wall, so that "
              "regional and subendocardial defects show: on or off");
DEFINE_string(tag_depths, kDefaults.tag_depths.c_str(),
              "a solid's tags through the wall keep frame 0's depth in every "
              "frame, as they keep its material point (held), or are ranked "
              "across the wall in each (ranked; among their neighbours with "
              "--local_transmural on); where a frame's contours place both "
              "walls, its tags' depths are measured across them whatever "
              "this says (fit.json's tag_depths: measured)");
DEFINE_string(uncertainty, kDefaults.uncertainty.c_str(),
              "each frame's parameter covariance, a standard deviation per "
              "knot value in parameters.csv: on or off");
DEFINE_string(vtk_format, kDefaults.vtk_format.c_str(),
              "fit, batch: each frame as vtp (frame_NNN.vtp, with fit.pvd), "
              "vtk (legacy frame_NNN.vtk) or both, binary (legacy BINARY, "
              "XML appended raw) or ascii (text), comma-separated: "
              "'vtk,ascii'");
DEFINE_string(vtk_precision, kDefaults.vtk_precision.c_str(),
              "fit, batch: the frames' points and values as float (float32: "
              "a micrometre on a heart, half the bytes) or double (exact); "
              "flags and weights are float32 either way");
DEFINE_string(base_plane, kDefaults.base_plane.c_str(),
              "fit, batch: where the cavity volume is "
              "closed: auto (the mitral valve plane when biv-me guide points "
              "have MITRAL_VALVE points in every frame, else rim) or rim "
              "(a flat lid at the base rim)");
DEFINE_bool(extrapolated, false,
            "fit, batch: report the numbers measured where frame 0 has no "
            "data (the apical level and ring when the data do not reach the "
            "apex); by default they are null / n/a");

namespace pfdm {

bool ShowExtrapolatedFromFlags() { return FLAGS_extrapolated; }

FitSettings FitSettingsFromFlags() {
  FitSettings s;
  s.format = FLAGS_format;
  s.contours = FLAGS_contours;
  s.base_plane = FLAGS_base_plane;
  s.rv_insertion = FLAGS_rv_insertion;
  s.model = FLAGS_model;
  s.knots = FLAGS_knots;
  s.wall = FLAGS_wall;
  s.surface = FLAGS_surface;
  s.ed_frame = FLAGS_ed_frame;
  s.smoothness = FLAGS_smoothness;
  s.prior = FLAGS_prior;
  s.untracked_prior = FLAGS_untracked_prior;
  s.untracked_prior_radii = FLAGS_untracked_prior_radii;
  s.temporal_prior = FLAGS_temporal_prior;
  s.incompressible = FLAGS_incompressible;
  s.loss = FLAGS_loss;
  s.loss_scale = FLAGS_loss_scale;
  s.threads = FLAGS_threads;
  s.apex = FLAGS_apex;
  s.base = FLAGS_base;
  s.solver = FLAGS_solver;
  s.linear_solver = FLAGS_linear_solver;
  s.time_step = FLAGS_time_step;
  s.rest_tolerance = FLAGS_rest_tolerance;
  s.max_steps = FLAGS_max_steps;
  s.damping = FLAGS_damping;
  s.integrator = FLAGS_integrator;
  s.damping_scale = FLAGS_damping_scale;
  s.jacobian = FLAGS_jacobian;
  s.local = FLAGS_local;
  s.local_grid = FLAGS_local_grid;
  s.local_stiffness = FLAGS_local_stiffness;
  s.local_transmural = FLAGS_local_transmural;
  s.tag_depths = FLAGS_tag_depths;
  s.uncertainty = FLAGS_uncertainty;
  s.vtk_format = FLAGS_vtk_format;
  s.vtk_precision = FLAGS_vtk_precision;
  return s;
}

PointSequence PointsFromFlags() {
  if (FLAGS_points.empty()) throw InputError("--points FILE is required");
  return ReadPoints(FLAGS_points, FLAGS_format, FLAGS_contours);
}

ModelConfig ModelConfigFromFlags() {
  return ModelConfigFrom(FitSettingsFromFlags());
}

FitOptions FitOptionsFromFlags() {
  return FitOptionsFrom(FitSettingsFromFlags());
}

VtkOutput VtkOutputFromFlags() { return VtkOutputFrom(FitSettingsFromFlags()); }

std::vector<BasePlane> BasePlanesFromFlags(const std::string& points) {
  return BasePlanesFrom(FitSettingsFromFlags(), points);
}

}  // namespace pfdm
