// A starting model from the first frame's points, with no user input.
#ifndef PFDM_FIT_STAGES_INITIALIZATION_H_
#define PFDM_FIT_STAGES_INITIALIZATION_H_

#include <optional>
#include <vector>

#include "Eigen/Core"
#include "pfdm/fit/fit_options.h"
#include "pfdm/model/model.h"

namespace pfdm {

// Long axis: the hint, else the points' principal axis, pointed from the end
// whose cross-section is narrower (the apex) to the wider one (the base).
// Axis 1: the principal direction across the long axis, its sign chosen so
// that the points' third moment along it is positive; axis 2 = 3 x 1.  Both
// rules move with the data, so a rigidly moved data set gets the same model.
// a0 (the scale gauge, held afterwards) makes a3 = 0.8 span the points'
// axial extent over [u_min, u_max]; a1, a2 come from the radial extents.
Model InitializeModel(const ModelConfig& config,
                      const std::vector<Eigen::Vector3d>& points,
                      const std::optional<AxisHint>& hint);

// The same along a given line (`direction` of unit length, either sign),
// pointed from its narrower end to its wider one: InitializeModel without a
// hint is InitializeModelAlong the principal axis.
Model InitializeModelAlong(const ModelConfig& config,
                           const std::vector<Eigen::Vector3d>& points,
                           const Eigen::Vector3d& direction);

// The points' principal directions, columns by ascending variance.
Eigen::Matrix3d PrincipalAxes(const std::vector<Eigen::Vector3d>& points);

}  // namespace pfdm

#endif  // PFDM_FIT_STAGES_INITIALIZATION_H_
