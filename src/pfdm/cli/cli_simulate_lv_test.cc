// End-to-end runs of `pfdm simulate --phantom lv`.
#include <algorithm>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "gtest/gtest.h"
#include "nlohmann/json.hpp"
#include "pfdm/testing/test_util.h"

namespace pfdm {
namespace {

namespace fs = std::filesystem;

int CsvRows(const std::string& path) {
  std::istringstream text(ReadText(path));
  std::string line;
  int rows = -1;  // The header.
  while (std::getline(text, line)) ++rows;
  return rows;
}

TEST(LvPhantomCliTest, WritesPointsAndTruth) {
  const std::string dir = ScratchDirectory("lv");
  CommandResult run = RunPfdm(
      "simulate --phantom lv --kinematics cycle --wall_tags wall --lesion "
      "--tags 50 --out " +
      dir + "/lv.csv");
  ASSERT_EQ(run.exit_code, 0) << run.error;
  EXPECT_EQ(CsvRows(dir + "/lv.csv"), 9 * 50);  // Cycle: 9 frames.
  const nlohmann::json truth =
      nlohmann::json::parse(ReadText(dir + "/lv_truth.json"));
  EXPECT_EQ(truth["kinematics"], "cycle");
  EXPECT_EQ(truth["tags"], "wall");
  EXPECT_EQ(truth["lesion"], true);
  ASSERT_EQ(truth["frames"].size(), 9u);
  EXPECT_NEAR(
      truth["frames"][4]["longitudinal_shortening_percent"].get<double>(), 17.0,
      1e-9);
  EXPECT_FALSE(fs::exists(dir + "/lv_truth.csv"));

  run = RunPfdm(
      "simulate --phantom lv --kinematics rigid-spin --frames 3 "
      "--tags 20 --noise 0 --out " +
      dir + "/spin.csv");
  ASSERT_EQ(run.exit_code, 0) << run.error;
  EXPECT_EQ(CsvRows(dir + "/spin.csv"), 3 * 20);
  const nlohmann::json spin =
      nlohmann::json::parse(ReadText(dir + "/spin_truth.json"));
  EXPECT_EQ(spin["frames"][2]["rigid"]["spin_deg"].get<double>(), 10.0);

  // --outliers: the truth lists them per frame (10 % of 200 tags).
  run = RunPfdm("simulate --phantom lv --outliers 0.1 --tags 200 --out " + dir +
                "/outliers.csv");
  ASSERT_EQ(run.exit_code, 0) << run.error;
  const nlohmann::json outliers =
      nlohmann::json::parse(ReadText(dir + "/outliers_truth.json"));
  EXPECT_EQ(outliers["outlier_fraction"].get<double>(), 0.1);
  for (const nlohmann::json& frame : outliers["frames"]) {
    EXPECT_NEAR(frame["outlier_ids"].size(), 20.0, 13.0);
  }

  run = RunPfdm("simulate --phantom lv --nobreathing --tags 20 --out " + dir +
                "/still.csv");
  ASSERT_EQ(run.exit_code, 0) << run.error;
  const nlohmann::json still =
      nlohmann::json::parse(ReadText(dir + "/still_truth.json"));
  EXPECT_EQ(still["breathing"], false);
  EXPECT_EQ(still["frames"][4]["rigid"]["axial_shift_mm"].get<double>(), 0.0);
}

// Partial data: a mid-ventricular segment's tags, short-axis slices'
// contours (one id per point and frame).
TEST(LvPhantomCliTest, WritesPartialData) {
  const std::string dir = ScratchDirectory("partial");
  CommandResult run =
      RunPfdm("simulate --phantom lv --region midventricular --tags 40 --out " +
              dir + "/mid.csv");
  ASSERT_EQ(run.exit_code, 0) << run.error;
  EXPECT_NE(run.output.find("(lv systole midventricular tags, 5 frames x 40 "
                            "tags)"),
            std::string::npos)
      << run.output;
  EXPECT_EQ(CsvRows(dir + "/mid.csv"), 5 * 40);
  const nlohmann::json mid =
      nlohmann::json::parse(ReadText(dir + "/mid_truth.json"));
  EXPECT_EQ(mid["region"], "midventricular");
  EXPECT_EQ(mid["sampling"], "tags");
  EXPECT_EQ(mid["region_heights"][0].get<double>(), 0.30);
  EXPECT_EQ(mid["region_heights"][1].get<double>(), 0.72);
  EXPECT_FALSE(mid.contains("slice_heights"));

  run = RunPfdm(
      "simulate --phantom lv --sampling sax-slices --slices 4 --tags 80 "
      "--kinematics static --frames 2 --out " +
      dir + "/sax.csv");
  ASSERT_EQ(run.exit_code, 0) << run.error;
  EXPECT_EQ(CsvRows(dir + "/sax.csv"), 2 * 80);
  const nlohmann::json sax =
      nlohmann::json::parse(ReadText(dir + "/sax_truth.json"));
  EXPECT_EQ(sax["sampling"], "sax-slices");
  ASSERT_EQ(sax["slice_heights"].size(), 4u);
  EXPECT_NEAR(sax["slice_heights"][3].get<double>(), 0.9, 1e-12);
  // Frame 1's ids follow frame 0's: contours, not tracked tags.
  std::istringstream text(ReadText(dir + "/sax.csv"));
  std::string line;
  std::getline(text, line);
  std::vector<std::string> ids;
  while (std::getline(text, line)) {
    const size_t comma = line.find(',');
    ids.push_back(
        line.substr(comma + 1, line.find(',', comma + 1) - comma - 1));
  }
  std::sort(ids.begin(), ids.end());
  EXPECT_EQ(std::unique(ids.begin(), ids.end()), ids.end());
}

// The cylindrical segment (lv_cylinder.h), tags through its wall thickening
// as an incompressible wall: its truth names both, and reads the cylinder's
// own motion (CylinderDeformation: 12 % shortening by end-systole).
TEST(LvPhantomCliTest, WritesTheCylinder) {
  const std::string dir = ScratchDirectory("cylinder");
  const CommandResult run = RunPfdm(
      "simulate --phantom lv --geometry cylinder --thickening incompressible "
      "--wall_tags wall --tags 40 --out " +
      dir + "/c.csv");
  ASSERT_EQ(run.exit_code, 0) << run.error;
  EXPECT_EQ(CsvRows(dir + "/c.csv"), 5 * 40);
  const nlohmann::json truth =
      nlohmann::json::parse(ReadText(dir + "/c_truth.json"));
  EXPECT_EQ(truth["shell"], "cylinder");
  EXPECT_EQ(truth["thickening"], "incompressible");
  EXPECT_EQ(truth["region"], "midventricular");
  EXPECT_NEAR(
      truth["frames"][4]["longitudinal_shortening_percent"].get<double>(), 12.0,
      1e-9);
}

TEST(LvPhantomCliTest, RejectsBadFlagsInOneLine) {
  const std::string out = " --out " + ScratchDirectory("bad") + "/x.csv";
  struct Case {
    const char* flags;
    const char* message;
  };
  for (const Case& c : {
           Case{"--phantom heart", "unknown --phantom 'heart'"},
           Case{"--phantom lv --kinematics diastole",
                "unknown --kinematics 'diastole'"},
           Case{"--phantom lv --wall_tags peri", "unknown --wall_tags 'peri'"},
           Case{"--phantom lv --outliers 1.5",
                "--outliers must be between 0 and 1"},
           Case{"--phantom lv --frames 0",
                "--frames must be between 1 and 1000, got 0"},
           Case{"--kinematics cycle", "need --phantom lv"},
           Case{"--lesion", "need --phantom lv"},
           Case{"--nobreathing", "need --phantom lv"},
           Case{"--phantom lv --region apical", "unknown --region 'apical'"},
           Case{"--phantom lv --sampling lax", "unknown --sampling 'lax'"},
           Case{"--phantom lv --slices -1", "0 <= --slices <= 1000"},
           Case{"--phantom lv --geometry cube", "unknown --geometry 'cube'"},
           Case{"--phantom lv --thickening linear",
                "unknown --thickening 'linear'"},
           Case{"--geometry cylinder", "need --phantom lv"},
           Case{"--phantom lv --geometry cylinder --lesion",
                "cylinder: tags only"},
           Case{"--phantom lv --sampling sax-slices --slices 30 --tags 20",
                "20 points for 30 contours"},
           Case{"--region midventricular", "need --phantom lv"},
           Case{"--sampling sax-slices", "need --phantom lv"},
       }) {
    const CommandResult run = RunPfdm(std::string("simulate ") + c.flags + out);
    EXPECT_NE(run.exit_code, 0) << c.flags;
    EXPECT_NE(run.error.find(c.message), std::string::npos)
        << c.flags << ": " << run.error;
    EXPECT_EQ(std::count(run.error.begin(), run.error.end(), '\n'), 1)
        << run.error;
  }
}

// Tags through the wall: `pfdm fit` says it fits a solid and why, and
// fit.json names the cavity, the myocardium and the mass; --wall midwall
// keeps one surface and names its volume for what it is.
TEST(LvPhantomCliTest, TagsThroughTheWallFitASolid) {
  const std::string dir = ScratchDirectory("lv_wall");
  CommandResult run = RunPfdm(
      "simulate --phantom lv --wall_tags wall --frames 3 --tags 1000 --out " +
      dir + "/lv.csv");
  ASSERT_EQ(run.exit_code, 0) << run.error;
  run = RunPfdm("fit --local off --points " + dir + "/lv.csv --out " + dir +
                "/solid");
  ASSERT_EQ(run.exit_code, 0) << run.error;
  EXPECT_EQ(run.output.rfind("wall: solid (tags spread ", 0), 0u) << run.output;
  const nlohmann::json solid =
      nlohmann::json::parse(ReadText(dir + "/solid/fit.json"));
  EXPECT_EQ(solid["model"]["wall"], "solid");
  EXPECT_EQ(solid["model"]["volume_surface"], "cavity");
  EXPECT_EQ(solid["settings"]["wall"], "auto");
  const auto& ed = solid["frames"][0];
  EXPECT_GT(ed["lv_mass_g"].get<double>(), 100.0);
  EXPECT_NEAR(ed["lv_mass_g"].get<double>(),
              1.05 * ed["myocardial_volume_ml"].get<double>(), 1e-9);
  // The phantom's ED cavity is 107 ml (lv_phantom.h).
  EXPECT_NEAR(ed["cavity_volume_ml"].get<double>(), 107.0, 5.0);
  EXPECT_GT(
      solid["frames"][2]["clinical"]["wall_thickening_percent"].get<double>(),
      10.0);
  EXPECT_TRUE(solid["regions"][0].contains("thickening_percent"));
  EXPECT_TRUE(solid.contains("ejection_fraction"));
  EXPECT_NE(ReadText(dir + "/solid/report.html").find("LV mass at ED"),
            std::string::npos);

  run = RunPfdm("fit --local off --wall midwall --points " + dir +
                "/lv.csv --out " + dir + "/midwall");
  ASSERT_EQ(run.exit_code, 0) << run.error;
  EXPECT_EQ(run.output.rfind("wall: midwall (--wall midwall)", 0), 0u)
      << run.output;
  const nlohmann::json midwall =
      nlohmann::json::parse(ReadText(dir + "/midwall/fit.json"));
  EXPECT_FALSE(midwall.contains("ejection_fraction"));
  EXPECT_GT(midwall["frames"][0]["midwall_volume_ml"].get<double>(), 150.0);
  EXPECT_FALSE(midwall["frames"][0].contains("lv_mass_g"));
}

// --loss with --loss_scale auto (the default): fit.json records "auto"
// and each frame's measured scale, the frames' files each point's weight;
// a number is recorded as given; without a loss neither.
TEST(LvPhantomCliTest, ARobustLossRecordsItsScaleAndWeights) {
  const std::string dir = ScratchDirectory("lv_loss");
  CommandResult run = RunPfdm(
      "simulate --phantom lv --outliers 0.05 --frames 3 --tags 500 --out " +
      dir + "/lv.csv");
  ASSERT_EQ(run.exit_code, 0) << run.error;
  const std::string fit =
      "fit --local off --wall midwall --points " + dir + "/lv.csv --out " + dir;
  run = RunPfdm(fit + "/auto --loss cauchy --vtk_format both");
  ASSERT_EQ(run.exit_code, 0) << run.error;
  nlohmann::json settings =
      nlohmann::json::parse(ReadText(dir + "/auto/fit.json"))["settings"];
  EXPECT_EQ(settings["loss"], "cauchy");
  EXPECT_EQ(settings["loss_scale"], "auto");
  ASSERT_EQ(settings["loss_scale_mm"].size(), 3u);
  // Frame 0's distances along the normal: sigma about the 0.5 mm noise,
  // times cauchy's 2.385.
  EXPECT_NEAR(settings["loss_scale_mm"][0].get<double>(), 2.385 * 0.55, 0.3);
  for (const char* file : {"/auto/frame_002.vtk", "/auto/frame_002.vtp"}) {
    EXPECT_NE(ReadText(dir + file).find("loss_weight"), std::string::npos)
        << file;
  }
  run = RunPfdm(fit + "/fixed --loss huber --loss_scale 2");
  ASSERT_EQ(run.exit_code, 0) << run.error;
  settings =
      nlohmann::json::parse(ReadText(dir + "/fixed/fit.json"))["settings"];
  EXPECT_EQ(settings["loss_scale"].get<double>(), 2.0);
  EXPECT_EQ(settings["loss_scale_mm"].get<double>(), 2.0);
  run = RunPfdm(fit + "/none --vtk_format vtk");
  ASSERT_EQ(run.exit_code, 0) << run.error;
  settings =
      nlohmann::json::parse(ReadText(dir + "/none/fit.json"))["settings"];
  EXPECT_FALSE(settings.contains("loss_scale"));
  EXPECT_EQ(ReadText(dir + "/none/frame_002.vtk").find("loss_weight"),
            std::string::npos);
}

}  // namespace
}  // namespace pfdm

