// Issue 30: the intervals' half-widths shrink about like 1/sqrt(N) as
// points are added.  Each kind of data of the interval calibration
// (lv_interval_calibration_test.cc) fitted with 400 and with 1,600 points
// a frame, 2 noise seeds each; every number's mean sd at both, the ratio
// printed (docs/uncertainty.md, "Half-widths and the number of points",
// whose tables scripts/interval_calibration.sh takes from here).
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "gtest/gtest.h"
#include "pfdm/testing/lv_interval_cases.h"

namespace pfdm {
namespace {

using interval_cases::Case;
using interval_cases::FitLv;
using interval_cases::Judged;
using interval_cases::Numbers;
using interval_cases::PhantomOptions;

// Each number's sd, averaged over kShrinkSeeds noise draws of c with
// `num_points` points a frame (a pooled row, such as every segment's, over
// its segments too), by name.
constexpr int kShrinkSeeds = 2;
std::map<std::string, double> MeanSds(const Case& c, int num_points,
                                      std::vector<std::string>* names) {
  std::map<std::string, std::pair<double, int>> sums;
  for (int s = 0; s < kShrinkSeeds; ++s) {
    LvPhantomOptions options = PhantomOptions(c, s);
    options.num_tags = num_points;
    const LvPhantom phantom = MakeLvPhantom(options);
    for (const Judged& j :
         Numbers(FitLv(phantom, true, c.transmural), phantom, false)) {
      if (!(j.sd > 0.0)) continue;
      if (sums.count(j.name) == 0) names->push_back(j.name);
      sums[j.name].first += j.sd;
      ++sums[j.name].second;
    }
  }
  std::map<std::string, double> sds;
  for (const auto& [name, sum] : sums) sds[name] = sum.first / sum.second;
  return sds;
}

// sd(4N) / sd(N) per number at N = 400, printed as a table.
std::map<std::string, double> ShrinkRatios(const Case& c,
                                           const std::string& title) {
  constexpr int kFew = 400;
  std::vector<std::string> names, unused;
  const std::map<std::string, double> few = MeanSds(c, kFew, &names);
  const std::map<std::string, double> many = MeanSds(c, 4 * kFew, &unused);
  std::map<std::string, double> ratios;
  std::printf(
      "## %s: the sds at 400 and 1,600 points\n\n"
      "| number | sd at 400 | sd at 1,600 | ratio (1/sqrt(4) = 0.5) |\n"
      "| --- | --- | --- | --- |\n",
      title.c_str());
  for (const std::string& name : names) {
    if (many.count(name) == 0) continue;
    ratios[name] = many.at(name) / few.at(name);
    std::printf("| %s | %.4g | %.4g | %.3f |\n", name.c_str(), few.at(name),
                many.at(name), ratios[name]);
  }
  std::printf("\n");
  return ratios;
}

void ExpectRatios(const std::map<std::string, double>& ratios,
                  const std::vector<std::string>& names, double low,
                  double high) {
  for (const std::string& name : names) {
    ASSERT_EQ(ratios.count(name), 1u) << name;
    EXPECT_GE(ratios.at(name), low) << name;
    EXPECT_LE(ratios.at(name), high) << name;
  }
}

// Issue 30: the half-widths shrink about like 1/sqrt(N) as points are
// added (2 seeds at 400 and 1,600 points; docs/uncertainty.md, "Half-widths
// and the number of points").  The volumes' less (0.64-0.67): part of their
// sd is the length's, which the highest points and the apex set, and more
// points spread along the wall put more of them near the top but not
// higher (the knots' a3, docs/uncertainty.md).  GCS's more (0.41; why
// was not looked into).  At 1,600 points the intervals still held the
// noise-free fit in 0.935 of 30 draws, pooled (GCS 0.967).
TEST(LvIntervalShrinkTest, HalfWidthsShrinkWithMidwallTags) {
  const auto ratios = ShrinkRatios(Case(), "mid-wall tags");
  ExpectRatios(
      ratios,
      {"volume fraction", "net twist deg", "shortening %",
       "radial contraction %", "GLS %", "torsion deg/cm", "segments Ecc %",
       "segments radial %", "segments rotation deg", "segments Ell %"},
      0.42, 0.58);
  ExpectRatios(ratios, {"EDV ml", "ESV ml"}, 0.58, 0.75);
  ExpectRatios(ratios, {"GCS %"}, 0.33, 0.5);
}

// Through the wall most sds shrink faster (0.36-0.52, most under 0.5): the
// ranked depths' error, about a tenth of the wall at 400 tags, counts in sigma
// and shrinks as the ranks grow finer (docs/uncertainty.md, What it is).
// Segment 9's rotation shrinks 0.595 (0.57 before ES followed ED's errors,
// report/tracked_response.h); ESV 0.635 and the volume fraction 0.617
// since ED's noise through the held depths is counted once: that takes
// 0.28 ml^2 off ESV's variance at 400 tags and 0.02 at 1,600, the share
// through ED's covariance shrinking 14 times where the depths' noise does
// 3 (ED's sigma carries the ranks' error, which shrinks as they grow
// finer).
TEST(LvIntervalShrinkTest, HalfWidthsShrinkWithWallTags) {
  const auto ratios =
      ShrinkRatios(Case{LvTagLayer::kWall}, "tags through the wall");
  for (const auto& [name, ratio] : ratios) {
    EXPECT_GE(ratio, 0.3) << name;
    EXPECT_LE(ratio, 0.65) << name;
  }
}

// Contours: the numbers the slices' rings set shrink like 1/sqrt(N), those
// that hang on the length (the volumes, the ejection fraction, shortening,
// GLS, Ell) much less (0.79-0.85 on the endocardium's, 0.62-0.75 on both
// walls'): the slices stay
// where they are however densely each is traced, and the length is set by
// the apex and the top slice.  The errors shrink alike: at 1,600 points the
// intervals held the noise-free fit in 0.928 of 30 draws, pooled (the
// shortening's sd 0.54 against an rms error of 0.62, GLS's 0.42 and 0.49).
TEST(LvIntervalShrinkTest, HalfWidthsShrinkWithEndocardialContours) {
  const auto ratios =
      ShrinkRatios(Case{LvTagLayer::kEndocardium, LvSampling::kSaxSlices},
                   "endocardial contours");
  ExpectRatios(
      ratios,
      {"radial contraction %", "GCS %", "segments Ecc %", "segments radial %"},
      0.4, 0.6);
  ExpectRatios(ratios,
               {"volume fraction", "EDV ml", "ESV ml", "shortening %", "GLS %",
                "segments Ell %"},
               0.7, 0.92);
}

TEST(LvIntervalShrinkTest, HalfWidthsShrinkWithWallContours) {
  const auto ratios = ShrinkRatios(
      Case{LvTagLayer::kWall, LvSampling::kSaxSlices}, "both walls' contours");
  ExpectRatios(ratios,
               {"radial contraction %", "GCS %", "wall thickening %",
                "segments Ecc %", "segments radial %", "segments thickening %"},
               0.42, 0.58);
  ExpectRatios(ratios,
               {"volume fraction", "EDV ml", "ESV ml", "shortening %", "GLS %",
                "segments Ell %"},
               0.58, 0.85);
}
}  // namespace
}  // namespace pfdm
