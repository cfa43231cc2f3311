#include "pfdm/util/atomic_file.h"

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "gtest/gtest.h"
#include "pfdm/testing/test_util.h"
#include "pfdm/util/error.h"

namespace pfdm {
namespace {

namespace fs = std::filesystem;

int Entries(const std::string& dir) {
  int n = 0;
  for (const auto& entry : fs::directory_iterator(dir))
    n += !entry.path().empty();
  return n;
}

// Random parts drawn in turn from `parts`, the last one repeated.
AtomicWriteOptions Parts(std::vector<std::string> parts) {
  auto next = std::make_shared<size_t>(0);
  AtomicWriteOptions options;
  options.random_parts = [parts, next] {
    return parts[std::min(parts.size() - 1, (*next)++)];
  };
  return options;
}

TEST(AtomicFileTest, WritesAndReplacesWholeFilesLeavingNoTemporary) {
  const std::string dir = ScratchDirectory("atomic");
  WriteFileAtomically(dir + "/a.txt", "first");
  WriteFileAtomically(dir + "/a.txt", "second");
  EXPECT_EQ(ReadText(dir + "/a.txt"), "second");
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    (void)entry;
    ++files;
  }
  EXPECT_EQ(files, 1);
}

TEST(AtomicFileTest, UnwritablePlaceIsAnInputError) {
  try {
    WriteFileAtomically("/nonexistent/dir/a.txt", "x");
    FAIL();
  } catch (const InputError& error) {
    EXPECT_EQ(
        std::string(error.what()),
        "/nonexistent/dir/a.txt: cannot write: No such file or directory");
  }
  EXPECT_FALSE(std::filesystem::exists("/nonexistent/dir"));
}

TEST(AtomicFileTest, FailedRenameKeepsTheTargetAndRemovesTheTemporary) {
  const std::string dir = ScratchDirectory("atomic_rename");
  // A non-empty folder cannot be replaced by a file.
  std::filesystem::create_directories(dir + "/out/inner");
  try {
    WriteFileAtomically(dir + "/out", "x");
    FAIL();
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()),
              dir + "/out: cannot write: Is a directory");
  }
  EXPECT_TRUE(std::filesystem::is_directory(dir + "/out/inner"));
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    (void)entry;
    ++files;
  }
  EXPECT_EQ(files, 1);
}

TEST(AtomicFileTest, WritesBinaryContentsByteForByte) {
  const std::string dir = ScratchDirectory("atomic_binary");
  const std::string contents("a\0b\r\n\xff", 6);
  WriteFileAtomically(dir + "/b.bin", contents);
  EXPECT_EQ(ReadText(dir + "/b.bin"), contents);
  WriteFileAtomically(dir + "/empty", "");
  EXPECT_EQ(std::filesystem::file_size(dir + "/empty"), 0u);
}

TEST(AtomicFileTest, EnsureDirectoryCreatesParentsAndRejectsFiles) {
  const std::string dir = ScratchDirectory("ensure");
  EnsureDirectory(dir + "/a/b");
  EXPECT_TRUE(std::filesystem::is_directory(dir + "/a/b"));
  EnsureDirectory(dir + "/a/b");  // Already there: fine.
  WriteText(dir + "/file", "x");
  try {
    EnsureDirectory(dir + "/file");
    FAIL();
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()),
              dir + "/file: cannot create folder: Not a directory");
  }
}

// Issue 29: the temporary was PATH.tmp.<pid>, opened with O_TRUNC through
// whatever was there: a link planted at it made pfdm overwrite the link's
// target.  Now a taken name is passed over, and nothing is written through.
TEST(AtomicFileTest, ALinkPlantedAtTheTemporaryNameIsPassedOver) {
  const std::string dir = ScratchDirectory("atomic_planted");
  const std::string path = dir + "/out.csv";
  WriteText(dir + "/victim", "precious");
  const std::string planted = TemporaryName(path, "PLANTED1");
  fs::create_symlink(dir + "/victim", planted);
  // Dangling: O_CREAT without O_EXCL would make the file it names.
  const std::string dangling = TemporaryName(path, "PLANTED2");
  fs::create_symlink(dir + "/made_through_the_link", dangling);
  WriteFileAtomically(path, "ours",
                      Parts({"PLANTED1", "PLANTED2", "free0001"}));
  EXPECT_EQ(ReadText(path), "ours");
  EXPECT_EQ(ReadText(dir + "/victim"), "precious");
  EXPECT_FALSE(fs::exists(dir + "/made_through_the_link"));
  // Someone else's links are left where they are.
  EXPECT_TRUE(fs::is_symlink(planted));
  EXPECT_TRUE(fs::is_symlink(dangling));
  EXPECT_EQ(Entries(dir), 4);  // victim, two links, out.csv
}

TEST(AtomicFileTest, EveryTemporaryNameTakenIsAClearErrorAndWritesNothing) {
  const std::string dir = ScratchDirectory("atomic_all_taken");
  const std::string path = dir + "/summary.csv";
  WriteText(dir + "/victim", "precious");
  const std::string planted = TemporaryName(path, "PLANTED1");
  fs::create_symlink(dir + "/victim", planted);
  try {
    WriteFileAtomically(path, "ours", Parts({"PLANTED1"}));
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()),
              path +
                  ": cannot write: the 100 temporary names drawn beside "
                  "it were all taken (" +
                  planted + " and others: planted?)");
  }
  EXPECT_EQ(ReadText(dir + "/victim"), "precious");
  EXPECT_FALSE(fs::exists(path));
  EXPECT_EQ(Entries(dir), 2);
}

