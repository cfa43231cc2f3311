// Where the RV meets the LV myocardium in one short-axis slice: the ends
// of the contact arc are the RV insertion points (the septum lies between
// them), which anchor the AHA segments.
#ifndef PFDM_SEGMENTATION_RV_CONTACT_H_
#define PFDM_SEGMENTATION_RV_CONTACT_H_

#include <optional>
#include <utility>

#include "Eigen/Core"
#include "pfdm/segmentation/boundary_points.h"

namespace pfdm {

// The contact points are the midpoints between each myocardial voxel and
// its 4-neighbours of the RV.  Seen from `centre` (the cavity's centroid),
// with (i, j) scaled by the spacings to mm, their angles leave one largest
// gap: the arc is the rest, its ends the contact points beside the gap.
// nullopt for fewer than 3 contact points or an arc under 20 degrees.
// Fractional (i, j).
std::optional<std::pair<Eigen::Vector2d, Eigen::Vector2d>> RvContactEnds(
    const SliceMask& myocardium, const SliceMask& rv,
    const Eigen::Vector2d& centre, double spacing_i, double spacing_j);

}  // namespace pfdm

#endif  // PFDM_SEGMENTATION_RV_CONTACT_H_
