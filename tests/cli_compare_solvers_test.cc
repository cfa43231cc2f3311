// pfdm compare-solvers end to end: the trace CSV, the plot, bad flags.
#include <filesystem>
#include <map>
#include <sstream>
#include <utility>

#include "gtest/gtest.h"
#include "test_util.h"

namespace pfdm {
namespace {

namespace fs = std::filesystem;

struct Row {
  int iteration;
  double pseudo_time, cost;
};

// (solver, frame) -> rows, in file order.
std::map<std::pair<std::string, int>, std::vector<Row>> ReadTraces(
    const std::string& path) {
  std::istringstream lines(ReadText(path));
  std::string line;
  std::getline(lines, line);
  EXPECT_EQ(line,
            "solver,frame,iteration,pseudo_time,wall_seconds,cost,"
            "gradient_norm,rms_mm");
  std::map<std::pair<std::string, int>, std::vector<Row>> traces;
  while (std::getline(lines, line)) {
    std::istringstream fields(line);
    std::string solver, cell;
    std::vector<double> values;
    std::getline(fields, solver, ',');
    while (std::getline(fields, cell, ',')) values.push_back(std::stod(cell));
    EXPECT_EQ(values.size(), 7u) << line;
    if (values.size() != 7u) continue;
    traces[{solver, static_cast<int>(values[0])}].push_back(
        {static_cast<int>(values[1]), values[2], values[4]});
  }
  return traces;
}

TEST(CliCompareSolversTest, WritesTracesOfAllThreeSolversAndThePlot) {
  const std::string dir = ScratchDirectory("compare");
  CommandResult run =
      RunPfdm("simulate --frames 2 --tags 150 --out " + dir + "/phantom.csv");
  ASSERT_EQ(run.exit_code, 0) << run.error;
  run = RunPfdm("compare-solvers --knots 9 --max_steps 3000 --points " + dir +
                "/phantom.csv --out " + dir + "/out");
  ASSERT_EQ(run.exit_code, 0) << run.error;
  EXPECT_NE(run.output.find("integrator all frames"), std::string::npos);

  const auto traces = ReadTraces(dir + "/out/convergence.csv");
  ASSERT_EQ(traces.size(), 6u);  // 3 solvers x 2 frames.
  for (const auto& [key, rows] : traces) {
    SCOPED_TRACE(key.first + " frame " + std::to_string(key.second));
    ASSERT_GE(rows.size(), 2u);
    for (size_t i = 1; i < rows.size(); ++i) {
      EXPECT_GT(rows[i].iteration, rows[i - 1].iteration);
      EXPECT_GE(rows[i].pseudo_time, rows[i - 1].pseudo_time);
    }
    if (key.first == "direct") {
      EXPECT_EQ(rows.back().pseudo_time, 0.0);
    } else {
      EXPECT_GT(rows.back().pseudo_time, 0.0);
    }
  }
  // The tracked frame's traces end at the same energy.
  const double direct = traces.at({"direct", 1}).back().cost;
  for (const char* solver : {"damped", "integrator"}) {
    EXPECT_NEAR(traces.at({solver, 1}).back().cost / direct, 1.0, 1e-4)
        << solver;
  }
  const std::string svg = ReadText(dir + "/out/convergence.svg");
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_NE(svg.find("integrator"), std::string::npos);
  for (const auto& entry : fs::directory_iterator(dir + "/out")) {
    EXPECT_EQ(entry.path().string().find(".tmp."), std::string::npos);
  }
}

TEST(CliCompareSolversTest, BadFlagsGiveOneLineAndNoOutput) {
  const std::string dir = ScratchDirectory("compare_bad");
  WriteText(dir + "/tags.csv", "frame,id,x,y,z\n0,1,2,3,4\n");
  const std::pair<std::string, std::string> cases[] = {
      {"--points " + dir + "/tags.csv",
       "pfdm: error: compare-solvers needs --out DIR\n"},
      {"--points " + dir + "/tags.csv --max_steps 0 --out " + dir + "/out",
       "pfdm: error: --max_steps must be at least 1\n"},
      {"--points " + dir + "/tags.csv --out " + dir + "/out",
       "pfdm: error: " + dir +
           "/tags.csv: frame 0: only 1 points, at least 10 needed\n"},
  };
  for (const auto& [flags, message] : cases) {
    const CommandResult run = RunPfdm("compare-solvers " + flags);
    EXPECT_EQ(run.exit_code, 1) << flags;
    EXPECT_EQ(run.error, message);
    EXPECT_FALSE(fs::exists(dir + "/out"));
  }
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
