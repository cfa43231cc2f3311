#include "pfdm/report/gnuplot.h"

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

TEST(GnuplotTest, ScriptErrorsAreReportedAndLeaveNoFile) {
  const std::string dir = ScratchDirectory("plot");
  EXPECT_THROW(RenderSvg({}, "plot $missing using 1:2", dir + "/bad.svg"),
               InputError);
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

}  // namespace
}  // namespace pfdm
