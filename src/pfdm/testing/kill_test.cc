// `pfdm fit` killed at random moments of its write phase: the output folder
// holds one complete set or none, and the next run leaves no temporaries.
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <filesystem>
#include <random>
#include <thread>

#include "gtest/gtest.h"
#include "nlohmann/json.hpp"
#include "pfdm/testing/test_util.h"

namespace pfdm {
namespace {

namespace fs = std::filesystem;

pid_t StartFit(const std::string& points, const std::string& out) {
  const pid_t pid = fork();
  if (pid == 0) {
    const int null = open("/dev/null", O_WRONLY);
    dup2(null, 1);
    dup2(null, 2);
    execl(PFDM_BINARY, PFDM_BINARY, "fit", "--points", points.c_str(), "--out",
          out.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  return pid;
}

ino_t Inode(const std::string& path) {
  struct stat status;
  return stat(path.c_str(), &status) == 0 ? status.st_ino : 0;
}

// Waits until the child starts replacing the older set (fit.json removed or
// parameters.csv, the first file written, replaced) or exits; true if it
// is still running.
bool WaitForWritePhase(pid_t pid, const std::string& out) {
  const ino_t parameters = Inode(out + "/parameters.csv");
  for (;;) {
    int status = 0;
    if (waitpid(pid, &status, WNOHANG) == pid) return false;
    if (!fs::exists(out + "/fit.json") ||
        Inode(out + "/parameters.csv") != parameters) {
      return true;
    }
    std::this_thread::sleep_for(std::chrono::microseconds(50));
  }
}

// One complete set of the two-frame fit, or none (no fit.json).
void ExpectOneCompleteSetOrNone(const std::string& out,
                                const std::string& what) {
  if (!fs::exists(out + "/fit.json")) return;
  const nlohmann::json fit = nlohmann::json::parse(ReadText(out + "/fit.json"));
  EXPECT_EQ(fit["frames"].size(), 2u) << what << ": an older fit.json";
  for (const char* name : {"parameters.csv", "parameters.svg", "report.html",
                           "fit.pvd", "frame_000.vtp", "frame_001.vtp"}) {
    EXPECT_TRUE(fs::exists(out + "/" + name)) << what << ": " << name;
  }
  EXPECT_FALSE(fs::exists(out + "/frame_002.vtk")) << what;
  EXPECT_FALSE(fs::exists(out + "/frame_002.vtp")) << what;
  EXPECT_EQ(ReadText(out + "/fit.pvd").find("frame_002"), std::string::npos)
      << what;
}

// Before issue 14 the older fit.json stayed until the new one was renamed
// over it, beside 1-19 new files, and temporaries stayed for good.
TEST(KillTest, AFitKilledWhileWritingLeavesOneCompleteSetOrNone) {
  const std::string dir = ScratchDirectory("kill");
  CommandResult run =
      RunPfdm("simulate --frames 3 --tags 300 --out " + dir + "/older.csv");
  ASSERT_EQ(run.exit_code, 0) << run.error;
  run = RunPfdm("simulate --frames 2 --tags 300 --seed 2 --out " + dir +
                "/newer.csv");
  ASSERT_EQ(run.exit_code, 0) << run.error;
  run = RunPfdm("fit --points " + dir + "/older.csv --out " + dir + "/older");
  ASSERT_EQ(run.exit_code, 0) << run.error;

  std::mt19937 random(14);
  // The write phase takes 4-14 ms here; kills spread over its first 5.
  std::uniform_int_distribution<int> delay_us(0, 5000);
  int killed_while_writing = 0;
  for (int signal : {SIGTERM, SIGKILL}) {
    for (int attempt = 0; attempt < 6; ++attempt) {
      const std::string what = std::string(strsignal(signal)) + " attempt " +
                               std::to_string(attempt);
      const std::string out = dir + "/out_" + std::to_string(signal) + "_" +
                              std::to_string(attempt);
      fs::copy(dir + "/older", out, fs::copy_options::recursive);
      const pid_t pid = StartFit(dir + "/newer.csv", out);
      ASSERT_GT(pid, 0);
      if (WaitForWritePhase(pid, out)) {
        std::this_thread::sleep_for(
            std::chrono::microseconds(delay_us(random)));
        kill(pid, signal);
        int status = 0;
        waitpid(pid, &status, 0);
        killed_while_writing += WIFSIGNALED(status);
      }
      ExpectOneCompleteSetOrNone(out, what);

      run = RunPfdm("fit --points " + dir + "/newer.csv --out " + out);
      ASSERT_EQ(run.exit_code, 0) << what << ": " << run.error;
      ASSERT_TRUE(fs::exists(out + "/fit.json")) << what;
      ExpectOneCompleteSetOrNone(out, what);
      for (const auto& entry : fs::directory_iterator(out)) {
        EXPECT_EQ(entry.path().filename().string().find(".tmp."),
                  std::string::npos)
            << what << ": " << entry.path();
      }
    }
  }
  RecordProperty("killed_while_writing", killed_while_writing);
}

}  // namespace
}  // namespace pfdm
