#include "pfdm/report/regional_limit.h"

#include "gtest/gtest.h"
#include "pfdm/phantom/phantom.h"
#include "pfdm/testing/truth_as_fit.h"

namespace pfdm {
namespace {

LocalGrid SmallGrid(const ModelConfig& config) {
  LocalGrid grid;
  grid.rows = 5;
  grid.cols = 8;
  grid.u_min = config.u_min;
  grid.u_max = config.u_max;
  return grid;
}

// A surface has no wall to see through; a solid with a field through the
// wall sees its segments' own thickening; without one, tags read as their
// ring and contours' thickening as their ring's.
TEST(RegionalLimitTest, BySurfaceFieldAndTracking) {
  PhantomOptions options;
  options.num_points = 20;
  SequenceFit fit = TruthAsFit(MakePhantom(options));
  EXPECT_EQ(RegionalLimitOf(fit), RegionalLimit::kNone);
  EXPECT_EQ(RegionalLimitNote(RegionalLimit::kNone), "");
  fit.config.MakeSolid();
  const LocalGrid grid = SmallGrid(fit.config);
  for (FrameFit& frame : fit.frames) frame.state.local = LocalField::Zero(grid);
  // Tags ranked in every tracked frame (--tag_depths ranked).
  EXPECT_EQ(RegionalLimitOf(fit), RegionalLimit::kRing);
  // Held from frame 0: the segments' motion is theirs.
  SequenceFit held = fit;
  for (size_t t = 1; t < held.frames.size(); ++t) {
    held.frames[t].depths_held = true;
  }
  EXPECT_EQ(RegionalLimitOf(held), RegionalLimit::kThickening);
  // --local off: no field at all moves the layers alike too.
  SequenceFit global_only = fit;
  for (FrameFit& frame : global_only.frames) frame.state.local = LocalField();
  EXPECT_EQ(RegionalLimitOf(global_only), RegionalLimit::kRing);
  SequenceFit transmural = fit;
  for (FrameFit& frame : transmural.frames) {
    frame.state.local = LocalField::Zero(grid, /*transmural=*/true);
  }
  EXPECT_EQ(RegionalLimitOf(transmural), RegionalLimit::kThirds);
  EXPECT_NE(RegionalLimitNote(RegionalLimit::kThirds).find("third"),
            std::string::npos);
  for (FrameFit& frame : fit.frames) frame.tracked = false;
  EXPECT_EQ(RegionalLimitOf(fit), RegionalLimit::kThickening);
  for (RegionalLimit limit :
       {RegionalLimit::kRing, RegionalLimit::kThickening}) {
    EXPECT_NE(RegionalLimitNote(limit).find("--local_transmural"),
              std::string::npos);
  }
}

}  // namespace
}  // namespace pfdm
