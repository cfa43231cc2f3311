// pfdm batch end to end: parallel cases, a failing case, resuming, shards.
#include <algorithm>
#include <filesystem>
#include <iterator>
#include <map>
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

std::vector<std::string> Names(const std::string& dir) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) {
    names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
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
  // Mid-wall phantoms: no cavity, so no ejection fraction, as in summary.csv.
  EXPECT_EQ(Lines(run.output, ", EF n/a (a midwall surface), "), 2)
      << run.output;
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
// and a case named summary.csv broke the summary.  Issue 29: the plain file
// ended as pending with no reason, and the folder of garbage, not pfdm's,
// was fitted and written over; both now fail alone, untouched.
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
            "pfdm: error: 2 of 3 cases failed, see " + out + "/summary.csv\n");
  const std::string alpha_reason =
      out + "/alpha: is a file, not a case folder; pfdm batch leaves it alone";
  EXPECT_EQ(Lines(run.output, "] alpha: FAILED: " + alpha_reason), 1)
      << run.output;
  EXPECT_EQ(Lines(run.output, "] beta: FAILED: " + out +
                                  "/beta: holds files pfdm did not mark"),
            1)
      << run.output;
  EXPECT_EQ(Lines(run.output, "] gamma: done, ok, 2 frames"), 1) << run.output;
  const std::string summary = ReadText(out + "/summary.csv");
  EXPECT_EQ(Row(summary, "alpha"),
            "alpha,failed" + std::string(17, ',') + "\"" + alpha_reason + "\"")
      << summary;
  EXPECT_EQ(Row(summary, "beta").rfind("beta,failed,", 0), 0u) << summary;
  EXPECT_EQ(Row(summary, "gamma").rfind("gamma,done,ok,2,", 0), 0u) << summary;
  EXPECT_EQ(ReadText(out + "/alpha"), "a plain file");
  EXPECT_EQ(ReadText(out + "/beta/fit.json"), "{ not json");
  EXPECT_EQ(std::distance(fs::directory_iterator(out + "/beta"),
                          fs::directory_iterator()),
            1);

  // A fit.json spoilt after the fit, in pfdm's own folder: the summary
  // says so (the shard that owns the case fits it again), the rest stands.
  WriteText(out + "/gamma/fit.json", "[]");
  run = RunPfdm("batch --manifest " + dir + "/cases.csv --out " + out +
                " --shard 0/3");
  EXPECT_NE(Row(ReadText(out + "/summary.csv"), "gamma").find("gamma,failed,"),
            std::string::npos)
      << ReadText(out + "/summary.csv");
  EXPECT_EQ(
      Row(ReadText(out + "/summary.csv"), "beta").rfind("beta,failed,", 0), 0u);

  WriteText(dir + "/cases.csv", "case,points\nsummary.csv,p.csv\n");
  run =
      RunPfdm("batch --manifest " + dir + "/cases.csv --out " + dir + "/out2");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.error, "pfdm: error: " + dir +
                           "/cases.csv:2: case 'summary.csv' is not a plain "
                           "folder name (letters, digits, '.', '_', '-'; not "
                           "summary.csv or *.tmp.*)\n");
}

