#include "pfdm/report/gnuplot.h"

#include <unistd.h>

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
                  "/bad.svg: gnuplot failed: line 2: no datablock named "
                  "$missing");
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

// gnuplot gone before its script is all written: the error names the
// plot, and the broken pipe does not end the caller's process.
TEST(GnuplotTest, AGnuplotThatExitsEarlyIsAnErrorNotASignal) {
  PlotData big{"big", std::vector<std::vector<double>>(
                          400000, std::vector<double>{1.0, 2.0, 3.0})};
  SvgRendering rendering;
  rendering.Render({{"first.svg", {}, "exit", 400, 300},
                    {"second.svg", {big}, "plot $big using 1:2", 400, 300}});
  try {
    rendering.Finish();
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()).rfind("first.svg: gnuplot failed", 0),
              0u)
        << error.what();
  }
}

// gnuplot may start long before it gets its plots.
TEST(GnuplotTest, RendersPlotsHandedOverAfterItStarted) {
  SvgRendering rendering;
  usleep(50000);
  rendering.Render(
      {{"late.svg", {{"d", {{0, 1}, {1, 2}}}}, "plot $d", 300, 200}});
  const std::vector<std::string> svgs = rendering.Finish();
  ASSERT_EQ(svgs.size(), 1u);
  EXPECT_NE(svgs[0].find("</svg>"), std::string::npos);
}

TEST(GnuplotTest, AllUndefinedDataNamesTheOutputNotAScript) {
  try {
    RenderSvgString("parameters.svg",
                    {{"d", {{0, std::nan("")}, {1, std::nan("")}}}},
                    "plot $d using 1:2", 400, 300);
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()),
              "parameters.svg: gnuplot failed: line 6: all points y value "
              "undefined!");
  }
}

// gnuplot's SVG terminal keeps the stroke colour it last wrote across
// documents, and writes it into the first, empty, group of the next:
// invisible, the only byte a plot after the first may differ in.
std::string WithoutCarriedStroke(std::string svg) {
  const std::string carried =
      "<g fill=\"none\" color=\"#FFFFFF\" stroke=\"black\"";
  const size_t at = svg.find(carried);
  if (at != std::string::npos) {
    svg.replace(at, carried.size(),
                "<g fill=\"none\" color=\"#FFFFFF\" stroke=\"currentColor\"");
  }
  return svg;
}

// One process for several plots gives each the SVG it would get alone: no
// setting, data block or size carries over to the next.
TEST(GnuplotTest, OneProcessRendersEachPlotAsAloneWould) {
  const SvgPlot line{"line.svg",
                     {{"d", {{0, 1}, {1, 3}, {2, 2}}}},
                     "set multiplot layout 1,2\nset logscale y\nset title "
                     "'first'\nplot $d using 1:2 with lines\nplot $d using "
                     "2:1\nunset multiplot",
                     500,
                     300};
  const SvgPlot points{"points.svg",
                       {{"e", {{0, -1}, {1, 2}}}},
                       "plot $e using 1:2 with points title 'second'",
                       700,
                       200};
  const std::vector<std::string> svgs = RenderSvgStrings({line, points, line});
  ASSERT_EQ(svgs.size(), 3u);
  EXPECT_EQ(svgs[0], RenderSvgString(line));
  EXPECT_TRUE(WithoutCarriedStroke(svgs[1]) == RenderSvgString(points));
  EXPECT_TRUE(WithoutCarriedStroke(svgs[2]) == svgs[0]);
  EXPECT_NE(svgs[1].find("viewBox=\"0 0 700 200\""), std::string::npos);
  EXPECT_EQ(svgs[1].find("first"), std::string::npos);
  EXPECT_EQ(CountOf(svgs[1], "</svg>"), 1);
}

// Started, gnuplot renders while the caller goes on; Finish gives what
// RenderSvgStrings gives, and an unfinished rendering may simply go.
TEST(GnuplotTest, RenderingRunsWhileTheCallerWorks) {
  const SvgPlot plot{"a.svg", {{"d", {{0, 1}, {1, 2}}}}, "plot $d", 400, 300};
  SvgRendering rendering({plot, plot});
  { SvgRendering abandoned({plot}); }
  const std::vector<std::string> svgs = rendering.Finish();
  ASSERT_EQ(svgs.size(), 2u);
  EXPECT_EQ(svgs[0], RenderSvgString(plot));
  EXPECT_TRUE(SvgRendering(std::vector<SvgPlot>{}).Finish().empty());
}

TEST(GnuplotTest, AFailingPlotAmongSeveralIsNamed) {
  const SvgPlot good{
      "good.svg", {{"d", {{0, 1}, {1, 2}}}}, "plot $d", 400, 300};
  // A data block of the plot before is gone, as in a process of its own.
  const SvgPlot bad{"bad.svg", {}, "plot $d", 400, 300};
  try {
    RenderSvgStrings({good, bad});
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()),
              // The line of the one script all the plots share.
              "bad.svg: gnuplot failed: line 9: no datablock named $d");
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
