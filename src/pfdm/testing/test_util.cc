#include "pfdm/testing/test_util.h"

#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "gtest/gtest.h"

namespace pfdm {

std::string ScratchDirectory(const std::string& name) {
  static int counter = 0;
  // Named by the test, not the process: a rerun replaces its predecessor's
  // files (disk use stays bounded) and what a test wrote is easy to find
  // and look at afterwards, while tests running in parallel never share.
  std::string test = "no_test";
  if (const testing::TestInfo* info =
          testing::UnitTest::GetInstance()->current_test_info()) {
    test = std::string(info->test_suite_name()) + "." + info->name();
    std::replace(test.begin(), test.end(), '/', '_');
  }
  const std::filesystem::path dir = std::filesystem::path(testing::TempDir()) /
                                    "pfdm_tests" / test /
                                    (name + "_" + std::to_string(counter++));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

void WriteText(const std::string& path, const std::string& text) {
  std::ofstream(path) << text;
}

int CountOf(const std::string& text, const std::string& what) {
  int n = 0;
  for (size_t at = text.find(what); at != std::string::npos;
       at = text.find(what, at + 1)) {
    ++n;
  }
  return n;
}

std::string ReadText(const std::string& path) {
  std::ifstream in(path);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

CommandResult RunPfdm(const std::string& arguments) {
  const std::string dir = ScratchDirectory("run");
  const std::string out = dir + "/stdout", err = dir + "/stderr";
  const std::string command =
      std::string(PFDM_BINARY) + " " + arguments + " > " + out + " 2> " + err;
  const int status = std::system(command.c_str());
  CommandResult result;
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.output = ReadText(out);
  result.error = ReadText(err);
  return result;
}

std::string SharedDataDirectory() {
  const std::string dir = PFDM_SHARED_DATA_DIR;
  return std::filesystem::is_directory(dir) ? dir : "";
}

}  // namespace pfdm