namespace pfdm {
namespace {

// The truth's RV insertion, given to `pfdm fit --rv_insertion`, makes the
// segments the AHA's: named, said to be anatomical in fit.json, the
// console and the report; without it they say they are not; a bad value is
// refused before the fit.
TEST(LvPhantomCliTest, RvInsertionAnchorsTheAhaSegments) {
  const std::string dir = ScratchDirectory("lv");
  CommandResult run =
      RunPfdm("simulate --phantom lv --lesion --tags 300 --frames 3 --out " +
              dir + "/lv.csv");
  ASSERT_EQ(run.exit_code, 0) << run.error;
  const nlohmann::json truth =
      nlohmann::json::parse(ReadText(dir + "/lv_truth.json"));
  std::string flag;
  for (const char* which : {"anterior", "inferior"}) {
    for (const auto& x : truth["rv_insertion"][which]) {
      flag += (flag.empty() ? "" : ",") + std::to_string(x.get<double>());
    }
  }
  run = RunPfdm("fit --local off --points " + dir + "/lv.csv --rv_insertion " +
                flag + " --out " + dir + "/aha");
  ASSERT_EQ(run.exit_code, 0) << run.error;
  EXPECT_NE(run.output.find("segments: AHA, anatomical (--rv_insertion)"),
            std::string::npos)
      << run.output;
  const nlohmann::json aha =
      nlohmann::json::parse(ReadText(dir + "/aha/fit.json"));
  EXPECT_EQ(aha["segments_anatomical"], true);
  EXPECT_NEAR(aha["segments"]["rv_insertion"]["septal_arc_deg"].get<double>(),
              120.0, 5.0);
  EXPECT_EQ(aha["regions"][7]["name"], "mid anteroseptal");
  EXPECT_EQ(aha["regions"][16]["name"], "apex");
  const std::string report = ReadText(dir + "/aha/report.html");
  EXPECT_NE(report.find("mid anteroseptal"), std::string::npos);
  EXPECT_NE(report.find("The segments are anatomical"), std::string::npos);

  run = RunPfdm("fit --local off --points " + dir + "/lv.csv --out " + dir +
                "/plain");
  ASSERT_EQ(run.exit_code, 0) << run.error;
  EXPECT_NE(run.output.find("segments: not anatomical (no RV insertion "
                            "given)"),
            std::string::npos);
  const nlohmann::json plain =
      nlohmann::json::parse(ReadText(dir + "/plain/fit.json"));
  EXPECT_EQ(plain["segments_anatomical"], false);
  EXPECT_EQ(plain["regions"][7]["name"], "mid 2");
  EXPECT_NE(ReadText(dir + "/plain/report.html")
                .find("The segments are not anatomical"),
            std::string::npos);

  run = RunPfdm("fit --points " + dir + "/lv.csv --rv_insertion 1,2 --out " +
                dir + "/bad");
  EXPECT_NE(run.exit_code, 0);
  EXPECT_NE(run.error.find("--rv_insertion '1,2'"), std::string::npos)
      << run.error;
  EXPECT_FALSE(fs::exists(dir + "/bad/fit.json"));
}

}  // namespace
}  // namespace pfdm
