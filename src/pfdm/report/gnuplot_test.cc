#include "pfdm/report/gnuplot.h"

#include <cmath>
#include <filesystem>

#include "gtest/gtest.h"
#include "pfdm/testing/test_util.h"
#include "pfdm/util/error.h"

namespace pfdm {
namespace {

TEST(GnuplotTest, RendersAnSvgFromDataBlocks) {
  const std::string path = ScratchDirectory("plot") + "/line.svg";
  RenderSvg({{"line", {{0, 1}, {1, 3}, {2, 2}}}},
            "plot $line using 1:2 with linespoints title 'test line'", path);
  const std::string svg = ReadText(path);
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_NE(svg.find("test line"), std::string::npos);
}

TEST(GnuplotTest, ScriptErrorsAreReportedInOneLineAndLeaveNoFile) {
  const std::string dir = ScratchDirectory("plot");
  try {
    RenderSvg({}, "plot $missing using 1:2", dir + "/bad.svg");
    FAIL() << "no error";
  } catch (const InputError& error) {
    // gnuplot's own message, not the temporary script it once named.
    EXPECT_EQ(std::string(error.what()),
              dir +
                  "/bad.svg: gnuplot failed: line 0: no datablock named "
                  "$missing");
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

TEST(GnuplotTest, AllUndefinedDataNamesTheOutputNotAScript) {
  try {
    RenderSvgString("parameters.svg",
                    {{"d", {{0, std::nan("")}, {1, std::nan("")}}}},
                    "plot $d using 1:2", 400, 300);
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()),
              "parameters.svg: gnuplot failed: line 3: all points y value "
              "undefined!");
  }
}

// The path once went into a shell command in single quotes: this one ran
// `touch PWNED` in the working folder (issue 14).
TEST(GnuplotTest, PathsNeverReachAShell) {
  const std::string dir = ScratchDirectory("plot");
  const std::filesystem::path cwd = std::filesystem::current_path();
  std::filesystem::current_path(dir);
  const std::string path = dir + "/c';touch PWNED;'d.svg";
  try {
    RenderSvg({{"line", {{0, 1}, {1, 3}}}}, "plot $line using 1:2", path);
  } catch (...) {
    std::filesystem::current_path(cwd);
    throw;
  }
  std::filesystem::current_path(cwd);
  EXPECT_NE(ReadText(path).find("</svg>"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(dir + "/PWNED"));
  int entries = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    (void)entry;
    ++entries;
  }
  EXPECT_EQ(entries, 1);  // The SVG alone: no script, log or temporary.
}

}  // namespace
}  // namespace pfdm
