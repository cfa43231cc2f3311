// Tags in a solid whose walls the frame's contours give: each tag's depth
// w is where it lies across the fitted wall, not its rank among the tags.
//
// Ranks (QuantileDepths, transmural.h) assume the tags fill the wall from
// the endocardium to the epicardium, which holds for tags through the wall
// alone: their spread is the wall.  Beside both walls' contours it need
// not: mid-wall tags (SPAMM lines read where the wall's middle is) ranked
// over [-1, 1] pulled the walls toward them against the contours, and on
// the LV phantom (400 mid-wall tags with both walls' contours on 9
// short-axis slices and 3 long-axis planes, 0.5 mm noise) EDV read 115-116
// ml against 106.9, with no verdict.  The contours place the walls, so a
// tag's distance from the mid-wall says its depth.
#ifndef PFDM_FIT_CORRESPONDENCE_MEASURED_DEPTHS_H_
#define PFDM_FIT_CORRESPONDENCE_MEASURED_DEPTHS_H_

#include <vector>

#include "pfdm/fit/correspondence/correspondence.h"
#include "pfdm/model/model.h"
#include "pfdm/util/point_data.h"

namespace pfdm {

// Whether the frame has points labelled on both walls (WallLayer), whose
// contours then place a solid's walls; the same of the points' layers' w
// (-1 endocardium, +1 epicardium, 0 unlabelled).
bool HasBothWalls(const Frame& frame);
bool HasBothWalls(const std::vector<double>& layer_w);

// Beyond this a measured depth is taken at it: a tag a quarter of the wall
// outside it is an outlier, whose cubic depth (model/transmural.h) would
// run away.
constexpr double kMaxMeasuredDepth = 1.5;

// Each tag's depth w from its distance d across the mid-wall (MidwallDistances,
// transmural.h) at its material point: the layer whose offset WallDepth(f,
// w) = w h / 2 + w^2 s + (w^3 - w) q (model/transmural.h) is d, by Newton's
// method from 2 d / h (exact where s = q = 0, frame 0's evenly spaced
// layers), within +-kMaxMeasuredDepth; 0 where h is not positive.
std::vector<double> MeasuredDepths(const Model& model,
                                   const std::vector<MaterialPoint>& material,
                                   const std::vector<double>& distances);

}  // namespace pfdm

#endif  // PFDM_FIT_CORRESPONDENCE_MEASURED_DEPTHS_H_