// The rename replaces a link at the final name itself, not its target.
TEST(AtomicFileTest, ALinkAtTheFinalNameIsReplacedNotWrittenThrough) {
  const std::string dir = ScratchDirectory("atomic_final_link");
  WriteText(dir + "/victim", "precious");
  fs::create_symlink(dir + "/victim", dir + "/out.csv");
  WriteFileAtomically(dir + "/out.csv", "ours");
  EXPECT_FALSE(fs::is_symlink(dir + "/out.csv"));
  EXPECT_EQ(ReadText(dir + "/out.csv"), "ours");
  EXPECT_EQ(ReadText(dir + "/victim"), "precious");
}

// Random names, not mkstemp's 0600: the file gets the mode any new file
// gets under the umask, as before.
TEST(AtomicFileTest, NamesAreRandomAndTheModeFollowsTheUmask) {
  const std::string dir = ScratchDirectory("atomic_mode");
  // PATH.tmp.HOST.PID.RANDOM, HOST in letters, digits and '-'.
  const std::string name = TemporaryName(dir + "/a", "x");
  const std::string tail = "." + std::to_string(getpid()) + ".x";
  ASSERT_EQ(name.rfind(dir + "/a.tmp.", 0), 0u) << name;
  ASSERT_EQ(name.substr(name.size() - tail.size()), tail) << name;
  const std::string host =
      name.substr(dir.size() + 7, name.size() - tail.size() - dir.size() - 7);
  EXPECT_FALSE(host.empty());
  EXPECT_EQ(host.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMN"
                                   "OPQRSTUVWXYZ0123456789-"),
            std::string::npos)
      << host;
  const mode_t mask = umask(022);
  WriteFileAtomically(dir + "/a", "x");
  umask(mask);
  struct stat status;
  ASSERT_EQ(stat((dir + "/a").c_str(), &status), 0);
  EXPECT_EQ(status.st_mode & 0777, 0644u);
}

TEST(AtomicFileTest, CreateFileIfAbsentNeverFollowsOrReplaces) {
  const std::string dir = ScratchDirectory("atomic_marker");
  EXPECT_TRUE(CreateFileIfAbsent(dir + "/mark", "pfdm"));
  EXPECT_FALSE(CreateFileIfAbsent(dir + "/mark", "other"));
  EXPECT_EQ(ReadText(dir + "/mark"), "pfdm");
  WriteText(dir + "/victim", "precious");
  fs::create_symlink(dir + "/victim", dir + "/link");
  fs::create_symlink(dir + "/nowhere", dir + "/dangling");
  EXPECT_FALSE(CreateFileIfAbsent(dir + "/link", "pfdm"));
  EXPECT_FALSE(CreateFileIfAbsent(dir + "/dangling", "pfdm"));
  EXPECT_EQ(ReadText(dir + "/victim"), "precious");
  EXPECT_FALSE(fs::exists(dir + "/nowhere"));
  EXPECT_EQ(InputErrorOf([&] { CreateFileIfAbsent(dir + "/no/mark", ""); }),
            dir + "/no/mark: cannot write: No such file or directory");
}

TEST(AtomicFileTest, CheckFolderTakesFilesLeavesNothingBehind) {
  const std::string dir = ScratchDirectory("atomic_probe");
  CheckFolderTakesFiles(dir, "fit.json");
  EXPECT_EQ(Entries(dir), 0);
  EXPECT_EQ(
      InputErrorOf([&] { CheckFolderTakesFiles(dir + "/no", "x"); }),
      dir + "/no: cannot write in this folder: No such file or directory");
}

// A pid that ran and has ended.
pid_t EndedPid() {
  const pid_t pid = fork();
  if (pid == 0) _exit(0);
  waitpid(pid, nullptr, 0);
  return pid;
}

void Age(const std::string& path, int seconds) {
  fs::last_write_time(
      path, fs::file_time_type::clock::now() - std::chrono::seconds(seconds));
}

// A killed write leaves its temporary; the next write of the file removes
// it when its writer has certainly stopped, and nothing else: shards on
// other machines share the batch folder.
TEST(AtomicFileTest, TheNextWriteRemovesOnlyTemporariesOfEndedWriters) {
  const std::string dir = ScratchDirectory("atomic_abandoned");
  const std::string path = dir + "/summary.csv";
  const std::string mine = TemporaryName(path, "x");
  // This host's prefix, PATH.tmp.HOST.
  const std::string host_prefix =
      mine.substr(0, mine.size() - std::to_string(getpid()).size() - 3);
  const std::string ended = std::to_string(EndedPid());
  const std::string abandoned = host_prefix + "." + ended + ".Abandon1";
  const std::string recent = host_prefix + "." + ended + ".Recent01";
  const std::string live =
      host_prefix + "." + std::to_string(getppid()) + ".Running1";
  const std::string other_host = path + ".tmp.elsewhere." + ended + ".Shard001";
  const std::string older_pfdm = path + ".tmp." + ended;
  const std::string link = host_prefix + "." + ended + ".Link0001";
  for (const std::string& name :
       {abandoned, recent, live, other_host, older_pfdm}) {
    WriteText(name, "half");
    if (name != recent) Age(name, 3600);
  }
  WriteText(dir + "/victim", "precious");
  fs::create_symlink(dir + "/victim", link);
  AtomicWriteOptions keep;
  keep.remove_abandoned = false;
  WriteFileAtomically(path, "first", keep);
  EXPECT_TRUE(fs::exists(abandoned));
  WriteFileAtomically(path, "whole");
  EXPECT_FALSE(fs::exists(abandoned));
  for (const std::string& name : {recent, live, other_host, older_pfdm, link}) {
    EXPECT_TRUE(fs::exists(fs::symlink_status(name))) << name;
  }
  EXPECT_EQ(ReadText(dir + "/victim"), "precious");
  EXPECT_EQ(ReadText(path), "whole");
}

}  // namespace
}  // namespace pfdm
