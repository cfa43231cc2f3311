#include "pfdm/report/fit_plots.h"

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

}  // namespace
}  // namespace pfdm
