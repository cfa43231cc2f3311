// End-to-end runs of the pfdm binary: the README's example and bad input.
#include <filesystem>
#include <sstream>

#include "gtest/gtest.h"
#include "nlohmann/json.hpp"
#include "pfdm/testing/test_util.h"

namespace pfdm {
namespace {

namespace fs = std::filesystem;

TEST(CliTest, SimulateThenFitWritesEveryOutput) {
  const std::string dir = ScratchDirectory("cli");
  CommandResult run =
      RunPfdm("simulate --frames 3 --tags 600 --out " + dir + "/phantom.csv");
  ASSERT_EQ(run.exit_code, 0) << run.error;
  ASSERT_TRUE(fs::exists(dir + "/phantom_truth.csv"));
  run = RunPfdm("fit --points " + dir + "/phantom.csv --out " + dir + "/fit");
  ASSERT_EQ(run.exit_code, 0) << run.error;
  for (const char* name : {"fit.json", "parameters.csv", "frame_000.vtk",
                           "frame_001.vtk", "frame_002.vtk"}) {
    EXPECT_TRUE(fs::exists(dir + "/fit/" + name)) << name;
  }
  for (const auto& entry : fs::directory_iterator(dir + "/fit")) {
    EXPECT_EQ(entry.path().string().find(".tmp."), std::string::npos);
  }
  const nlohmann::json fit =
      nlohmann::json::parse(ReadText(dir + "/fit/fit.json"));
  ASSERT_EQ(fit["frames"].size(), 3u);
  EXPECT_EQ(fit["model"]["knots"], 17);
  EXPECT_EQ(fit["settings"]["solver"], "direct");
  EXPECT_EQ(fit["settings"]["linear_solver"], "SPARSE_NORMAL_CHOLESKY");
  EXPECT_EQ(fit["settings"]["jacobian"], "analytic");
  EXPECT_FALSE(fit["settings"].contains("damping"));
  EXPECT_EQ(fit["model"]["functions"]["tau"]["mode"], "free");
  EXPECT_LT(fit["frames"][0]["rms_mm"].get<double>(), 0.6);
  EXPECT_EQ(fit["frames"][2]["n_points"], 600);
  EXPECT_NEAR(fit["frames"][2]["clinical"]["longitudinal_shortening_percent"]
                  .get<double>(),
              20.0, 1.5);
  // tau = -5 + 7 h degrees; the apical and basal rings at h = 0.2, 0.85.
  EXPECT_NEAR(fit["frames"][2]["clinical"]["net_twist_deg"].get<double>(),
              7.0 * 0.65, 1.0);

  // parameters.csv: one row per frame, function and knot, as documented.
  std::istringstream rows(ReadText(dir + "/fit/parameters.csv"));
  std::string line;
  std::getline(rows, line);
  EXPECT_EQ(line, "frame,function,knot,u,z_mm,value");
  int count = 0;
  while (std::getline(rows, line)) ++count;
  EXPECT_EQ(count, 3 * 14 * 17);
}

TEST(CliTest, FitWithTheIntegratorRecordsItsSettings) {
  const std::string dir = ScratchDirectory("cli_integrator");
  CommandResult run =
      RunPfdm("simulate --frames 2 --tags 150 --out " + dir + "/phantom.csv");
  ASSERT_EQ(run.exit_code, 0) << run.error;
  run = RunPfdm(
      "fit --knots 9 --solver integrator --damping unit "
      "--damping_scale twist=2,offsets=0.5 --time_step 1e-4 "
      "--max_steps 50 --rest_tolerance 1e-5 --points " +
      dir + "/phantom.csv --out " + dir + "/fit");
  ASSERT_EQ(run.exit_code, 0) << run.error;
  const nlohmann::json settings =
      nlohmann::json::parse(ReadText(dir + "/fit/fit.json"))["settings"];
  EXPECT_EQ(settings["solver"], "integrator");
  EXPECT_EQ(settings["damping"], "unit");
  EXPECT_EQ(settings["damping_scale"]["twist"], 2.0);
  EXPECT_EQ(settings["damping_scale"]["offsets"], 0.5);
  EXPECT_EQ(settings["damping_scale"]["shape"], 1.0);
  EXPECT_EQ(settings["time_step"], 1e-4);
  EXPECT_EQ(settings["max_steps"], 50);
  EXPECT_EQ(settings["rest_tolerance"], 1e-5);
  const nlohmann::json frames =
      nlohmann::json::parse(ReadText(dir + "/fit/fit.json"))["frames"];
  EXPECT_LE(frames[0]["iterations"].get<int>(), 50 * 10);  // 50 per round.
}

struct BadInput {
  const char* name;
  const char* csv;  // nullptr: no file at all.
  const char* extra_flags;
  const char* message;  // What stderr must end with, after the file name.
};

const BadInput kBadInputs[] = {
    {"missing file", nullptr, "", "tags.csv: cannot open the file"},
    {"missing column", "frame,id,x,y\n0,1,2,3\n", "",
     "tags.csv: missing column 'z'"},
    {"nan", "frame,id,x,y,z\n0,1,2,3,4\n0,2,2,nan,4\n", "",
     "tags.csv:3: column 'y' is not a finite number"},
    {"empty frame", "frame,id,x,y,z\n0,1,2,3,4\n2,1,2,3,4\n", "",
     "tags.csv: frame 1 has no points"},
    {"duplicate id", "frame,id,x,y,z\n0,1,2,3,4\n0,1,2,3,5\n", "",
     "tags.csv:3: id 1 appears twice in frame 0"},
    {"too few points",
     "frame,id,x,y,z\n0,1,2,3,4\n0,2,5,6,7\n0,3,1,1,1\n"
     "0,4,2,2,2\n",
     "", "tags.csv: frame 0: only 4 points, at least 10 needed"},
    {"unknown model", "frame,id,x,y,z\n0,1,2,3,4\n", "--model cylinder",
     "unknown --model 'cylinder' (expected paper or superellipsoid)"},
    {"half a hint", "frame,id,x,y,z\n0,1,2,3,4\n", "--apex 1,2,3",
     "--apex and --base go together"},
    {"bad hint", "frame,id,x,y,z\n0,1,2,3,4\n", "--apex 1,2 --base 0,0,0",
     "--apex must be x,y,z in mm, got '1,2'"},
    {"unknown linear solver", "frame,id,x,y,z\n0,1,2,3,4\n",
     "--linear_solver CHOLMOD", "unknown --linear_solver 'CHOLMOD'"},
    {"negative time step", "frame,id,x,y,z\n0,1,2,3,4\n",
     "--solver integrator --time_step -1",
     "--time_step must be 0 (default) or positive"},
    {"no steps", "frame,id,x,y,z\n0,1,2,3,4\n", "--max_steps 0",
     "--max_steps must be at least 1"},
    {"unknown damping", "frame,id,x,y,z\n0,1,2,3,4\n", "--damping mass",
     "unknown --damping 'mass' (expected jacobi or unit)"},
    {"bad damping scale", "frame,id,x,y,z\n0,1,2,3,4\n",
     "--damping_scale twist=0",
     "--damping_scale entry 'twist=0' is not group=value with a positive "
     "value and group one of pose, shape, twist, bending, offsets"},
};

TEST(CliTest, BadInputGivesOneLineNonZeroExitAndNoOutput) {
  for (const BadInput& bad : kBadInputs) {
    const std::string dir = ScratchDirectory("bad");
    if (bad.csv != nullptr) WriteText(dir + "/tags.csv", bad.csv);
    const CommandResult run =
        RunPfdm("fit --points " + dir + "/tags.csv --out " + dir + "/fit " +
                bad.extra_flags);
    EXPECT_EQ(run.exit_code, 1) << bad.name;
    EXPECT_EQ(std::count(run.error.begin(), run.error.end(), '\n'), 1)
        << bad.name << ": " << run.error;
    const std::string expected = std::string(bad.message) + "\n";
    ASSERT_GE(run.error.size(), expected.size()) << bad.name;
    EXPECT_EQ(run.error.substr(run.error.size() - expected.size()), expected)
        << bad.name;
    EXPECT_EQ(run.error.rfind("pfdm: error: ", 0), 0u) << bad.name;
    EXPECT_FALSE(fs::exists(dir + "/fit")) << bad.name;
  }
}

TEST(CliTest, UnknownCommandIsAUsageError) {
  const CommandResult run = RunPfdm("transmogrify");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.error.find("unknown command 'transmogrify'"),
            std::string::npos);
}

}  // namespace
}  // namespace pfdm
