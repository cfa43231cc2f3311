// Model::WorldPoint at many material points at once.  One at a time, each
// point's shape takes seven scalar sines and cosines (u, v, the bends'
// phases and shapes, the twist); here they come from SinCosMany
// (batch_trig.h) a batch of points at a time, and the shape from its closed
// form (ShapesOfBatch, as the point groups take theirs), which matches
// ReferenceShape to round-off.  For
// the per-frame passes over every point: residuals, the wall's distances,
// the local field's rows.
#ifndef PFDM_MODEL_WORLD_POINTS_H_
#define PFDM_MODEL_WORLD_POINTS_H_

#include <cstddef>

#include "Eigen/Core"
#include "pfdm/model/model.h"

namespace pfdm {

// out[i] = model.WorldPoint(u[i], v[i], w[i]) for i < n, where the
// coordinates of point i are u[i * stride], v[i * stride], w[i * stride]
// (stride 3 for an array of {u, v, w} structs).
void WorldPoints(const Model& model, size_t n, const double* u, const double* v,
                 const double* w, size_t stride, Eigen::Vector3d* out);

}  // namespace pfdm

#endif  // PFDM_MODEL_WORLD_POINTS_H_
