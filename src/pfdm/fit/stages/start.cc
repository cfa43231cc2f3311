#include "pfdm/fit/stages/start.h"

#include <string>
#include <utility>

#include "Eigen/Dense"
#include "pfdm/fit/stages/initialization.h"
#include "pfdm/fit/stages/start_axis.h"
#include "pfdm/fit/stages/tracked_ids.h"
#include "pfdm/util/error.h"

namespace pfdm {
namespace {

std::string FrameName(const std::string& source, const Frame& frame) {
  return source + ": frame " + std::to_string(frame.index);
}

void CheckEnoughPoints(const std::string& source, const Frame& frame,
                       int min_points) {
  if (static_cast<int>(frame.points.size()) >= min_points) return;
  throw InputError(FrameName(source, frame) + ": only " +
                   std::to_string(frame.points.size()) + " points, at least " +
                   std::to_string(min_points) + " needed");
}

// A surface is fitted to points that span space; identical, collinear or
// coplanar points once reached Ceres as NaN (a CHECK dump) or "fitted" with
// exit 0.  Spreads are the principal standard deviations, mm.
void CheckSpansSpace(const std::string& source, const Frame& frame) {
  const Eigen::Vector3d spread = PrincipalSpreads(frame);
  const char* what = nullptr;
  if (!(spread[2] > 1e-6)) {
    what = "all at one place";
  } else if (spread[1] < 1e-3 * spread[2]) {
    what = "on a line";
  } else if (spread[0] < 1e-3 * spread[2]) {
    what = "in a plane";
  }
  if (what != nullptr) {
    throw InputError(FrameName(source, frame) + ": the points lie " + what +
                     "; a surface needs points that span space");
  }
}

bool HasTags(const Frame& frame, const FramesPerId& frames_per_id) {
  for (const DataPoint& p : frame.points) {
    if (frames_per_id.at(p.id) > 1) return true;
  }
  return false;
}

}  // namespace

SequenceStart StartSequence(const PointSequence& sequence,
                            const ModelConfig& config,
                            const FitOptions& options) {
  if (sequence.frames.empty()) {
    throw InputError(sequence.source + ": no frames");
  }
  if (options.ed_frame < 0 ||
      options.ed_frame >= static_cast<int>(sequence.frames.size())) {
    throw InputError(sequence.source + ": no frame " +
                     std::to_string(options.ed_frame) + " for end-diastole");
  }
  for (const Frame& frame : sequence.frames) {
    CheckEnoughPoints(sequence.source, frame, options.min_points);
    CheckSpansSpace(sequence.source, frame);
  }
  CheckInterrupt(options.solver);
  CheckIdsFollowPoints(sequence, options.solver.interrupt);
  CheckInterrupt(options.solver);
  const Frame& first = sequence.frames[0];
  StartAxis axis = ChooseStartAxis(first, config, options, sequence.source);
  SequenceStart start{std::move(axis.model), CountFramesPerId(sequence), false,
                      WallDecision(), std::move(axis.source)};
  start.has_tags = HasTags(first, start.frames_per_id);
  start.wall = DecideWallFromContours(first, start.has_tags, options,
                                      sequence.source, &start.model.config);
  return start;
}

}  // namespace pfdm
