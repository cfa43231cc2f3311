#include "pfdm/solvers/damping_groups.h"

#include "gtest/gtest.h"
#include "pfdm/util/error.h"

namespace pfdm {
namespace {

TEST(DampingGroupsTest, ParsesGroupsAndRefusesBadEntries) {
  const DampingGroups groups =
      DampingGroupsFromText("twist=10,offsets=0.5,bending=2");
  EXPECT_EQ(groups.Of(kTau), 10.0);
  EXPECT_EQ(groups.Of(kE2o), 0.5);
  EXPECT_EQ(groups.Of(kB1), 2.0);
  EXPECT_EQ(groups.Of(kA3), 1.0);
  EXPECT_EQ(groups.pose, 1.0);
  EXPECT_EQ(DampingGroupsFromText("").Of(kTau), 1.0);
  for (const char* bad : {"twist", "twist=", "spin=2", "twist=0", "twist=-1",
                          "twist=2x", "twist=nan", "twist=1,,"}) {
    EXPECT_THROW(DampingGroupsFromText(bad), InputError) << bad;
  }
}

}  // namespace
}  // namespace pfdm
