// The local field on top of a frame's global fit (FitOptions::local;
// Metaxas & Terzopoulos: global first, local after), in rounds for the
// frame's contour points, which find their closest points on the whole
// model after each solve.
#ifndef PFDM_FIT_STAGES_LOCAL_STAGE_H_
#define PFDM_FIT_STAGES_LOCAL_STAGE_H_

#include <string>
#include <vector>

#include "pfdm/fit/correspondence/surface_grid.h"
#include "pfdm/fit/fit_options.h"
#include "pfdm/fit/problem/local_direct.h"
#include "pfdm/fit/stages/frame_points.h"
#include "pfdm/fit/stages/sequence_fit.h"
#include "pfdm/model/model.h"

namespace pfdm {

// Which points pull along the normal in the local field: contours
// (untracked, not tags).  Tags, on their first frame too, pull with the
// whole vector.
std::vector<bool> LocalSlidingPoints(const FramePoints& frame);

// Points seen in one frame only (contours) pull along the normal and then
// find their closest points on the whole model, as they did on the global
// one: the field moves the surface along itself too.  Tracked points keep
// the global fit's material point and pull with the whole vector on every
// frame, frame 0 included.  The rounds end when the contours' closest
// points settle or a round gains little.  Sets model->state.local, the
// contours' material points in *fit and its local account; throws
// InputError naming the frame when a solve is unusable.  `direct` (may be
// null) keeps the direct solver's factorization from frame to frame,
// `grid` (may be null) the searches' grid (SurfaceGrid::Follow).
void FitLocalStage(const FramePoints& frame, const FitOptions& options,
                   const std::string& source, Model* model, FrameFit* fit,
                   LocalDirectSolver* direct = nullptr,
                   SurfaceGrid* grid = nullptr);

}  // namespace pfdm

#endif  // PFDM_FIT_STAGES_LOCAL_STAGE_H_
