#include "pfdm/io/point_spread.h"

#include <string>
#include <vector>

#include "gtest/gtest.h"
#include "pfdm/util/error.h"

namespace pfdm {
namespace {

std::string ErrorOf(const std::vector<DataPoint>& points,
                    const std::vector<unsigned>& lines) {
  try {
    CheckPointsLieTogether("p.csv", 3, points, lines);
  } catch (const InputError& error) {
    return error.what();
  }
  return "no error";
}

// 11 points within 10 mm of (100, 200, 300), the median.
std::vector<DataPoint> Heart() {
  std::vector<DataPoint> points;
  for (int i = 0; i <= 10; ++i) {
    points.push_back({i, Eigen::Vector3d(95 + i, 200, 300)});
  }
  return points;
}

TEST(PointSpreadTest, NamesTheFirstFarPointByLine) {
  std::vector<DataPoint> points = Heart();
  std::vector<unsigned> lines = {2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12};
  EXPECT_EQ(ErrorOf(points, lines), "no error");
  // 500 mm from the median is still a heart's; 600 is not.
  points.push_back({11, Eigen::Vector3d(100, 700, 300)});
  points.push_back({12, Eigen::Vector3d(100, 200, -300)});
  points.push_back({13, Eigen::Vector3d(100, 200, 1e6)});
  lines.insert(lines.end(), {40, 30, 20});
  EXPECT_EQ(ErrorOf(points, lines),
            "p.csv:20: frame 3: the point lies 999700 mm from the centre of "
            "the frame's points, beyond any heart (500 mm)");
  lines.back() = 50;  // Now the point 600 mm off comes first.
  EXPECT_EQ(ErrorOf(points, lines),
            "p.csv:30: frame 3: the point lies 600 mm from the centre of the "
            "frame's points, beyond any heart (500 mm)");
  EXPECT_EQ(ErrorOf({}, {}), "no error");
}

// Data in micrometres: every point is far from the others' centre.
TEST(PointSpreadTest, AFrameBeyondAnyHeartIsRefusedAtItsFirstLine) {
  std::vector<DataPoint> points;
  std::vector<unsigned> lines;
  for (int i = 0; i < 10; ++i) {
    points.push_back({i, Eigen::Vector3d(0, 0, i * 1e4)});
    lines.push_back(i + 2);
  }
  EXPECT_EQ(ErrorOf(points, lines),
            "p.csv:2: frame 3: the point lies 50000 mm from the centre of the "
            "frame's points, beyond any heart (500 mm)");
}

}  // namespace
}  // namespace pfdm
