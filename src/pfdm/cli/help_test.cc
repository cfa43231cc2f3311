// The help, version and unknown-flag answers of the pfdm binary (help.cc).
#include "pfdm/cli/help.h"

#include <string>

#include "gtest/gtest.h"
#include "pfdm/testing/test_util.h"

namespace pfdm {
namespace {

bool Contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

int LineCount(const std::string& text) {
  int lines = 0;
  for (char c : text) lines += c == '\n';
  return lines;
}

TEST(HelpTest, OverviewListsTheCommandsAndExitsZero) {
  for (const char* arguments : {"--help", "-h", "help"}) {
    const CommandResult run = RunPfdm(arguments);
    EXPECT_EQ(run.exit_code, 0) << arguments;
    for (const char* command :
         {"fit", "simulate", "batch", "mesh-points", "compare-solvers"}) {
      EXPECT_TRUE(Contains(run.output, std::string("\n  ") + command))
          << arguments << ": " << command;
    }
    // gflags' and glog's own flags are not pfdm's to explain.
    EXPECT_FALSE(Contains(run.output, "logtostderr")) << arguments;
    EXPECT_LT(LineCount(run.output), 25) << arguments;
  }
}

TEST(HelpTest, CommandHelpListsOnlyItsFlagsWithDefaults) {
  for (const char* arguments : {"fit --help", "help fit", "fit -h"}) {
    const CommandResult run = RunPfdm(arguments);
    EXPECT_EQ(run.exit_code, 0) << arguments;
    EXPECT_TRUE(Contains(run.output, "usage: pfdm fit ")) << run.output;
    EXPECT_TRUE(Contains(run.output, "  --knots=17 ")) << run.output;
    EXPECT_TRUE(Contains(run.output, "  --model=\"paper\" ")) << run.output;
    EXPECT_TRUE(Contains(run.output, "knots per parameter function"));
    EXPECT_FALSE(Contains(run.output, "--noise")) << "simulate's flag";
    EXPECT_FALSE(Contains(run.output, "logtostderr"));
  }
  const CommandResult simulate = RunPfdm("simulate --help");
  EXPECT_TRUE(Contains(simulate.output, "  --noise="));
  EXPECT_FALSE(Contains(simulate.output, "--knots"));
}

TEST(HelpTest, VersionNamesTheReleaseAndTheBuild) {
  const CommandResult run = RunPfdm("--version");
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_TRUE(Contains(run.output, "pfdm 0.1.0 (")) << run.output;
  EXPECT_TRUE(Contains(run.output, "Ceres 2.")) << run.output;
  EXPECT_TRUE(Contains(run.output, "Eigen 3.")) << run.output;
}

TEST(HelpTest, UnknownFlagGetsOneLineWithTheNearestName) {
  const CommandResult run = RunPfdm("fit --point x.csv --out /nonexistent");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.error,
            "pfdm: error: unknown flag --point for fit (did you mean "
            "--points?); see 'pfdm fit --help'\n");
  const CommandResult far = RunPfdm("simulate --zzzzzz=3");
  EXPECT_EQ(far.exit_code, 2);
  EXPECT_EQ(far.error,
            "pfdm: error: unknown flag --zzzzzz for simulate; see 'pfdm "
            "simulate --help'\n");
}

TEST(HelpTest, AFlagWithoutItsValueIsOneLine) {
  const CommandResult run = RunPfdm("fit --out x --points");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.error, "pfdm: error: --points needs a value\n");
}

TEST(HelpTest, UnknownCommandGetsTheNearestName) {
  const CommandResult run = RunPfdm("fitt --points x.csv");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.error,
            "pfdm: error: unknown command 'fitt' (did you mean fit?); see "
            "'pfdm --help'\n");
  const CommandResult bare = RunPfdm("");
  EXPECT_EQ(bare.exit_code, 2);
  EXPECT_TRUE(Contains(bare.error, "usage: pfdm <command>"));
}

TEST(HelpTest, FlagValuesAreNotTakenForCommands) {
  // "fit" is --out's value, not the command; --frames 0 is refused.
  const CommandResult run = RunPfdm("simulate --out fit --frames 0 --noise=-1");
  EXPECT_EQ(run.exit_code, 1) << run.error;
  EXPECT_TRUE(Contains(run.error, "pfdm: error: ")) << run.error;
  EXPECT_FALSE(Contains(run.error, "unknown command")) << run.error;
}

TEST(NearestNameTest, FindsSlipsAndRefusesStrangers) {
  const std::vector<std::string> flags = {"points", "knots", "smoothness",
                                          "loss_scale", "out"};
  EXPECT_EQ(NearestName("point", flags), "points");
  EXPECT_EQ(NearestName("smothness", flags), "smoothness");
  EXPECT_EQ(NearestName("lossscale", flags), "loss_scale");
  EXPECT_EQ(NearestName("knot", flags), "knots");
  EXPECT_EQ(NearestName("zzzzzz", flags), "");
  EXPECT_EQ(NearestName("tags", flags), "");
}

}  // namespace
}  // namespace pfdm
