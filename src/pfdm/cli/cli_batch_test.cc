// pfdm batch end to end: parallel cases, a failing case, resuming, shards.
#include <filesystem>
#include <sstream>

#include "gtest/gtest.h"
#include "pfdm/testing/test_util.h"

namespace pfdm {
namespace {

namespace fs = std::filesystem;

int Lines(const std::string& text, const std::string& containing) {
  std::istringstream in(text);
  int n = 0;
  for (std::string line; std::getline(in, line);) {
    n += line.find(containing) != std::string::npos;
  }
  return n;
}

std::string Row(const std::string& csv, const std::string& name) {
  std::istringstream in(csv);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind(name + ",", 0) == 0) return line;
  }
  return "";
}

// Two small phantoms and a case whose points are missing.
std::string MakeCohort(const std::string& dir) {
  for (int seed : {1, 2}) {
    const CommandResult run = RunPfdm("simulate --frames 3 --tags 300 --seed " +
                                      std::to_string(seed) + " --out " + dir +
                                      "/p" + std::to_string(seed) + ".csv");
    EXPECT_EQ(run.exit_code, 0) << run.error;
  }
  WriteText(dir + "/cases.csv",
            "case,points\nalpha,p1.csv\nbeta,p2.csv\ngamma,missing.csv\n");
  return dir + "/cases.csv";
}

TEST(CliBatchTest, FitsInParallelRecordsFailuresAndResumes) {
  const std::string dir = ScratchDirectory("batch");
  const std::string manifest = MakeCohort(dir);
  const std::string out = dir + "/out";
  CommandResult run =
      RunPfdm("batch --manifest " + manifest + " --out " + out + " --jobs 2");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.error,
            "pfdm: error: 1 of 3 cases failed, see " + out + "/summary.csv\n");
  EXPECT_EQ(Lines(run.output, "] alpha: done, ok, 3 frames"), 1) << run.output;
  EXPECT_EQ(Lines(run.output, "] beta: done, ok, 3 frames"), 1);
  EXPECT_EQ(Lines(run.output, "] gamma: FAILED: " + dir +
                                  "/missing.csv: cannot open the file"),
            1)
      << run.output;
  EXPECT_EQ(Lines(run.output, "/3] "), 3);
  for (const char* name : {"fit.json", "report.html", "parameters.svg",
                           "fit.pvd", "frame_002.vtp"}) {
    EXPECT_TRUE(fs::exists(out + "/alpha/" + name)) << name;
  }
  EXPECT_FALSE(fs::exists(out + "/gamma/fit.json"));
  std::string summary = ReadText(out + "/summary.csv");
  EXPECT_EQ(summary.rfind("case,status,quality,frames,max_rms_mm,", 0), 0u);
  EXPECT_EQ(Row(summary, "alpha").rfind("alpha,done,ok,3,", 0), 0u);
  EXPECT_EQ(Row(summary, "gamma").rfind("gamma,failed,,,", 0), 0u);
  EXPECT_NE(Row(summary, "gamma").find("cannot open the file"),
            std::string::npos);
  // The phantom's tags lie on a mid-wall surface, whose enclosed volume
  // falls by about 0.45 of its ED value by the third frame: not an
  // ejection fraction, so that column stays empty.
  std::istringstream alpha(Row(summary, "alpha"));
  std::vector<std::string> fields;
  for (std::string f; std::getline(alpha, f, ',');) fields.push_back(f);
  ASSERT_GE(fields.size(), 15u);
  EXPECT_EQ(fields[5], "midwall");
  EXPECT_EQ(fields[8], "2");  // es_frame
  const double fraction =
      1.0 - std::stod(fields[7]) / std::stod(fields[6]);  // ES / ED volume.
  EXPECT_GT(fraction, 0.2);
  EXPECT_LT(fraction, 0.5);
  EXPECT_EQ(fields[9], "");              // ejection_fraction
  EXPECT_LT(std::stod(fields[4]), 1.5);  // max RMS, mm

  // Resume: the done cases are skipped; the repaired one is fitted.
  const auto written = fs::last_write_time(out + "/alpha/fit.json");
  fs::copy_file(dir + "/p1.csv", dir + "/missing.csv");
  run = RunPfdm("batch --manifest " + manifest + " --out " + out + " --jobs 2");
  EXPECT_EQ(run.exit_code, 0) << run.error;
  EXPECT_EQ(Lines(run.output, "skipped, fit.json exists"), 2) << run.output;
  EXPECT_EQ(Lines(run.output, "] gamma: done"), 1);
  EXPECT_EQ(fs::last_write_time(out + "/alpha/fit.json"), written);
  EXPECT_FALSE(fs::exists(out + "/gamma/error.txt"));
  summary = ReadText(out + "/summary.csv");
  EXPECT_EQ(Lines(summary, ",done,"), 3);
  // gamma fitted the same points as alpha: the same row but for its name.
  EXPECT_EQ(Row(summary, "gamma").substr(5), Row(summary, "alpha").substr(5));
}

