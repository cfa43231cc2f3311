#include "gtest/gtest.h"
#include "pfdm/testing/test_util.h"

namespace pfdm {
namespace {

TEST(CliCheckJacobiansTest, PassesAtTheDefaultToleranceAndFailsAtZero) {
  CommandResult run = RunPfdm("check-jacobians");
  EXPECT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("apex pole"), std::string::npos);
  EXPECT_NE(run.output.find(": ok"), std::string::npos);
  // Rounding alone exceeds a zero tolerance: the check can fail.
  run = RunPfdm("check-jacobians --tolerance 0");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.output.find("FAILED"), std::string::npos);
}

}  // namespace
}  // namespace pfdm