// Issue 29: a plain file ended as pending with no reason, someone else's
// fit.json was fitted again and written over, and a linked case folder was
// followed and its target's files replaced.  Only a new, empty or marked
// folder is pfdm's; every other case fails alone, with its reason in
// summary.csv, and nothing is written into it.
TEST(CliBatchTest, CaseFoldersThatAreNotPfdmsFailAloneAndAreNeverWrittenInto) {
  const std::string dir = ScratchDirectory("batch");
  CommandResult run =
      RunPfdm("simulate --frames 2 --tags 200 --out " + dir + "/p.csv");
  ASSERT_EQ(run.exit_code, 0) << run.error;
  run = RunPfdm("fit --points " + dir + "/p.csv --out " + dir + "/theirs");
  ASSERT_EQ(run.exit_code, 0) << run.error;
  const std::string their_json = ReadText(dir + "/theirs/fit.json");
  WriteText(dir + "/cases.csv",
            "case,points\nplain,p.csv\nlinked,p.csv\ndangling,p.csv\n"
            "foreign,p.csv\nstranger,p.csv\nempty,p.csv\nfresh,p.csv\n");
  const std::string out = dir + "/out";
  fs::create_directories(out + "/empty");
  WriteText(out + "/plain", "a plain file");
  fs::create_directories(dir + "/elsewhere");
  WriteText(dir + "/elsewhere/fit.json", "{ theirs");
  WriteText(dir + "/elsewhere/keep.txt", "theirs");
  fs::create_directory_symlink(dir + "/elsewhere", out + "/linked");
  fs::create_directory_symlink(dir + "/nowhere", out + "/dangling");
  // A genuine fit.json, but not written here by pfdm (no marker).
  fs::create_directories(out + "/foreign");
  fs::copy_file(dir + "/theirs/fit.json", out + "/foreign/fit.json");
  fs::create_directories(out + "/stranger");
  WriteText(out + "/stranger/notes.txt", "theirs");

  run = RunPfdm("batch --manifest " + dir + "/cases.csv --out " + out +
                " --jobs 2");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.error,
            "pfdm: error: 5 of 7 cases failed, see " + out + "/summary.csv\n");
  const std::string link_reason =
      ": is a link, not a case folder of pfdm's; pfdm batch does not write "
      "through it";
  const std::string unmarked_reason =
      ": holds files pfdm did not mark as its own (no .pfdm-fit); pfdm batch "
      "leaves it alone: move them, or create that file if an older pfdm "
      "wrote them";
  const std::map<std::string, std::string> reasons = {
      {"plain", out + "/plain: is a file, not a case folder; pfdm batch "
                      "leaves it alone"},
      {"linked", out + "/linked" + link_reason},
      {"dangling", out + "/dangling" + link_reason},
      {"foreign", out + "/foreign" + unmarked_reason},
      {"stranger", out + "/stranger" + unmarked_reason}};
  const std::string summary = ReadText(out + "/summary.csv");
  for (const auto& [name, reason] : reasons) {
    EXPECT_EQ(Lines(run.output, "] " + name + ": FAILED: " + reason), 1)
        << run.output;
    EXPECT_EQ(Row(summary, name),
              name + ",failed" + std::string(17, ',') + "\"" + reason + "\"")
        << summary;
  }
  for (const char* name : {"empty", "fresh"}) {
    EXPECT_EQ(Row(summary, name).rfind(std::string(name) + ",done,ok,2,", 0),
              0u)
        << summary;
    EXPECT_TRUE(fs::is_regular_file(out + "/" + name + "/.pfdm-fit"));
  }
  // Untouched, every one.
  EXPECT_EQ(ReadText(out + "/plain"), "a plain file");
  EXPECT_EQ(Names(dir + "/elsewhere"),
            (std::vector<std::string>{"fit.json", "keep.txt"}));
  EXPECT_EQ(ReadText(dir + "/elsewhere/fit.json"), "{ theirs");
  EXPECT_FALSE(fs::exists(dir + "/nowhere"));
  EXPECT_EQ(Names(out + "/foreign"), std::vector<std::string>{"fit.json"});
  EXPECT_EQ(ReadText(out + "/foreign/fit.json"), their_json);
  EXPECT_EQ(Names(out + "/stranger"), std::vector<std::string>{"notes.txt"});

  // An older pfdm's case, once marked by hand, counts as done.
  WriteText(out + "/foreign/.pfdm-fit", "");
  run = RunPfdm("batch --manifest " + dir + "/cases.csv --out " + out);
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(Lines(run.output, "] foreign: skipped, fit.json exists"), 1)
      << run.output;
  EXPECT_EQ(Row(ReadText(out + "/summary.csv"), "foreign")
                .rfind("foreign,done,ok,2,", 0),
            0u);
  EXPECT_EQ(ReadText(out + "/foreign/fit.json"), their_json);
}

// Links planted in the batch's own folders are replaced or removed, never
// written or read through: summary.csv, a case's fit.json and error.txt.
TEST(CliBatchTest, LinksPlantedInItsOwnFoldersAreNeverFollowed) {
  const std::string dir = ScratchDirectory("batch");
  CommandResult run =
      RunPfdm("simulate --frames 2 --tags 200 --out " + dir + "/p.csv");
  ASSERT_EQ(run.exit_code, 0) << run.error;
  WriteText(dir + "/cases.csv", "case,points\nalpha,p.csv\nbeta,none.csv\n");
  const std::string out = dir + "/out";
  WriteText(dir + "/victim", "precious, and not a fit.json");
  for (const char* name : {"alpha", "beta"}) {
    fs::create_directories(out + "/" + name);
    WriteText(out + "/" + name + "/.pfdm-fit", "");
    fs::create_symlink(dir + "/victim", out + "/" + name + "/error.txt");
  }
  fs::create_symlink(dir + "/victim", out + "/alpha/fit.json");
  fs::create_symlink(dir + "/victim", out + "/summary.csv");
  run = RunPfdm("batch --manifest " + dir + "/cases.csv --out " + out);
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(Lines(run.output, "] alpha: done, ok, 2 frames"), 1) << run.output;
  EXPECT_EQ(ReadText(dir + "/victim"), "precious, and not a fit.json");
  for (const std::string path : {out + "/summary.csv", out + "/alpha/fit.json",
                                 out + "/beta/error.txt"}) {
    EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(path))) << path;
  }
  EXPECT_FALSE(fs::exists(fs::symlink_status(out + "/alpha/error.txt")));
  EXPECT_NE(ReadText(out + "/beta/error.txt").find("cannot open the file"),
            std::string::npos);
  const std::string summary = ReadText(out + "/summary.csv");
  EXPECT_EQ(Row(summary, "alpha").rfind("alpha,done,ok,2,", 0), 0u) << summary;
  EXPECT_EQ(summary.find("precious"), std::string::npos) << summary;

  // A link planted at fit.json after the fit: the summary names it and
  // does not show what it points to.
  fs::remove(out + "/alpha/fit.json");
  fs::create_symlink(dir + "/victim", out + "/alpha/fit.json");
  run = RunPfdm("batch --manifest " + dir + "/cases.csv --out " + out +
                " --shard 1/2");
  EXPECT_EQ(Row(ReadText(out + "/summary.csv"), "alpha"),
            "alpha,failed" + std::string(17, ',') + "\"" + out +
                "/alpha/fit.json: is a link, not a file pfdm wrote\"");
}

}  // namespace
}  // namespace pfdm
