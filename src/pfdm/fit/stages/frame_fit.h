// One frame's fit as its stages: the global correspondence rounds, the wall
// (frame 0), the local field and the summary.
#ifndef PFDM_FIT_STAGES_FRAME_FIT_H_
#define PFDM_FIT_STAGES_FRAME_FIT_H_

#include <string>

#include "pfdm/fit/correspondence/surface_grid.h"
#include "pfdm/fit/fit_options.h"
#include "pfdm/fit/problem/local_direct.h"
#include "pfdm/fit/stages/frame_points.h"
#include "pfdm/fit/stages/sequence_fit.h"
#include "pfdm/fit/stages/wall_stage.h"
#include "pfdm/model/model.h"
#include "pfdm/util/point_data.h"

namespace pfdm {

// What a frame's fit takes from the frames before it and leaves to the
// next.
struct CarriedState {
  explicit CarriedState(const Model& start)
      : model(start), previous(start.state), reference(start.state) {}

  Model model;  // Where the next frame's fit starts.
  // The state the prior pulls toward: the previous frame's; frame 0's
  // (reference) for untracked frames, which may also not spin away from its
  // pose.
  ModelState previous;
  ModelState reference;
  int frames_fitted = 0;  // Before the frame being fitted.
  // Frame 0's material points' lowest and highest u: where --incompressible
  // holds the wall's volume.
  double data_u_low = 0.0, data_u_high = 0.0;
  TrackedMaterial tracked_material;
  // Its tags' depths are frame 0's (held_depths.h), not ranked in each
  // frame: FitSequence sets it once it has measured their noise.
  bool depths_held = false;
  // Frame 0's depths have been shrunk for the noise a pilot measured
  // (FitSequence): no pilot is flown again.
  bool depths_shrunk = false;
  // Frame 0's robust loss scale (0 without a loss), for the band of a
  // solid's ranks in every frame (RankBandMm).
  double reference_loss_scale_mm = 0.0;
  // The local field's direct solver, kept for its factorization: tracked
  // frames' fields share one matrix (local_direct.h).
  LocalDirectSolver local_solver;
  // The closest-point searches' grids, their k-d trees kept while the
  // surface moves little (SurfaceGrid::Follow): the global rounds' and the
  // local field's.  One grid for both was rebuilt twice a frame more, as
  // the field came and went (biv-me's contours: 137 builds in 25 frames).
  SurfaceGrid surface_grid;
  SurfaceGrid local_surface_grid;
};

// Fits `frame` (`reference`: frame 0) from carried->model and updates
// *carried for the next frame; decides the wall on frame 0 when *wall is
// undecided, and with --loss_scale auto measures the frame's loss scale
// (loss_scale.h).  Throws InputError naming the frame when a solve fails or the
// fit diverges.
FrameFit FitFrame(const Frame& frame, bool reference,
                  const FramesPerId& frames_per_id, const FitOptions& options,
                  const std::string& source, WallDecision* wall,
                  CarriedState* carried);

}  // namespace pfdm

#endif  // PFDM_FIT_STAGES_FRAME_FIT_H_
