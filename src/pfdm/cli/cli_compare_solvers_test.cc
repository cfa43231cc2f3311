// pfdm compare-solvers end to end: the trace CSV, the plot, bad flags.
#include <cmath>
#include <filesystem>
#include <map>
#include <sstream>
#include <utility>

#include "gtest/gtest.h"
#include "pfdm/testing/test_util.h"

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

// (solver, frame) -> iteration -> "function/knot" -> value.
using Trajectories = std::map<std::pair<std::string, int>,
                              std::map<int, std::map<std::string, double>>>;

Trajectories ReadTrajectories(const std::string& path) {
  std::istringstream lines(ReadText(path));
  std::string line;
  std::getline(lines, line);
  EXPECT_EQ(line, "solver,frame,iteration,pseudo_time,function,knot,value");
  Trajectories trajectories;
  while (std::getline(lines, line)) {
    std::istringstream fields(line);
    std::string solver, frame, iteration, time, function, knot, value;
    std::getline(fields, solver, ',');
    std::getline(fields, frame, ',');
    std::getline(fields, iteration, ',');
    std::getline(fields, time, ',');
    std::getline(fields, function, ',');
    std::getline(fields, knot, ',');
    std::getline(fields, value, ',');
    trajectories[{solver, std::stoi(frame)}][std::stoi(iteration)]
                [function + "/" + knot] = std::stod(value);
  }
  return trajectories;
}

TEST(CliCompareSolversTest, WritesTracesOfAllThreeSolversAndThePlot) {
  const std::string dir = ScratchDirectory("compare");
  CommandResult run =
      RunPfdm("simulate --frames 2 --tags 150 --out " + dir + "/phantom.csv");
  ASSERT_EQ(run.exit_code, 0) << run.error;
  run = RunPfdm("compare-solvers --knots 9 --points " + dir +
                "/phantom.csv --out " + dir + "/out");
  ASSERT_EQ(run.exit_code, 0) << run.error;
  EXPECT_NE(run.output.find("integrator all frames"), std::string::npos);
  // Forward Euler with the model damping, the default, brings every frame
  // to rest (with Jacobi damping it stopped at its step cap,
  // NO_CONVERGENCE).
  EXPECT_NE(run.output.find("integrator: euler, damping model"),
            std::string::npos);
  int resting = 0;
  std::istringstream printed(run.output);
  for (std::string line; std::getline(printed, line);) {
    if (line.rfind("integrator frame", 0) != 0) continue;
    EXPECT_NE(line.find("REST"), std::string::npos) << line;
    ++resting;
  }
  EXPECT_EQ(resting, 2);

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
  // The path of the model: thinned, ending where the trace ends, and the
  // three solvers' paths end at the same twist.
  const Trajectories paths = ReadTrajectories(dir + "/out/trajectory.csv");
  ASSERT_EQ(paths.size(), 6u);
  for (const auto& [key, path] : paths) {
    SCOPED_TRACE(key.first + " frame " + std::to_string(key.second));
    const auto& rows = traces.at(key);
    EXPECT_EQ(path.begin()->first, 0);
    EXPECT_EQ(path.rbegin()->first, rows.back().iteration);
    EXPECT_LE(path.size(), 12 + 10 * std::log10(rows.size()));
    EXPECT_EQ(path.begin()->second.size(), 10u * 9u);  // The 10 free.
  }
  const auto& direct_end = paths.at({"direct", 1}).rbegin()->second;
  for (const char* solver : {"damped", "integrator"}) {
    const auto& end = paths.at({solver, 1}).rbegin()->second;
    EXPECT_NEAR(end.at("tau/8"), direct_end.at("tau/8"), 0.01 * M_PI / 180)
        << solver;
    EXPECT_NEAR(end.at("a1/4"), direct_end.at("a1/4"), 0.01) << solver;
  }
  // Frame 1 starts from frame 0's fit: its twist is still 0 there.
  EXPECT_EQ(paths.at({"integrator", 1}).begin()->second.at("tau/8"), 0.0);
  EXPECT_NE(paths.at({"integrator", 1}).rbegin()->second.at("tau/8"), 0.0);

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
       "pfdm: error: --max_steps must be between 1 and 1000000, got 0\n"},
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
