#include "pfdm/report/segment_curves.h"

#include <cstdio>

#include "gtest/gtest.h"
#include "pfdm/phantom/phantom.h"
#include "pfdm/testing/test_util.h"
#include "pfdm/testing/truth_as_fit.h"

namespace pfdm {
namespace {

TEST(SegmentCurvesTest, CycleXIsTimeWhereEveryFrameHasOne) {
  PhantomOptions options;
  options.num_points = 20;
  const Phantom phantom = MakePhantom(options);
  SequenceFit fit = TruthAsFit(phantom);
  bool timed = true;
  EXPECT_EQ(CycleX(AnalyzeFit(fit), &timed),
            (std::vector<double>{0, 1, 2, 3, 4}));
  EXPECT_FALSE(timed);
  fit.time_ms = {10, 60, 110, 160, 210};
  EXPECT_EQ(CycleX(AnalyzeFit(fit), &timed), fit.time_ms);
  EXPECT_TRUE(timed);
}

// A chart per level with a curve per segment, the timing table and the
// index as measured (segment_timing.h), in ms with the frames' times.
TEST(SegmentCurvesTest, LevelsTableAndIndex) {
  PhantomOptions options;
  options.num_points = 20;
  const Phantom phantom = MakePhantom(options);
  SequenceFit fit = TruthAsFit(phantom);
  fit.time_ms = {0, 40, 80, 120, 160};
  const FitAnalysis analysis = AnalyzeFit(fit);
  const std::string html = SegmentCurvesHtml(analysis);
  EXPECT_EQ(CountOf(html, "class='chart'"), 3);
  // 6 + 6 + 4 curves, each named on hover.
  EXPECT_EQ(CountOf(html, "<g><title>"), 16);
  EXPECT_NE(html.find("<g><title>7 mid 1</title>"), std::string::npos);
  EXPECT_EQ(CountOf(html, "<tr>"), 1 + 17);
  const Dyssynchrony& d = analysis.dyssynchrony;
  ASSERT_EQ(d.segments, 16);
  char index[64];
  std::snprintf(index, sizeof(index), "16 segments): <b>%.0f ms</b>", d.index);
  EXPECT_NE(html.find(index), std::string::npos) << index;
  char row[96];
  std::snprintf(row, sizeof(row), "<tr><td>1 basal 1</td><td>%.1f</td>",
                d.peaks[0].percent);
  EXPECT_NE(html.find(row), std::string::npos) << row;
  EXPECT_EQ(html.find("nan"), std::string::npos);
}

}  // namespace
}  // namespace pfdm
