// The first stage of a sequence fit: checks that every frame can be fitted,
// then the initial model (initialization.h) and what the contours say of the
// wall.
#ifndef PFDM_FIT_STAGES_START_H_
#define PFDM_FIT_STAGES_START_H_

#include <string>

#include "pfdm/fit/fit_options.h"
#include "pfdm/fit/stages/frame_points.h"
#include "pfdm/fit/stages/wall_stage.h"
#include "pfdm/model/model.h"
#include "pfdm/util/point_data.h"

namespace pfdm {

struct SequenceStart {
  Model model;  // Frame 0's starting model; a solid for both walls' contours.
  FramesPerId frames_per_id;
  bool has_tags = false;  // Whether frame 0 has tracked tags.
  WallDecision wall;
  std::string axis_source;  // StartAxis::source.
};

// Throws InputError naming the source and frame when there are no frames,
// or a frame has fewer than options.min_points points or points that do
// not span space, or ids that do not follow the points of the frame before
// (CheckIdsFollowPoints).
SequenceStart StartSequence(const PointSequence& sequence,
                            const ModelConfig& config,
                            const FitOptions& options);

}  // namespace pfdm

#endif  // PFDM_FIT_STAGES_START_H_
