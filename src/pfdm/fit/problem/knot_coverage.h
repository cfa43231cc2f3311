// Which knots a frame's points cover well enough that their radii are the
// data's: the untracked prior pulls a1 and a2 less there (FrameProblem::
// AddPrior), and holds them fully where the data are thin.
#ifndef PFDM_FIT_PROBLEM_KNOT_COVERAGE_H_
#define PFDM_FIT_PROBLEM_KNOT_COVERAGE_H_

#include <vector>

#include "pfdm/fit/correspondence/correspondence.h"
#include "pfdm/model/parameter_function.h"

namespace pfdm {

// Each knot's points, each counted by its hat weight (what a knot's value
// takes from a point between it and its neighbour), in kCoverageSectors
// equal sectors of v.
constexpr int kCoverageSectors = 8;
using SectorCounts = std::vector<std::vector<double>>;
SectorCounts KnotSectorCounts(const KnotGrid& grid,
                              const std::vector<MaterialPoint>& material);

// A knot is covered when its hat-weighted points reach `min_share` of an
// even share (N / K) and fill at least `min_sectors` of the sectors with
// at least one point's weight each: a ring's two radii need points around
// it, not a long-axis contour's two crossings alone.
// biv-me's contours (short-axis stack and three long-axis planes) cover
// knots 1-13 of 17 this way; the knots above the stack and the apex's stay
// held.
inline constexpr double kCoveredKnotShare = 0.5;
inline constexpr int kCoveredKnotSectors = 6;
std::vector<bool> CoveredKnots(const KnotGrid& grid,
                               const std::vector<MaterialPoint>& material,
                               double min_share, int min_sectors);

// The untracked prior's scales at each knot: `scales`, with a1's and a2's
// times `radii_scale` at the covered knots.
std::vector<FunctionValues> CoveredRadiiScales(
    const KnotGrid& grid, const std::vector<MaterialPoint>& material,
    const FunctionValues& scales, double radii_scale);

}  // namespace pfdm

#endif  // PFDM_FIT_PROBLEM_KNOT_COVERAGE_H_