TEST(CliBatchTest, ShardsSplitTheManifestAndTheSummaryCoversAll) {
  const std::string dir = ScratchDirectory("batch");
  MakeCohort(dir);
  WriteText(dir + "/cases.csv", "case,points\nalpha,p1.csv\nbeta,p2.csv\n");
  const std::string out = dir + "/out";
  CommandResult run = RunPfdm("batch --manifest " + dir + "/cases.csv --out " +
                              out + " --shard 1/2");
  EXPECT_EQ(run.exit_code, 0) << run.error;
  EXPECT_EQ(Lines(run.output, "[1/1] beta: done"), 1) << run.output;
  EXPECT_FALSE(fs::exists(out + "/alpha"));
  EXPECT_EQ(Row(ReadText(out + "/summary.csv"), "alpha"),
            "alpha,pending" + std::string(17, ','));
  run = RunPfdm("batch --manifest " + dir + "/cases.csv --out " + out +
                " --shard 0/2");
  EXPECT_EQ(run.exit_code, 0) << run.error;
  EXPECT_EQ(Lines(ReadText(out + "/summary.csv"), ",done,"), 2);
}

TEST(CliBatchTest, BadManifestOrShardIsOneLineAndWritesNothing) {
  const std::string dir = ScratchDirectory("batch");
  WriteText(dir + "/cases.csv", "case,points\na b,x.csv\n");
  CommandResult run =
      RunPfdm("batch --manifest " + dir + "/cases.csv --out " + dir + "/out");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.error, "pfdm: error: " + dir +
                           "/cases.csv:2: case 'a b' is not a plain folder "
                           "name (letters, digits, '.', '_', '-'; not "
                           "summary.csv or *.tmp.*)\n");
  EXPECT_FALSE(fs::exists(dir + "/out"));
  WriteText(dir + "/cases.csv", "case,points\na,x.csv\n");
  run = RunPfdm("batch --manifest " + dir + "/cases.csv --out " + dir +
                "/out --shard 2/2");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.error,
            "pfdm: error: --shard must be i/n with 0 <= i < n, got '2/2'\n");
  EXPECT_FALSE(fs::exists(dir + "/out"));
}

// Issue 14: DIR/<case> as a plain file ended the program in std::terminate
// with no summary, a garbage DIR/<case>/fit.json stopped the whole batch,
// and a case named summary.csv broke the summary.
TEST(CliBatchTest, OneBrokenCaseCostsNeitherTheOthersNorTheSummary) {
  const std::string dir = ScratchDirectory("batch");
  CommandResult run =
      RunPfdm("simulate --frames 2 --tags 200 --out " + dir + "/p.csv");
  ASSERT_EQ(run.exit_code, 0) << run.error;
  WriteText(dir + "/cases.csv",
            "case,points\nalpha,p.csv\nbeta,p.csv\ngamma,p.csv\n");
  const std::string out = dir + "/out";
  fs::create_directories(out + "/beta");
  WriteText(out + "/alpha", "a plain file");
  WriteText(out + "/beta/fit.json", "{ not json");
  run = RunPfdm("batch --manifest " + dir + "/cases.csv --out " + out);
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.error,
            "pfdm: error: 1 of 3 cases failed, see " + out + "/summary.csv\n");
  EXPECT_EQ(Lines(run.output,
                  "] alpha: FAILED: " + out + "/alpha: cannot create folder"),
            1)
      << run.output;
  EXPECT_EQ(Lines(run.output, "] beta: done, ok, 2 frames"), 1) << run.output;
  EXPECT_EQ(Lines(run.output, "] gamma: done, ok, 2 frames"), 1) << run.output;
  const std::string summary = ReadText(out + "/summary.csv");
  EXPECT_EQ(Row(summary, "alpha").rfind("alpha,pending,", 0), 0u) << summary;
  EXPECT_EQ(Row(summary, "beta").rfind("beta,done,ok,2,", 0), 0u) << summary;
  EXPECT_EQ(ReadText(out + "/alpha"), "a plain file");

  // A fit.json spoilt after the fit: the summary says so, the rest stands.
  WriteText(out + "/gamma/fit.json", "[]");
  run = RunPfdm("batch --manifest " + dir + "/cases.csv --out " + out +
                " --shard 0/3");
  EXPECT_NE(Row(ReadText(out + "/summary.csv"), "gamma").find("gamma,failed,"),
            std::string::npos)
      << ReadText(out + "/summary.csv");
  EXPECT_EQ(Row(ReadText(out + "/summary.csv"), "beta").rfind("beta,done,", 0),
            0u);

  WriteText(dir + "/cases.csv", "case,points\nsummary.csv,p.csv\n");
  run =
      RunPfdm("batch --manifest " + dir + "/cases.csv --out " + dir + "/out2");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.error, "pfdm: error: " + dir +
                           "/cases.csv:2: case 'summary.csv' is not a plain "
                           "folder name (letters, digits, '.', '_', '-'; not "
                           "summary.csv or *.tmp.*)\n");
}

}  // namespace
}  // namespace pfdm
