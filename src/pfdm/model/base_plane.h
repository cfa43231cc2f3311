// The plane that closes the LV cavity at the base: through the mitral
// valve's hinge points where the data has them.
#ifndef PFDM_MODEL_BASE_PLANE_H_
#define PFDM_MODEL_BASE_PLANE_H_

#include <optional>
#include <vector>

#include "Eigen/Core"

namespace pfdm {

struct BasePlane {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();    // On the plane.
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // Unit; sign free.
  int num_points = 0;                                 // It was fitted to.
};

// Least-squares plane through points; nullopt for fewer than 3 points or
// points that lie at one place or nearly on a line (no plane is defined).
std::optional<BasePlane> FitBasePlane(
    const std::vector<Eigen::Vector3d>& points);

}  // namespace pfdm

#endif  // PFDM_MODEL_BASE_PLANE_H_
