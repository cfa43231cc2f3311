#include "pfdm/util/verdict.h"

#include "gtest/gtest.h"

namespace pfdm {
namespace {

TEST(VerdictTest, IsOkWithoutReasons) {
  const Verdict verdict;
  EXPECT_EQ(verdict.quality(), Quality::kOk);
  EXPECT_EQ(verdict.Summary(), "ok");
  EXPECT_FALSE(verdict.Has("unsettled"));
}

TEST(VerdictTest, TakesItsWorstReasonsQuality) {
  Verdict verdict;
  verdict.Warn("unsettled", "closest points still moving (0.20 mm)");
  EXPECT_EQ(verdict.quality(), Quality::kWarning);
  verdict.Fail("rms_high", "RMS 47 mm");
  verdict.Warn("solver", "NO_CONVERGENCE");
  EXPECT_EQ(verdict.quality(), Quality::kFailed);
  EXPECT_TRUE(verdict.Has("rms_high"));
  EXPECT_EQ(verdict.Summary(),
            "failed: closest points still moving (0.20 mm); RMS 47 mm; "
            "NO_CONVERGENCE");
  EXPECT_STREQ(QualityName(verdict.reasons()[1].severity), "failed");
}

TEST(VerdictTest, AddsAnothersReasonsAndTakesTheWorstOfMany) {
  Verdict fit, analysis;
  fit.Warn("solver", "NO_CONVERGENCE");
  analysis.Fail("volume", "cavity 0.0 ml");
  Verdict both = fit;
  both.Add(analysis);
  EXPECT_EQ(both.reasons().size(), 2u);
  EXPECT_EQ(WorstQuality({fit, Verdict()}), Quality::kWarning);
  EXPECT_EQ(WorstQuality({fit, analysis}), Quality::kFailed);
  EXPECT_EQ(WorstQuality({}), Quality::kOk);
}

}  // namespace
}  // namespace pfdm
