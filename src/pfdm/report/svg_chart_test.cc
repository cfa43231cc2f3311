#include "pfdm/report/svg_chart.h"

#include <cmath>

#include "gtest/gtest.h"
#include "pfdm/testing/test_util.h"

namespace pfdm {
namespace {

TEST(SvgChartTest, RoundTicks) {
  EXPECT_EQ(RoundTicks(0.0, 97.0, 5),
            (std::vector<double>{0.0, 20.0, 40.0, 60.0, 80.0}));
  EXPECT_EQ(RoundTicks(-21.3, 2.0, 5),
            (std::vector<double>{-20.0, -15.0, -10.0, -5.0, 0.0}));
  const std::vector<double> fine = RoundTicks(0.11, 0.149, 4);
  ASSERT_EQ(fine.size(), 4u);
  EXPECT_NEAR(fine[0], 0.11, 1e-12);
  EXPECT_NEAR(fine[3], 0.14, 1e-12);
}

// Every value a dot whose hover text gives it; a gap where NaN; ED and ES
// marked; names escaped.
TEST(SvgChartTest, DotsWithValuesOnHover) {
  Chart chart;
  chart.title = "strain <global>";
  chart.x_label = "time from the trigger (ms)";
  chart.y_label = "percent";
  chart.x = {0, 40, 80, 120};
  chart.series = {{"GCS", {0.0, -8.5, -17.25, -12.0}, "#222"},
                  {"apical", {0.0, NAN, -20.0, -15.0}, "#c0392b"}};
  chart.ed = 0;
  chart.es = 2;
  const std::string svg = ChartSvg(chart);
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
  EXPECT_EQ(CountOf(svg, "<circle"), 4 + 3);
  EXPECT_NE(svg.find("<title>GCS, time from the trigger (ms) 80: -17.25"
                     "</title>"),
            std::string::npos);
  EXPECT_NE(svg.find("<title>apical, time from the trigger (ms) 120: "
                     "-15.00</title>"),
            std::string::npos);
  // The NaN breaks apical's path: two pieces, each started by M.
  const size_t apical = svg.find("<title>apical</title><path d='");
  ASSERT_NE(apical, std::string::npos);
  const std::string path = svg.substr(apical, svg.find("'/>", apical) - apical);
  EXPECT_EQ(CountOf(path, "M"), 2);
  EXPECT_NE(svg.find(">ED</text>"), std::string::npos);
  EXPECT_NE(svg.find(">ES</text>"), std::string::npos);
  EXPECT_NE(svg.find("strain &lt;global&gt;"), std::string::npos);
  EXPECT_EQ(svg.find("nan"), std::string::npos);
  EXPECT_EQ(svg.find("95 %"), std::string::npos);  // No bars given.

  // A 95 % half-width: a bar, and on hover.
  chart.series[0].half_width = {0.0, 1.25, 2.0, NAN};
  const std::string bars = ChartSvg(chart);
  EXPECT_NE(bars.find("80: -17.25 &#177; 2.00 (95 %)</title>"),
            std::string::npos);
  EXPECT_EQ(CountOf(bars, "(95 %)"), 2);

  // A bias moves the bar's centre off the value, as fit.json's ci95 is
  // centred: -17.25 - 0.5 -+ 2.
  chart.series[0].bias = {0.0, NAN, 0.5, 0.1};
  const std::string shifted = ChartSvg(chart);
  EXPECT_NE(shifted.find("80: -17.25, 95 %: -19.75 to -15.75 (less the "
                         "noise's bias)</title>"),
            std::string::npos);
  EXPECT_EQ(CountOf(shifted, "(95 %)"), 1);  // The unbiased one.
}

}  // namespace
}  // namespace pfdm
