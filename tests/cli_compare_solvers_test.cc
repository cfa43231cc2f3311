#include <filesystem>
#include <set>
#include <sstream>

#include "gtest/gtest.h"
#include "test_util.h"

namespace pfdm {
namespace {

TEST(CliCompareSolversTest, WritesTracesOfAllThreeSolversAndAPlot) {
  const std::string dir = ScratchDirectory("compare");
  ASSERT_EQ(RunPfdm("simulate --frames 2 --tags 200 --out " + dir + "/p.csv")
                .exit_code,
            0);
  const CommandResult run = RunPfdm("compare-solvers --knots 9 --points " +
                                    dir + "/p.csv --out " + dir + "/cmp");
  ASSERT_EQ(run.exit_code, 0) << run.error;
  std::istringstream csv(ReadText(dir + "/cmp/convergence.csv"));
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line,
            "solver,frame,iteration,pseudo_time,wall_seconds,cost,"
            "gradient_norm,rms_mm");
  std::set<std::string> solvers;
  while (std::getline(csv, line)) solvers.insert(line.substr(0, line.find(',')));
  EXPECT_EQ(solvers, (std::set<std::string>{"direct", "damped", "integrator"}));
  const std::string svg = ReadText(dir + "/cmp/convergence.svg");
  EXPECT_NE(svg.find("integrator"), std::string::npos);
}

TEST(CliCompareSolversTest, UnknownSolverIsAnError) {
  const std::string dir = ScratchDirectory("compare");
  const CommandResult run =
      RunPfdm("fit --solver newton --points " + dir + "/x.csv --out " + dir);
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.error.find("unknown --solver 'newton'"), std::string::npos);
}

}  // namespace
}  // namespace pfdm
