#include "pfdm/util/stride.h"

#include "gtest/gtest.h"

namespace pfdm {
namespace {

// Every stride-th item from the first, counted.
size_t Kept(size_t count, size_t stride) {
  return count == 0 ? 0 : (count - 1) / stride + 1;
}

// The stride keeps at most `most` items, and a stride one less would keep
// more: the least that fits.
TEST(StrideTest, KeepsAtMostTheLimitWithTheLeastStride) {
  for (size_t most : {1, 3, 4096}) {
    for (size_t count : {0, 1, 2, 3, 4, 4095, 4096, 4097, 8192, 8193, 20000}) {
      const size_t stride = StrideForAtMost(count, most);
      EXPECT_GE(stride, 1u);
      EXPECT_LE(Kept(count, stride), most) << count << " " << most;
      if (stride > 1) {
        EXPECT_GT(Kept(count, stride - 1), most) << count << " " << most;
      }
    }
  }
  EXPECT_EQ(StrideForAtMost(20000, 4096), 5u);  // 4,000 kept.
  EXPECT_EQ(StrideForAtMost(4096, 4096), 1u);
  EXPECT_EQ(StrideForAtMost(10, 0), 10u);  // At least one kept.
}

}  // namespace
}  // namespace pfdm
