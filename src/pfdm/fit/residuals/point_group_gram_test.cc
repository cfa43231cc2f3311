// The Gram matrices (point_group_gram.cc) behind a group's square-root
// form when both knots are varied over the same functions.
#include <vector>

#include "gtest/gtest.h"
#include "pfdm/fit/residuals/point_group_residual.h"
#include "pfdm/testing/point_group_checks.h"

namespace pfdm {
namespace {

// A tracked frame: the pose and globals held, the knots' free entries.
TEST(PointGroupGramTest, SquareRootFormOfKnotsOnly) {
  ExpectStackedNormalEquations({{false, false, false, true, true},
                                {},
                                FreeFunctions(),
                                FreeFunctions()});
}

// The reference frame: the pose varied too, and the globals, here whole.
TEST(PointGroupGramTest, SquareRootFormOfEveryBlock) {
  ExpectStackedNormalEquations(
      {{true, true, true, true, true}, {}, FreeFunctions(), FreeFunctions()});
  ExpectStackedNormalEquations({{true, false, true, true, true},
                                {kA0, kEps1},
                                FreeFunctions(),
                                FreeFunctions()});
}

// A tracked frame: the pose and the knots varied, every point with three
// rows, so the pose's columns come from moments (PoseMomentGram); with a
// point-to-plane sample among them, from MomentGram.
TEST(PointGroupGramTest, SquareRootFormOfPoseAndKnots) {
  GroupCase tracked{{true, true, false, true, true},
                    {},
                    FreeFunctions(),
                    FreeFunctions(),
                    false};
  ExpectStackedNormalEquations(tracked);
  // On the mid-wall ds/df has half its entries zero, which the moments
  // leave out (the first points say which); points off it after the first
  // fill more in, and the group starts over with all.
  tracked.mid_wall_first = 60;
  ExpectStackedNormalEquations(tracked);
  tracked.mid_wall_first = 40;
  ExpectStackedNormalEquations(tracked);
  tracked.mid_wall_first = 0;
  tracked.point_to_plane = true;
  ExpectStackedNormalEquations(tracked);
}

}  // namespace
}  // namespace pfdm
