#include "pfdm/segmentation/rv_contact.h"

#include <cmath>

#include "gtest/gtest.h"
#include "pfdm/util/angles.h"

namespace pfdm {
namespace {

// A ring of myocardium and an RV crescent outside it from 30 to 150
// degrees: the contact's ends at those angles.
TEST(RvContactTest, ArcEndsAtTheCrescentsEdges) {
  const int n = 60;
  const Eigen::Vector2d centre(30, 30);
  SliceMask myo{n, n, std::vector<std::uint8_t>(n * n, 0)};
  SliceMask rv = myo;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const Eigen::Vector2d d = Eigen::Vector2d(i, j) - centre;
      const double r = d.norm(), angle = std::atan2(d.y(), d.x()) * 180 / kPi;
      myo.inside[j * n + i] = r >= 10 && r <= 16;
      rv.inside[j * n + i] = r > 16 && r <= 24 && angle >= 30 && angle <= 150;
    }
  }
  const auto ends = RvContactEnds(myo, rv, centre, 1.0, 1.0);
  ASSERT_TRUE(ends.has_value());
  auto angle = [&](const Eigen::Vector2d& p) {
    return std::atan2(p.y() - centre.y(), p.x() - centre.x()) * 180 / kPi;
  };
  EXPECT_NEAR(angle(ends->first), 30.0, 4.0);
  EXPECT_NEAR(angle(ends->second), 150.0, 4.0);
  EXPECT_NEAR((ends->first - centre).norm(), 16.5, 1.0);
  // No RV: no insertion.
  rv.inside.assign(n * n, 0);
  EXPECT_FALSE(RvContactEnds(myo, rv, centre, 1.0, 1.0).has_value());
}

}  // namespace
}  // namespace pfdm
