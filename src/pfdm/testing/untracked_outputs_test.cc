// End to end: what contours cannot show (rotation, twist, torsion, shear)
// is null in fit.json, empty in summary.csv, n/a on the report's cards and
// absent from its plots; the same data as tags give numbers.  On the
// independent LV phantom, and on biv-me patient 1's contours when
// ../shared/data is there.
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "gtest/gtest.h"
#include "nlohmann/json.hpp"
#include "pfdm/testing/test_util.h"

namespace pfdm {
namespace {

// The clinical keys a turn about the axis makes; a solid adds its walls'.
const std::vector<std::string> kRotationKeys = {
    "net_twist_deg",      "apex_rotation_deg", "base_rotation_deg",
    "torsion_deg_per_cm", "shear_angle_deg",   "gcl_percent"};
const std::vector<std::string> kWallRotationKeys = {
    "endo_apex_rotation_deg", "endo_base_rotation_deg", "endo_net_twist_deg",
    "epi_apex_rotation_deg",  "epi_base_rotation_deg",  "epi_net_twist_deg"};

// The fields of summary.csv's row of case `name`.
std::vector<std::string> SummaryRow(const std::string& csv,
                                    const std::string& name) {
  std::istringstream in(csv);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind(name + ",", 0) != 0) continue;
    std::vector<std::string> fields;
    std::istringstream row(line + ",");  // The empty last field kept.
    for (std::string f; std::getline(row, f, ',');) fields.push_back(f);
    return fields;
  }
  ADD_FAILURE() << "no row " << name << " in " << csv;
  return std::vector<std::string>(19);
}

// summary.csv's columns.
constexpr int kEsFrame = 8;
constexpr int kLvMass = 10;
constexpr int kNetTwist = 12;
constexpr int kShortening = 13;
constexpr int kRadial = 14;

// The points of csv (frame,id,x,y,z) with each id made unique per frame:
// the same positions as contours.
void WriteAsContours(const std::string& csv, const std::string& out) {
  std::istringstream in(ReadText(csv));
  std::ostringstream text;
  std::string line;
  std::getline(in, line);
  text << line << '\n';
  while (std::getline(in, line)) {
    const size_t a = line.find(','), b = line.find(',', a + 1);
    const long frame = std::stol(line.substr(0, a));
    const long id = std::stol(line.substr(a + 1, b - a - 1));
    text << frame << ',' << id + 1000000 * frame << line.substr(b) << '\n';
  }
  WriteText(out, text.str());
}

// Every frame's rotations null and the contraction a number; the regions'
// rotation and Ecl null, their Ecc a number; every frame listed.
void ExpectRotationNull(const nlohmann::json& fit, bool solid) {
  std::vector<std::string> keys = kRotationKeys;
  if (solid)
    keys.insert(keys.end(), kWallRotationKeys.begin(), kWallRotationKeys.end());
  const size_t frames = fit["frames"].size();
  for (size_t t = 0; t < frames; ++t) {
    const nlohmann::json& clinical = fit["frames"][t]["clinical"];
    for (const std::string& key : keys) {
      EXPECT_TRUE(clinical.at(key).is_null()) << key << " frame " << t;
    }
    EXPECT_TRUE(clinical["radial_contraction_percent"].is_number()) << t;
    EXPECT_TRUE(clinical["gcs_percent"].is_number()) << t;
  }
  for (const nlohmann::json& region : fit["regions"]) {
    for (size_t t = 0; t < frames; ++t) {
      EXPECT_TRUE(region["rotation_deg"][t].is_null());
      EXPECT_TRUE(region["ecl_percent"][t].is_null());
      EXPECT_TRUE(region["ecc_percent"][t].is_number());
    }
  }
  std::vector<int> all(frames);
  for (size_t t = 0; t < frames; ++t) all[t] = static_cast<int>(t);
  EXPECT_EQ(fit["not_measured"]["frames"], nlohmann::json(all));
}

// The report of a fit without tracked points: n/a cards, no rotation
// curves or map, no NaN printed; contraction a number.
void ExpectReportSaysNA(const std::string& dir, bool solid) {
  const std::string html = WithoutScripts(ReadText(dir + "/report.html"));
  EXPECT_NE(html.find("net twist at ES<b>n/a</b>"), std::string::npos);
  EXPECT_NE(html.find("torsion at ES<b>n/a</b>shear angle n/a</div>"),
            std::string::npos);
  EXPECT_EQ(
      html.find("endo / epi net twist at ES<b>n/a</b>") != std::string::npos,
      solid);
  EXPECT_NE(html.find("No tracked points:</b>"), std::string::npos);
  EXPECT_NE(html.find("radial contraction at ES<b>"), std::string::npos);
  EXPECT_EQ(html.find("radial contraction at ES<b>n/a"), std::string::npos);
  // The bull's-eye and cycle plots, inlined: no rotation map or panel.
  EXPECT_NE(html.find("radial contraction at ES, %"), std::string::npos);
  EXPECT_EQ(html.find("rotation at ES, degrees"), std::string::npos);
  EXPECT_EQ(html.find("rotation about the LV axis"), std::string::npos);
  EXPECT_EQ(html.find("nan"), std::string::npos);
  EXPECT_EQ(html.find("NaN"), std::string::npos);
  const std::string parameters = ReadText(dir + "/parameters.svg");
  EXPECT_EQ(CountOf(parameters, "n/a: no tracked points"), solid ? 2 : 1);
}

