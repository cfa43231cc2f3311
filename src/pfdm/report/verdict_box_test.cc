#include "pfdm/report/verdict_box.h"

#include "gtest/gtest.h"

namespace pfdm {
namespace {

TEST(VerdictBoxTest, ShowsTheWorstQualityAndEveryReason) {
  SequenceFit fit;
  fit.frames.resize(3);
  for (int t = 0; t < 3; ++t) fit.frames[t].frame = t;
  FitAnalysis analysis;
  analysis.verdicts.resize(3);
  std::string box = VerdictBoxHtml(fit, analysis);
  EXPECT_NE(box.find("Quality: ok."), std::string::npos) << box;
  EXPECT_EQ(box.find("<li>"), std::string::npos);

  analysis.verdicts[1].Warn("unsettled", "closest points <still> moving");
  box = VerdictBoxHtml(fit, analysis);
  EXPECT_NE(box.find("Quality: warning."), std::string::npos);
  EXPECT_NE(box.find("<li>frame 1: warning: closest points &lt;still&gt; "
                     "moving</li>"),
            std::string::npos)
      << box;

  analysis.verdicts[2].Fail("volume_range", "cavity volume 0 ml");
  box = VerdictBoxHtml(fit, analysis);
  EXPECT_NE(box.find("Quality: failed."), std::string::npos);
  EXPECT_NE(box.find("#c0392b"), std::string::npos);
  EXPECT_NE(box.find("<li>frame 2: failed: cavity volume 0 ml</li>"),
            std::string::npos);
}

}  // namespace
}  // namespace pfdm
