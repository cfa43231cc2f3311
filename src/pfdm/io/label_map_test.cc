#include "pfdm/io/label_map.h"

#include "gtest/gtest.h"
#include "pfdm/testing/test_util.h"

namespace pfdm {
namespace {

TEST(LabelMapTest, PresetsAndPairs) {
  const LabelMap acdc = ParseLabelMap("acdc");
  EXPECT_EQ(acdc.lv, 3);
  EXPECT_EQ(acdc.myo, 2);
  EXPECT_EQ(acdc.rv, 1);
  const LabelMap mnms = ParseLabelMap("mnms");
  EXPECT_EQ(mnms.lv, 1);
  EXPECT_EQ(mnms.rv, 3);
  const LabelMap own = ParseLabelMap("myo=20,lv=10");
  EXPECT_EQ(own.lv, 10);
  EXPECT_EQ(own.myo, 20);
  EXPECT_EQ(own.rv, -1);
  EXPECT_EQ(ParseLabelMap("lv=1,myo=2,rv=none").rv, -1);
}

TEST(LabelMapTest, Refused) {
  EXPECT_EQ(InputErrorOf([] { ParseLabelMap("lv=3,myo=3"); }),
            "--labels 'lv=3,myo=3': two structures share a label (expected "
            "acdc, mnms or lv=3,myo=2,rv=1)");
  EXPECT_EQ(InputErrorOf([] { ParseLabelMap("lv=3"); }),
            "--labels 'lv=3': lv and myo are needed (expected acdc, mnms or "
            "lv=3,myo=2,rv=1)");
  EXPECT_EQ(InputErrorOf([] { ParseLabelMap("lv=x,myo=2"); }),
            "--labels 'lv=x,myo=2': lv=x is not a label (1 to 65535) "
            "(expected acdc, mnms or lv=3,myo=2,rv=1)");
  EXPECT_EQ(InputErrorOf([] { ParseLabelMap("la=4,lv=3,myo=2"); }),
            "--labels 'la=4,lv=3,myo=2': 'la=4' is not lv=, myo= or rv= "
            "(expected acdc, mnms or lv=3,myo=2,rv=1)");
}

}  // namespace
}  // namespace pfdm