// The LV phantom's tags, and the same points as contours, in one batch.
TEST(UntrackedOutputsTest, LvPhantomContoursReportNoRotation) {
  const std::string dir = ScratchDirectory("lv");
  CommandResult run = RunPfdm("simulate --phantom lv --out " + dir + "/lv.csv");
  ASSERT_EQ(run.exit_code, 0) << run.error;
  WriteAsContours(dir + "/lv.csv", dir + "/lv_contours.csv");
  WriteText(dir + "/cases.csv",
            "case,points\ntags,lv.csv\ncontours,lv_contours.csv\n");
  const std::string out = dir + "/out";
  run = RunPfdm("batch --manifest " + dir + "/cases.csv --out " + out +
                " --jobs 2");
  ASSERT_EQ(run.exit_code, 0) << run.error;
  EXPECT_NE(run.output.find("contours: done, ok, 5 frames"), std::string::npos)
      << run.output;
  EXPECT_NE(run.output.find("net twist at ES n/a"), std::string::npos)
      << run.output;

  const std::string summary = ReadText(out + "/summary.csv");
  const std::vector<std::string> tags = SummaryRow(summary, "tags");
  const std::vector<std::string> contours = SummaryRow(summary, "contours");
  // The phantom twists 13 degrees by ES; a mid-wall fit reads 8.4.
  EXPECT_NEAR(std::stod(tags[kNetTwist]), 8.4, 2.0) << summary;
  EXPECT_EQ(contours[kNetTwist], "") << summary;
  EXPECT_EQ(contours[kEsFrame], "4");
  // Shortening (17 % true) and radial contraction are still measured.
  EXPECT_NEAR(std::stod(contours[kShortening]), 17.0, 3.0);
  EXPECT_NEAR(std::stod(contours[kRadial]), std::stod(tags[kRadial]), 5.0);

  const nlohmann::json tag_fit =
      nlohmann::json::parse(ReadText(out + "/tags/fit.json"));
  EXPECT_FALSE(tag_fit.contains("not_measured"));
  for (const std::string& key : kRotationKeys) {
    EXPECT_TRUE(tag_fit["frames"][4]["clinical"][key].is_number()) << key;
  }
  EXPECT_LT(tag_fit["regions"][15]["rotation_deg"][4].get<double>(), -2.0);
  ExpectRotationNull(
      nlohmann::json::parse(ReadText(out + "/contours/fit.json")), false);

  const std::string tag_html =
      WithoutScripts(ReadText(out + "/tags/report.html"));
  EXPECT_NE(tag_html.find("rotation at ES, degrees"), std::string::npos);
  EXPECT_NE(tag_html.find("rotation about the LV axis"), std::string::npos);
  EXPECT_EQ(tag_html.find("n/a"), std::string::npos);
  EXPECT_EQ(tag_html.find("nan"), std::string::npos);
  ExpectReportSaysNA(out + "/contours", false);
}

// biv-me patient 1's contours of both walls (a solid): every rotation of
// the mid-wall and of each wall is null, the cavity's ejection fraction
// and the LV mass are numbers.
TEST(UntrackedOutputsTest, BivMeContoursReportNoRotation) {
  const std::string shared = SharedDataDirectory();
  if (shared.empty()) GTEST_SKIP() << "../shared/data is absent";
  const std::string dir = ScratchDirectory("biv_me");
  WriteText(dir + "/cases.csv",
            "case,points\nbiv," + shared + "/biv-me-patient1/guidepoints\n");
  const std::string out = dir + "/out";
  const CommandResult run =
      RunPfdm("batch --manifest " + dir + "/cases.csv --out " + out +
              " --contours lv-cavity,lv-epi");
  ASSERT_EQ(run.exit_code, 0) << run.error;
  const nlohmann::json fit =
      nlohmann::json::parse(ReadText(out + "/biv/fit.json"));
  EXPECT_EQ(fit["model"]["wall"], "solid");
  ASSERT_EQ(fit["frames"].size(), 25u);
  ExpectRotationNull(fit, true);
  EXPECT_NEAR(fit["ejection_fraction"]["ratio"].get<double>(), 0.6, 0.05);
  const std::vector<std::string> row =
      SummaryRow(ReadText(out + "/summary.csv"), "biv");
  EXPECT_EQ(row[kNetTwist], "");
  EXPECT_GT(std::stod(row[kLvMass]), 80.0);
  EXPECT_GT(std::stod(row[kShortening]), 5.0);
  ExpectReportSaysNA(out + "/biv", true);
}

}  // namespace
}  // namespace pfdm
