#include "pfdm/util/median.h"

#include "gtest/gtest.h"

namespace pfdm {
namespace {

TEST(MedianTest, IsTheMiddleValueOrTheUpperOfTwo) {
  EXPECT_EQ(Median({}), 0.0);
  EXPECT_EQ(Median({4.0}), 4.0);
  EXPECT_EQ(Median({9.0, -1.0, 3.0}), 3.0);
  EXPECT_EQ(Median({9.0, -1.0, 3.0, 5.0}), 5.0);
}

}  // namespace
}  // namespace pfdm
