// pfdm fit's verdict end to end: what a clean fit, a fit the regularizer
// decides and an absurd fit say, and their exit codes.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "Eigen/Geometry"
#include "gtest/gtest.h"
#include "nlohmann/json.hpp"
#include "pfdm/io/point_reader.h"
#include "pfdm/testing/test_util.h"

namespace pfdm {
namespace {

nlohmann::json FitJsonOf(const std::string& dir) {
  return nlohmann::json::parse(ReadText(dir + "/fit/fit.json"));
}

std::string Phantom(const std::string& dir) {
  const CommandResult run =
      RunPfdm("simulate --frames 3 --tags 600 --out " + dir + "/phantom.csv");
  EXPECT_EQ(run.exit_code, 0) << run.error;
  return dir + "/phantom.csv";
}

TEST(CliVerdictTest, ACleanFitIsOkAndSaysNothingMore) {
  const std::string dir = ScratchDirectory("cli_verdict_clean");
  const CommandResult run =
      RunPfdm("fit --points " + Phantom(dir) + " --out " + dir + "/fit");
  ASSERT_EQ(run.exit_code, 0) << run.error;
  EXPECT_EQ(run.error, "");
  const nlohmann::json fit = FitJsonOf(dir);
  EXPECT_EQ(fit["quality"]["overall"], "ok");
  EXPECT_EQ(fit["quality"]["frames_ok"], 3);
  EXPECT_EQ(fit["frames"][1]["quality"], "ok");
  EXPECT_TRUE(fit["frames"][1]["quality_reasons"].empty());
  EXPECT_NE(ReadText(dir + "/fit/report.html").find("Quality: ok."),
            std::string::npos);
}

// --prior 1 holds every frame near the one before: the prior, not the
// data, decides the fit (shortening 7.6 % against 17 once, exit 0 and no
// word).
TEST(CliVerdictTest, APriorThatWinsIsNamed) {
  const std::string dir = ScratchDirectory("cli_verdict_prior");
  const CommandResult run = RunPfdm("fit --prior 1 --points " + Phantom(dir) +
                                    " --out " + dir + "/fit");
  const nlohmann::json fit = FitJsonOf(dir);
  for (int t = 0; t < 3; ++t) {
    bool named = false;
    for (const auto& reason : fit["frames"][t]["quality_reasons"]) {
      named = named || (reason["code"] == "prior" &&
                        reason["text"].get<std::string>().rfind(
                            "without the prior", 0) == 0);
    }
    EXPECT_TRUE(named) << t << fit["frames"][t]["quality_reasons"];
  }
  EXPECT_NE(run.error.find("pfdm: frame 2: "), std::string::npos) << run.error;
}

// A uniform random cloud: no ventricle, yet once EF 0.96 and exit 0.  Its
// points keep their ids from frame to frame, moved by up to 1 mm: a fresh
// cloud per frame under the same ids is scrambled ids, an input error
// (fit/stages/tracked_ids.h).
TEST(CliVerdictTest, ARandomCloudFailsWithExitThree) {
  const std::string dir = ScratchDirectory("cli_verdict_cloud");
  std::mt19937 random(11);
  std::uniform_real_distribution<double> coordinate(-50.0, 50.0);
  std::uniform_real_distribution<double> jitter(-1.0 / std::sqrt(3.0),
                                                1.0 / std::sqrt(3.0));
  double cloud[500][3];
  for (auto& point : cloud) {
    for (double& x : point) x = coordinate(random);
  }
  std::string csv = "frame,id,x,y,z\n";
  for (int t = 0; t < 3; ++t) {
    for (int id = 0; id < 500; ++id) {
      double x[3];
      for (int i = 0; i < 3; ++i)
        x[i] = cloud[id][i] + (t ? jitter(random) : 0);
      char line[128];
      std::snprintf(line, sizeof(line), "%d,%d,%.3f,%.3f,%.3f\n", t, id, x[0],
                    x[1], x[2]);
      csv += line;
    }
  }
  WriteText(dir + "/cloud.csv", csv);
  const CommandResult run =
      RunPfdm("fit --points " + dir + "/cloud.csv --out " + dir + "/fit");
  EXPECT_EQ(run.exit_code, 3) << run.error;
  EXPECT_NE(run.error.find("pfdm: the fit is implausible"), std::string::npos)
      << run.error;
  const nlohmann::json fit = FitJsonOf(dir);
  EXPECT_EQ(fit["quality"]["overall"], "failed");
  bool rms_size = false;
  for (const auto& reason : fit["frames"][0]["quality_reasons"]) {
    rms_size = rms_size || reason["code"] == "rms_size";
  }
  EXPECT_TRUE(rms_size) << fit["frames"][0]["quality_reasons"];
  EXPECT_NE(ReadText(dir + "/fit/report.html").find("Quality: failed."),
            std::string::npos);
}

// Data in metres: every volume a millionth of a heart's.
TEST(CliVerdictTest, DataInMetresFailOnTheirVolumes) {
  const std::string dir = ScratchDirectory("cli_verdict_metres");
  const std::string phantom = ReadText(Phantom(dir));
  std::string csv = "frame,id,x,y,z\n";
  int frame, id;
  double x, y, z;
  for (size_t at = phantom.find('\n') + 1; at < phantom.size();
       at = phantom.find('\n', at) + 1) {
    if (std::sscanf(phantom.c_str() + at, "%d,%d,%lf,%lf,%lf", &frame, &id, &x,
                    &y, &z) != 5) {
      break;
    }
    char line[160];
    std::snprintf(line, sizeof(line), "%d,%d,%.9f,%.9f,%.9f\n", frame, id,
                  x * 1e-3, y * 1e-3, z * 1e-3);
    csv += line;
  }
  WriteText(dir + "/metres.csv", csv);
  const CommandResult run =
      RunPfdm("fit --points " + dir + "/metres.csv --out " + dir + "/fit");
  EXPECT_EQ(run.exit_code, 3) << run.error;
  EXPECT_NE(run.error.find("are the data in mm?"), std::string::npos)
      << run.error;
}

// Tags on a mid-ventricular segment only (no apex): the fit finds the long
// axis and says in every frame that what it reports of the apex is
// extrapolated; a warning, exit 0.
TEST(CliVerdictTest, ASegmentWithoutApexSaysTheApexIsExtrapolated) {
  const std::string dir = ScratchDirectory("cli_verdict_segment");
  CommandResult run = RunPfdm(
      "simulate --phantom lv --region midventricular --frames 3 --out " + dir +
      "/segment.csv");
  ASSERT_EQ(run.exit_code, 0) << run.error;
  run = RunPfdm("fit --points " + dir + "/segment.csv --out " + dir + "/fit");
  EXPECT_EQ(run.exit_code, 0) << run.error;
  const nlohmann::json fit = FitJsonOf(dir);
  EXPECT_FALSE(fit["model"]["apex_in_data"].get<bool>());
  EXPECT_EQ(fit["quality"]["overall"], "warning");
  for (const auto& frame : fit["frames"]) {
    bool extrapolated = false;
    for (const auto& reason : frame["quality_reasons"]) {
      extrapolated = extrapolated || reason["code"] == "extrapolated";
    }
    EXPECT_TRUE(extrapolated) << frame["quality_reasons"];
  }
  EXPECT_NE(run.error.find("are extrapolated"), std::string::npos) << run.error;
  // What lies below the data is null, unless asked for.
  EXPECT_EQ(fit["not_measured"]["extrapolated"]["levels"],
            nlohmann::json({"apical", "apex cap"}));
  EXPECT_TRUE(fit["frames"][2]["clinical"]["net_twist_deg"].is_null());
  EXPECT_TRUE(fit["frames"][2]["clinical"]["base_rotation_deg"].is_number());
  EXPECT_TRUE(fit["regions"][15]["ecc_percent"][2].is_null());
  EXPECT_TRUE(fit["regions"][6]["ecc_percent"][2].is_number());
  run = RunPfdm("fit --extrapolated --points " + dir + "/segment.csv --out " +
                dir + "/shown/fit");
  EXPECT_EQ(run.exit_code, 0) << run.error;
  const nlohmann::json shown = FitJsonOf(dir + "/shown");
  EXPECT_TRUE(shown["not_measured"]["extrapolated"]["shown"].get<bool>());
  EXPECT_TRUE(shown["frames"][2]["clinical"]["net_twist_deg"].is_number());
  EXPECT_TRUE(shown["regions"][15]["ecc_percent"][2].is_number());

  // The same data told that the apex is the centre of their lowest ring
  // (the data's own 5 % lowest along the axis the fit found): the hint is
  // taken.  Once frame 0 did not settle on it: RMS 5.5 mm, closest points
  // moving by 22.6 mm, "CONVERGENCE" and exit 0, later a failed verdict;
  // with the mixed rounds (global_rounds.cc) it ended on its best round,
  // its points still moving by over 1 mm.  With frame 0's spin kept at the
  // start's where the section is round (frame_fit.cc) it comes within
  // 0.1 mm of settling, as close to the data as the fit without the hint,
  // and the verdict has nothing to say of it but the apex.
  const nlohmann::json& pose = fit["frames"][0]["pose"]["quaternion_wxyz"];
  const Eigen::Vector3d axis =
      Eigen::Quaterniond(pose[0], pose[1], pose[2], pose[3]) *
      Eigen::Vector3d::UnitZ();
  const PointSequence sequence = ReadPointsCsv(dir + "/segment.csv");
  const std::vector<DataPoint>& points = sequence.frames[0].points;
  std::vector<double> heights;
  for (const DataPoint& p : points) heights.push_back(axis.dot(p.position));
  std::vector<double> sorted = heights;
  std::sort(sorted.begin(), sorted.end());
  const double low = sorted[sorted.size() / 20];
  const double high = sorted[sorted.size() - 1 - sorted.size() / 20];
  Eigen::Vector3d apex = Eigen::Vector3d::Zero(), base = apex;
  int num_low = 0, num_high = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    if (heights[i] < low) apex += points[i].position, ++num_low;
    if (heights[i] > high) base += points[i].position, ++num_high;
  }
  apex /= num_low;
  base /= num_high;
  const auto text = [](const Eigen::Vector3d& x) {
    return std::to_string(x.x()) + "," + std::to_string(x.y()) + "," +
           std::to_string(x.z());
  };
  run = RunPfdm("fit --points " + dir + "/segment.csv --out " + dir +
                "/hinted/fit --apex=" + text(apex) + " --base=" + text(base));
  EXPECT_EQ(run.exit_code, 0) << run.error;
  const nlohmann::json hinted = FitJsonOf(dir + "/hinted");
  EXPECT_EQ(hinted["frames"][0]["quality"], "warning");
  EXPECT_NEAR(hinted["frames"][0]["rms_mm"].get<double>(),
              fit["frames"][0]["rms_mm"].get<double>(), 0.1);
  bool unsettled = false;
  for (const auto& reason : hinted["frames"][0]["quality_reasons"]) {
    unsettled = unsettled || reason["code"] == "unsettled";
  }
  EXPECT_FALSE(unsettled) << hinted["frames"][0]["quality_reasons"];
  EXPECT_LT(hinted["frames"][0]["correspondence_unsettled_mm"].get<double>(),
            0.2);
}

}  // namespace
}  // namespace pfdm
