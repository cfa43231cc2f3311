#include "pfdm/report/fit_plots.h"

#include <cmath>

#include "gtest/gtest.h"
#include "pfdm/phantom/phantom.h"
#include "pfdm/testing/test_util.h"
#include "pfdm/util/error.h"

namespace pfdm {
namespace {

TEST(FitPlotsTest, SixPanelsWithOneLegendEntryPerFrame) {
  PhantomOptions options;
  options.num_points = 1;
  const Phantom phantom = MakePhantom(options);
  const std::string svg = ParameterPlotsSvg(phantom.truth);
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  for (const char* title :
       {"radial: a1 / a1 at frame 0", "radial: a2 / a2 at frame 0",
        "longitudinal: a3 / a3 at frame 0", "twist tau (degrees)",
        "bending b0 (mm)", "bending b2 (mm)"}) {
    EXPECT_EQ(CountOf(svg, title), 1) << title;
  }
  // gnuplot writes a key entry as <text><tspan ...>N</tspan>; five frames.
  for (int t = 0; t < 5; ++t) {
    EXPECT_GE(CountOf(svg, ">" + std::to_string(t) + "</tspan>"), 1) << t;
  }
}

TEST(FitPlotsTest, CycleCurvesNameTheEjectionFraction) {
  std::vector<ClinicalSummary> summaries(3);
  const double volumes[] = {150, 60, 120};
  for (int t = 0; t < 3; ++t) {
    summaries[t].frame = t;
    summaries[t].volume_ml = volumes[t];
  }
  const std::string svg = CycleCurvesSvg(summaries);
  EXPECT_NE(svg.find("EF 60.0 %"), std::string::npos);
  EXPECT_NE(svg.find("net twist"), std::string::npos);
}

// With trigger times the curves run against them, ED and ES marked at
// theirs; without, against the frame number.
TEST(FitPlotsTest, CycleCurvesRunAgainstTheTriggerTimeWhereKnown) {
  std::vector<ClinicalSummary> summaries(4);
  const double volumes[] = {100, 150, 60, 120};
  for (int t = 0; t < 4; ++t) {
    summaries[t].frame = t;
    summaries[t].volume_ml = volumes[t];
  }
  const SvgPlot by_frame = CycleCurves(summaries, "cavity", 1);
  EXPECT_NE(by_frame.script.find("set xlabel 'frame'"), std::string::npos);
  EXPECT_NE(by_frame.script.find("set label 1 'ED' at 1,150"),
            std::string::npos)
      << by_frame.script;
  EXPECT_EQ(by_frame.data.front().rows[3][0], 3.0);
  for (int t = 0; t < 4; ++t) summaries[t].time_ms = 40.0 * t + 12.5;
  const SvgPlot timed = CycleCurves(summaries, "cavity", 1);
  EXPECT_NE(timed.script.find("set xlabel 'time from the trigger (ms)'"),
            std::string::npos);
  EXPECT_NE(timed.script.find("set label 1 'ED' at 52.5,150"),
            std::string::npos)
      << timed.script;
  EXPECT_NE(timed.script.find("set label 2 'ES' at 92.5,60"),
            std::string::npos);
  EXPECT_EQ(timed.data.front().rows[3][0], 132.5);
  EXPECT_NE(RenderSvgString(timed).find("EF 60.0 %"), std::string::npos);
}

// Rotations not measured (contours) are left out: with none measured, the
// rotation panel goes; with some, their frames' rows are NaN, which gnuplot
// skips.  The twist panels of the parameter plots say why they are empty.
TEST(FitPlotsTest, CurvesLeaveOutRotationsNotMeasured) {
  std::vector<ClinicalSummary> summaries(3);
  const double volumes[] = {150, 60, 120};
  for (int t = 0; t < 3; ++t) {
    summaries[t].frame = t;
    summaries[t].volume_ml = volumes[t];
    summaries[t].net_twist_deg = 4.0 * t;
  }
  LeaveOutRotation(&summaries[1]);
  const SvgPlot some = CycleCurves(summaries);
  EXPECT_NE(some.script.find("layout 1,3"), std::string::npos);
  EXPECT_NE(some.script.find("net twist"), std::string::npos);
  ASSERT_EQ(some.data.front().rows.size(), 3u);
  EXPECT_EQ(some.data.front().rows[2][4], 8.0);
  EXPECT_TRUE(std::isnan(some.data.front().rows[1][4]));
  EXPECT_EQ(some.data.front().rows[1][5], 0.0);  // Contraction stays.
  const std::string some_svg = RenderSvgString(some);
  EXPECT_NE(some_svg.find("rotation about the LV axis"), std::string::npos);
  for (ClinicalSummary& s : summaries) LeaveOutRotation(&s);
  const SvgPlot none = CycleCurves(summaries);
  EXPECT_NE(none.script.find("layout 1,2"), std::string::npos);
  const std::string none_svg = RenderSvgString(none);
  EXPECT_EQ(none_svg.find("rotation about the LV axis"), std::string::npos);
  EXPECT_EQ(none_svg.find("net twist"), std::string::npos);
  EXPECT_NE(none_svg.find("EF 60.0 %"), std::string::npos);
  EXPECT_NE(none_svg.find("contraction"), std::string::npos);

  PhantomOptions options;
  options.num_points = 1;
  const Phantom phantom = MakePhantom(options);
  EXPECT_EQ(ParameterPlots(phantom.truth, std::vector<bool>(5, true)).script,
            ParameterPlots(phantom.truth).script);
  EXPECT_EQ(ParameterPlotsSvg(phantom.truth).find("n/a"), std::string::npos);
  const SvgPlot held =
      ParameterPlots(phantom.truth, {true, true, true, true, false});
  const std::vector<double>& knot0_frame4 = held.data.front().rows[4 * 19];
  EXPECT_EQ(knot0_frame4[0], 0.0);
  EXPECT_TRUE(std::isnan(knot0_frame4[4]));   // tau
  EXPECT_FALSE(std::isnan(knot0_frame4[1]));  // a1
  const std::string no_twist =
      ParameterPlotsSvg(phantom.truth, std::vector<bool>(5, false));
  EXPECT_EQ(CountOf(no_twist, "n/a: no tracked points"), 1);
  EXPECT_EQ(CountOf(no_twist, "twist tau (degrees)"), 1);
}

}  // namespace
}  // namespace pfdm
