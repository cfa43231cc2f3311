#include "pfdm/io/fit_settings.h"

#include <string>

#include "gtest/gtest.h"
#include "pfdm/util/error.h"

namespace pfdm {
namespace {

std::string ErrorOf(const FitSettings& settings) {
  try {
    FitOptionsFrom(settings);
    ModelConfigFrom(settings);
    BasePlanesFrom(settings, "");
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

// The defaults are the library's: the CLI and the Python module, which
// take theirs from FitSettings, fit as FitSequence does by default.
TEST(FitSettingsTest, DefaultsAreTheLibrarys) {
  const FitSettings settings;
  const FitOptions options = FitOptionsFrom(settings);
  const FitOptions library;
  EXPECT_EQ(options.smoothness_weight, library.smoothness_weight);
  EXPECT_EQ(options.prior_weight, library.prior_weight);
  EXPECT_EQ(options.untracked_prior_weight, library.untracked_prior_weight);
  EXPECT_EQ(options.untracked_prior_covered_radii_scale,
            library.untracked_prior_covered_radii_scale);
  EXPECT_EQ(options.temporal_prior_weight, library.temporal_prior_weight);
  EXPECT_EQ(options.local.enabled, library.local.enabled);
  EXPECT_EQ(options.local.rows, library.local.rows);
  EXPECT_EQ(options.local.cols, library.local.cols);
  EXPECT_EQ(options.local.stiffness, library.local.stiffness);
  EXPECT_EQ(options.loss, library.loss);
  EXPECT_EQ(options.loss_scale_auto, library.loss_scale_auto);
  EXPECT_TRUE(options.loss_scale_auto);
  EXPECT_EQ(options.loss_scale_mm, library.loss_scale_mm);
  EXPECT_EQ(options.solver.kind, library.solver.kind);
  EXPECT_EQ(options.solver.linear_solver, library.solver.linear_solver);
  EXPECT_EQ(options.solver.num_threads, library.solver.num_threads);
  EXPECT_EQ(options.solver.time_step, library.solver.time_step);
  EXPECT_EQ(options.solver.rest_tolerance, library.solver.rest_tolerance);
  EXPECT_EQ(options.solver.max_steps, library.solver.max_steps);
  EXPECT_EQ(options.solver.damping, library.solver.damping);
  EXPECT_EQ(options.solver.integrator, library.solver.integrator);
  EXPECT_EQ(options.jacobian, library.jacobian);
  EXPECT_FALSE(options.hint.has_value());
  const ModelConfig config = ModelConfigFrom(settings);
  EXPECT_EQ(config.name, "paper");
  EXPECT_EQ(config.num_knots, 17);
  EXPECT_TRUE(BasePlanesFrom(settings, "").empty());
}

TEST(FitSettingsTest, SettingsReachTheOptions) {
  FitSettings settings;
  settings.model = "superellipsoid";
  settings.knots = 9;
  settings.solver = "integrator";
  settings.damping = "unit";
  settings.damping_scale = "twist=2";
  settings.integrator = "rkc";
  settings.time_step = 0.5;
  settings.apex = "1,2,3";
  settings.base = "4,5,6.5";
  const FitOptions options = FitOptionsFrom(settings);
  EXPECT_EQ(options.solver.kind, SolverKind::kIntegrator);
  EXPECT_EQ(options.solver.damping, DampingKind::kUnit);
  EXPECT_EQ(options.solver.integrator, IntegratorKind::kRkc);
  EXPECT_EQ(options.damping_groups.twist, 2.0);
  EXPECT_EQ(options.solver.time_step, 0.5);
  ASSERT_TRUE(options.hint.has_value());
  EXPECT_EQ(options.hint->apex, Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(options.hint->base_center, Eigen::Vector3d(4, 5, 6.5));
  EXPECT_EQ(ModelConfigFrom(settings).num_knots, 9);
  EXPECT_EQ(ModelConfigFrom(settings).name, "superellipsoid");
  settings = FitSettings();
  settings.solver = "damped";
  settings.linear_solver = "DENSE_QR";
  settings.rest_tolerance = 0.01;
  settings.max_steps = 1000000;
  settings.local_stiffness = 1e-4;
  settings.local_transmural = "on";
  EXPECT_TRUE(FitOptionsFrom(settings).local.transmural);
  EXPECT_FALSE(FitOptionsFrom(FitSettings()).local.transmural);
  EXPECT_TRUE(FitOptionsFrom(FitSettings()).hold_tag_depths);
  FitSettings ranked;
  ranked.tag_depths = "ranked";
  EXPECT_FALSE(FitOptionsFrom(ranked).hold_tag_depths);
  // Either way with the field through the wall (ranked: among neighbours).
  ranked.local_transmural = "on";
  EXPECT_FALSE(FitOptionsFrom(ranked).hold_tag_depths);
  EXPECT_TRUE(FitOptionsFrom(ranked).local.transmural);
  EXPECT_EQ(FitOptionsFrom(settings).solver.linear_solver, ceres::DENSE_QR);
  EXPECT_EQ(FitOptionsFrom(settings).solver.rest_tolerance, 0.01);
  EXPECT_EQ(FitOptionsFrom(settings).solver.max_steps, 1000000);
  EXPECT_EQ(FitOptionsFrom(settings).local.stiffness, 1e-4);
}

// --loss_scale: auto (measured) by default, or a number of mm.
TEST(FitSettingsTest, LossScaleIsAutoOrANumber) {
  FitSettings settings;
  settings.loss = "cauchy";
  FitOptions options = FitOptionsFrom(settings);
  EXPECT_EQ(options.loss, "cauchy");
  EXPECT_TRUE(options.loss_scale_auto);
  settings.loss_scale = "2.5";
  options = FitOptionsFrom(settings);
  EXPECT_FALSE(options.loss_scale_auto);
  EXPECT_EQ(options.loss_scale_mm, 2.5);
}

// --untracked_prior_radii reaches the option it names, ends included.
TEST(FitSettingsTest, TheRadiiShareReachesTheFit) {
  FitSettings s;
  for (double share : {0.0, 0.5, 1.0}) {
    s.untracked_prior_radii = share;
    EXPECT_EQ(FitOptionsFrom(s).untracked_prior_covered_radii_scale, share);
  }
}

TEST(FitSettingsTest, BadSettingsNameTheirFlag) {
  FitSettings s;
  s.apex = "1,2,3";
  EXPECT_EQ(ErrorOf(s), "--apex and --base go together");
  s.base = "1,2";
  EXPECT_EQ(ErrorOf(s), "--base must be x,y,z in mm, got '1,2'");
  s = FitSettings();
  s.untracked_prior = -1.0;
  EXPECT_EQ(ErrorOf(s), "--untracked_prior must be between 0 and 1e6, got -1");
  s = FitSettings();
  s.untracked_prior_radii = 1.5;
  EXPECT_EQ(ErrorOf(s),
            "--untracked_prior_radii must be between 0 and 1, got 1.5");
  s = FitSettings();
  s.temporal_prior = -0.5;
  EXPECT_EQ(ErrorOf(s), "--temporal_prior must be between 0 and 1e6, got -0.5");
  s = FitSettings();
  s.local = "yes";
  EXPECT_EQ(ErrorOf(s), "--local must be on or off, got 'yes'");
  s = FitSettings();
  s.local_transmural = "1";
  EXPECT_EQ(ErrorOf(s), "--local_transmural must be on or off, got '1'");
  s = FitSettings();
  s.tag_depths = "kept";
  EXPECT_EQ(ErrorOf(s), "--tag_depths must be held or ranked, got 'kept'");
  s = FitSettings();
  s.local_grid = "9x100";
  EXPECT_EQ(ErrorOf(s),
            "--local_grid must be NUxNV with 3 to 40 rows and 4 to 72 "
            "columns, got '9x100'");
  s = FitSettings();
  s.local_stiffness = -1.0;
  EXPECT_EQ(ErrorOf(s),
            "--local_stiffness must be between 1e-4 and 1e6 (--local off: no "
            "local deformations), got -1");
  s = FitSettings();
  s.linear_solver = "MAGIC";
  EXPECT_EQ(ErrorOf(s), "unknown --linear_solver 'MAGIC'");
  s = FitSettings();
  s.solver = "integrator";
  s.time_step = -1.0;
  EXPECT_EQ(ErrorOf(s),
            "--time_step must be 0 (default) or between 1e-6 and 1e12, got -1");
  s = FitSettings();
  s.solver = "damped";
  s.max_steps = 0;
  EXPECT_EQ(ErrorOf(s), "--max_steps must be between 1 and 1000000, got 0");
  s = FitSettings();
  s.knots = 1;
  EXPECT_EQ(ErrorOf(s), "--knots must be between 2 and 100, got 1");
  for (const char* scale : {"0", "-1", "nan", "inf", "2mm", "", "Auto"}) {
    s = FitSettings();
    s.loss = "huber";
    s.loss_scale = scale;
    EXPECT_EQ(ErrorOf(s),
              std::string("--loss_scale must be auto or a positive number of "
                          "mm, got '") +
                  scale + "'");
  }
  s = FitSettings();
  s.loss = "tukey";
  EXPECT_EQ(ErrorOf(s),
            "unknown --loss 'tukey' (expected none, huber or cauchy)");
  s = FitSettings();
  s.base_plane = "lid";
  EXPECT_EQ(ErrorOf(s), "unknown --base_plane 'lid' (expected auto or rim)");
}

// Issue 29: each of these ran to exit 0; the values at the edges of the
// ranges are accepted (above, SettingsReachTheOptions).
TEST(FitSettingsTest, NumbersOutsideWhatMakesSenseNameFlagValueAndRange) {
  FitSettings s;
  s.local_stiffness = 0.0;  // 67,888 ml.
  EXPECT_EQ(ErrorOf(s),
            "--local_stiffness must be between 1e-4 and 1e6 (--local off: no "
            "local deformations), got 0");
  s = FitSettings();
  s.solver = "integrator";
  s.rest_tolerance = 1e308;  // Stopped the integrator at once.
  EXPECT_EQ(ErrorOf(s),
            "--rest_tolerance must be between 1e-12 and 0.01, got 1e+308");
  s.rest_tolerance = 0.02;
  EXPECT_EQ(ErrorOf(s),
            "--rest_tolerance must be between 1e-12 and 0.01, got 0.02");
  s = FitSettings();
  s.solver = "damped";
  s.max_steps = 2147483647;
  EXPECT_EQ(ErrorOf(s),
            "--max_steps must be between 1 and 1000000, got 2147483647");
  s = FitSettings();
  s.threads = 257;
  EXPECT_EQ(ErrorOf(s), "--threads must be between 1 and 256, got 257");
}

// Issue 29: --time_step with the direct solver was silently ignored.  A
// setting differing from its default is one given; the defaults pass.
TEST(FitSettingsTest, SettingsTheChosenSolverLossOrFieldDoNotUseAreRefused) {
  struct Case {
    void (*set)(FitSettings*);
    const char* message;
  };
  const Case cases[] = {
      {[](FitSettings* s) { s->time_step = 1.0; },
       "--time_step applies to --solver damped or integrator, not --solver "
       "direct"},
      {[](FitSettings* s) { s->rest_tolerance = 1e-3; },
       "--rest_tolerance applies to --solver damped or integrator, not "
       "--solver direct"},
      {[](FitSettings* s) { s->max_steps = 10; },
       "--max_steps applies to --solver damped or integrator, not --solver "
       "direct"},
      {[](FitSettings* s) {
         s->solver = "damped";
         s->damping = "unit";
       },
       "--damping applies to --solver integrator, not --solver damped"},
      {[](FitSettings* s) { s->damping_scale = "twist=2"; },
       "--damping_scale applies to --solver integrator, not --solver direct"},
      {[](FitSettings* s) { s->integrator = "rkc"; },
       "--integrator applies to --solver integrator, not --solver direct"},
      {[](FitSettings* s) {
         s->solver = "integrator";
         s->linear_solver = "DENSE_QR";
       },
       "--linear_solver applies to --solver direct or damped, not --solver "
       "integrator"},
      {[](FitSettings* s) { s->loss_scale = "2"; },
       "--loss_scale applies to --loss huber or cauchy, not --loss none"},
      {[](FitSettings* s) {
         s->local = "off";
         s->local_grid = "9x16";
       },
       "--local_grid applies to --local on, not --local off"},
      {[](FitSettings* s) {
         s->local = "off";
         s->local_stiffness = 1.0;
       },
       "--local_stiffness applies to --local on, not --local off"},
      {[](FitSettings* s) {
         s->local = "off";
         s->local_transmural = "on";
       },
       "--local_transmural applies to --local on, not --local off"},
  };
  for (const Case& c : cases) {
    FitSettings s;
    c.set(&s);
    EXPECT_EQ(ErrorOf(s), c.message);
  }
  // compare-solvers runs every solver: theirs all apply, the loss's not.
  FitSettings s;
  s.time_step = 1.0;
  s.damping = "unit";
  s.linear_solver = "DENSE_QR";
  EXPECT_EQ(FitOptionsForEverySolver(s).solver.time_step, 1.0);
  s.loss_scale = "2";
  EXPECT_THROW(FitOptionsForEverySolver(s), InputError);
}

std::string ErrorAgainst(const FitOptions& options,
                         const PointSequence& points) {
  try {
    CheckOptionsAgainstPoints(options, points);
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

// Frame 0: the 8 corners of a cube of side 20 about (100, 0, 0), twice
// (a fit needs 10 points): RMS radius and farthest point 10 sqrt(3) =
// 17.32 mm.
PointSequence Cube() {
  PointSequence points;
  points.frames.resize(1);
  for (int i = 0; i < 16; ++i) {
    points.frames[0].points.push_back(
        {i, Eigen::Vector3d(100 + (i & 1 ? 10 : -10), i & 2 ? 10 : -10,
                            i & 4 ? 10 : -10)});
  }
  return points;
}

// Issue 29: a Cauchy scale of 1e150 or a Huber one of 1e-300 left the
// model where it started; --apex 900000,0,0 gave an EDV of 3.6e12 ml.
TEST(FitSettingsTest, LossScaleAndAxisHintAreBoundedByTheDatasScale) {
  const PointSequence cube = Cube();
  FitSettings s;
  s.loss = "cauchy";
  s.loss_scale = "1e150";
  EXPECT_EQ(ErrorAgainst(FitOptionsFrom(s), cube),
            "--loss_scale must be between 0.173 and 17321 mm (1e-2 to 1e3 "
            "times the RMS radius of frame 0's points, 17.3 mm), got 1e+150");
  s.loss = "huber";
  s.loss_scale = "1e-300";
  EXPECT_EQ(ErrorAgainst(FitOptionsFrom(s), cube),
            "--loss_scale must be between 0.173 and 17321 mm (1e-2 to 1e3 "
            "times the RMS radius of frame 0's points, 17.3 mm), got 1e-300");
  s.loss_scale = "0.18";  // Just inside.
  EXPECT_EQ(ErrorAgainst(FitOptionsFrom(s), cube), "");
  s.loss_scale = "17000";
  EXPECT_EQ(ErrorAgainst(FitOptionsFrom(s), cube), "");

  s = FitSettings();
  s.apex = "900000,0,0";
  s.base = "-900000,0,0";
  EXPECT_EQ(ErrorAgainst(FitOptionsFrom(s), cube),
            "--apex must lie within 34.6 mm of the centroid of frame 0's "
            "points (twice the farthest point's distance), got 900000,0,0, "
            "899900 mm from it");
  s.apex = "130,0,0";  // 30 mm from the centroid: inside.
  s.base = "100,0,40";
  EXPECT_EQ(ErrorAgainst(FitOptionsFrom(s), cube),
            "--base must lie within 34.6 mm of the centroid of frame 0's "
            "points (twice the farthest point's distance), got 100,0,40, "
            "40 mm from it");
  s.base = "100,0,30";
  EXPECT_EQ(ErrorAgainst(FitOptionsFrom(s), cube), "");
  // Points too few or at one place: the fit's start says so.
  s.apex = "900000,0,0";
  PointSequence few = cube;
  few.frames[0].points.resize(9);
  EXPECT_EQ(ErrorAgainst(FitOptionsFrom(s), few), "");
  PointSequence one_place = cube;
  for (DataPoint& p : one_place.frames[0].points) p.position.setZero();
  EXPECT_EQ(ErrorAgainst(FitOptionsFrom(s), one_place), "");
}

// --surface declares one surface, so not with --wall solid; --ed_frame is a
// frame of the points.
TEST(FitSettingsTest, SurfaceAndEndDiastoleAreCheckedAndReachTheOptions) {
  FitSettings s;
  EXPECT_EQ(FitOptionsFrom(s).surface, SurfaceChoice::kAuto);
  EXPECT_EQ(FitOptionsFrom(s).ed_frame, 0);
  s.surface = "endo";
  s.ed_frame = 3;
  EXPECT_EQ(FitOptionsFrom(s).surface, SurfaceChoice::kEndocardium);
  EXPECT_EQ(FitOptionsFrom(s).ed_frame, 3);
  s.surface = "epi";
  EXPECT_EQ(FitOptionsFrom(s).surface, SurfaceChoice::kEpicardium);
  s.surface = "midwall";
  EXPECT_EQ(FitOptionsFrom(s).surface, SurfaceChoice::kMidwall);
  s.wall = "solid";
  EXPECT_EQ(ErrorOf(s),
            "--surface midwall declares one surface; --wall solid fits two");
  s = FitSettings();
  s.surface = "endocardium";
  EXPECT_EQ(ErrorOf(s),
            "--surface must be auto, endo, midwall or epi, got 'endocardium'");
  s = FitSettings();
  s.ed_frame = -1;
  EXPECT_EQ(ErrorOf(s), "--ed_frame must be a frame number from 0, got -1");
  s.ed_frame = 1;  // Cube() has one frame.
  PointSequence cube = Cube();
  cube.source = "cube.csv";
  EXPECT_EQ(ErrorAgainst(FitOptionsFrom(s), cube),
            "--ed_frame 1 is not a frame of cube.csv (frames 0 to 0)");
  s.ed_frame = 0;
  EXPECT_EQ(ErrorAgainst(FitOptionsFrom(s), cube), "");
}

}  // namespace
}  // namespace pfdm