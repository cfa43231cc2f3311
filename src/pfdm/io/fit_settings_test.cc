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
  settings.linear_solver = "DENSE_QR";
  settings.damping = "unit";
  settings.damping_scale = "twist=2";
  settings.time_step = 0.5;
  settings.apex = "1,2,3";
  settings.base = "4,5,6.5";
  const FitOptions options = FitOptionsFrom(settings);
  EXPECT_EQ(options.solver.kind, SolverKind::kIntegrator);
  EXPECT_EQ(options.solver.linear_solver, ceres::DENSE_QR);
  EXPECT_EQ(options.solver.damping, DampingKind::kUnit);
  EXPECT_EQ(options.damping_groups.twist, 2.0);
  EXPECT_EQ(options.solver.time_step, 0.5);
  ASSERT_TRUE(options.hint.has_value());
  EXPECT_EQ(options.hint->apex, Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(options.hint->base_center, Eigen::Vector3d(4, 5, 6.5));
  EXPECT_EQ(ModelConfigFrom(settings).num_knots, 9);
  EXPECT_EQ(ModelConfigFrom(settings).name, "superellipsoid");
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
  s.local = "yes";
  EXPECT_EQ(ErrorOf(s), "--local must be on or off, got 'yes'");
  s = FitSettings();
  s.local_grid = "9x100";
  EXPECT_EQ(ErrorOf(s),
            "--local_grid must be NUxNV with 3 to 40 rows and 4 to 72 "
            "columns, got '9x100'");
  s = FitSettings();
  s.local_stiffness = -1.0;
  EXPECT_EQ(ErrorOf(s), "--local_stiffness must be between 0 and 1e6, got -1");
  s = FitSettings();
  s.linear_solver = "MAGIC";
  EXPECT_EQ(ErrorOf(s), "unknown --linear_solver 'MAGIC'");
  s = FitSettings();
  s.time_step = -1.0;
  EXPECT_EQ(ErrorOf(s),
            "--time_step must be 0 (default) or between 1e-6 and 1e12, got -1");
  s = FitSettings();
  s.max_steps = 0;
  EXPECT_EQ(ErrorOf(s), "--max_steps must be at least 1");
  s = FitSettings();
  s.knots = 1;
  EXPECT_EQ(ErrorOf(s), "--knots must be between 2 and 100, got 1");
  for (const char* scale : {"0", "-1", "nan", "inf", "2mm", "", "Auto"}) {
    s = FitSettings();
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

}  // namespace
}  // namespace pfdm
