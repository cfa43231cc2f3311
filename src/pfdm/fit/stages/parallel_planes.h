// Whether points lie on a few parallel planes, and the planes' normal: the
// short-axis slices of a cine stack, or short-axis tag planes at end-
// diastole, are cut normal to the long axis.
#ifndef PFDM_FIT_STAGES_PARALLEL_PLANES_H_
#define PFDM_FIT_STAGES_PARALLEL_PLANES_H_

#include <optional>
#include <vector>

#include "Eigen/Core"

namespace pfdm {

struct ParallelPlanes {
  Eigen::Vector3d normal;  // Unit length, either sign.
  int count = 0;           // Planes.
  double fraction = 0.0;   // Of the points, on them.
};

// The planes on which more than half of the points lie, within 1 mm, when
// there are 2 to 40 of them, each holding at least 2 % of the points (at
// least 5) with its flanks (1-3 mm to either side) holding less than half
// as many; nullopt otherwise.  The normals tried are the directions along
// which the points' heights concentrate most (a lattice over the sphere),
// each refined over its planes' points; the one whose planes hold the most
// points wins.  Uses at most 2,000 of the points (500 to search the
// directions), evenly spread over their order.
std::optional<ParallelPlanes> FindParallelPlanes(
    const std::vector<Eigen::Vector3d>& points);

}  // namespace pfdm

#endif  // PFDM_FIT_STAGES_PARALLEL_PLANES_H_
