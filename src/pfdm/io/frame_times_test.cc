#include "pfdm/io/frame_times.h"

#include <vector>

#include "gtest/gtest.h"
#include "pfdm/testing/test_util.h"

namespace pfdm {
namespace {

TEST(FrameTimesTest, OneTimePerFrameInOrder) {
  FrameTimes times;
  EXPECT_TRUE(times.Times("p.csv").empty());
  times.Add("p.csv", 2, 0, 0.0);
  times.Add("p.csv", 3, 1, 33.3);
  times.Add("p.csv", 4, 0, 0.0);  // Rows of a frame need not be together.
  times.Add("p.csv", 5, 2, 66.6);
  EXPECT_EQ(times.Times("p.csv"), (std::vector<double>{0.0, 33.3, 66.6}));
}

TEST(FrameTimesTest, ContradictionsAreNamedByLine) {
  FrameTimes times;
  times.Add("p.csv", 2, 0, 10.0);
  EXPECT_EQ(InputErrorOf([&] { times.Add("p.csv", 7, 0, 12.5); }),
            "p.csv:7: time_ms 12.5 differs from frame 0's 10 (line 2)");
  EXPECT_EQ(InputErrorOf([&] { times.Add("p.csv", 8, 1, -3.0); }),
            "p.csv:8: time_ms -3 is negative");
  times.Add("p.csv", 9, 1, 10.0);
  EXPECT_EQ(InputErrorOf([&] { times.Times("p.csv"); }),
            "p.csv:9: frame 1's time_ms 10 is not after frame 0's 10");
}

}  // namespace
}  // namespace pfdm
