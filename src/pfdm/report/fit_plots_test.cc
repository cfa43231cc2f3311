#include "pfdm/report/fit_plots.h"

#include <cmath>

#include "gtest/gtest.h"
#include "pfdm/phantom/phantom.h"
#include "pfdm/testing/test_util.h"
#include "pfdm/util/error.h"

namespace pfdm {
namespace {

TEST(FitPlotsTest, SixPanelsColouredByFrame) {
  PhantomOptions options;
  options.num_points = 1;
  const Phantom phantom = MakePhantom(options);
  const std::string svg = ParameterPlotsSvg(phantom.truth, {}, {}, 3);
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  for (const char* title :
       {"radial: a1 / a1 at frame 0", "radial: a2 / a2 at frame 0",
        "longitudinal: a3 / a3 at frame 0", "twist tau (degrees)",
        "bending b0 (mm)", "bending b2 (mm)"}) {
    EXPECT_EQ(CountOf(svg, title), 1) << title;
  }
  // No legend: a colour bar labelled 'frame' (on the first panel), and
  // each frame's line titled for hover, in each of the six panels; ED and
  // ES named.
  EXPECT_EQ(CountOf(svg, ">frame</tspan>"), 1);
  for (const char* title :
       {"<title>frame 0 (ED)</title>", "<title>frame 1</title>",
        "<title>frame 3 (ES)</title>", "<title>frame 4</title>"}) {
    EXPECT_EQ(CountOf(svg, title), 6) << title;
  }
}

// The twist panels leave out the frames whose rotation is not measured
// (contours), and say why they are empty where none is.
TEST(FitPlotsTest, TwistPanelsLeaveOutRotationsNotMeasured) {
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
