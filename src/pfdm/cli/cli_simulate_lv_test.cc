// End-to-end runs of `pfdm simulate --phantom lv`.
#include <algorithm>
#include <filesystem>
#include <sstream>

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

  run = RunPfdm("simulate --phantom lv --nobreathing --tags 20 --out " + dir +
                "/still.csv");
  ASSERT_EQ(run.exit_code, 0) << run.error;
  const nlohmann::json still =
      nlohmann::json::parse(ReadText(dir + "/still_truth.json"));
  EXPECT_EQ(still["breathing"], false);
  EXPECT_EQ(still["frames"][4]["rigid"]["axial_shift_mm"].get<double>(), 0.0);
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
           Case{"--phantom lv --wall_tags endo", "unknown --wall_tags 'endo'"},
           Case{"--phantom lv --outliers 0.1", "--outliers is for"},
           Case{"--phantom lv --frames 0", "1 <= --frames <= 1000"},
           Case{"--kinematics cycle", "need --phantom lv"},
           Case{"--lesion", "need --phantom lv"},
           Case{"--nobreathing", "need --phantom lv"},
       }) {
    const CommandResult run = RunPfdm(std::string("simulate ") + c.flags + out);
    EXPECT_NE(run.exit_code, 0) << c.flags;
    EXPECT_NE(run.error.find(c.message), std::string::npos)
        << c.flags << ": " << run.error;
    EXPECT_EQ(std::count(run.error.begin(), run.error.end(), '\n'), 1)
        << run.error;
  }
}

}  // namespace
}  // namespace pfdm
