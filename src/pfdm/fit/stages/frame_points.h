// One frame's data points as the stages of its fit see them: where each
// is, which wall it names, and whether it keeps a material point from an
// earlier frame.
#ifndef PFDM_FIT_STAGES_FRAME_POINTS_H_
#define PFDM_FIT_STAGES_FRAME_POINTS_H_

#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "Eigen/Core"
#include "pfdm/fit/correspondence/correspondence.h"
#include "pfdm/fit/problem/gauge.h"
#include "pfdm/util/point_data.h"

namespace pfdm {

// In how many frames each id appears: an id seen in more than one is a
// tracked tag, one seen once an untracked surface sample (a contour point).
using FramesPerId = std::unordered_map<std::int64_t, int>;

// Each tracked id's material point, found on the frame that first saw it.
using TrackedMaterial = std::unordered_map<std::int64_t, MaterialPoint>;

struct FramePoints {
  int index = 0;  // The frame's number in its input.
  FrameKind kind = FrameKind::kReference;
  std::vector<Eigen::Vector3d> positions;
  // How a point is sought in a solid: its contour's wall, -1 endocardium or
  // +1 epicardium; 0 for everything else (tags get their depth from
  // QuantileDepths).
  std::vector<double> layer_w;
  // Whether the point's id appears in other frames too (a tag).
  std::vector<bool> is_tag;
  // Points with no material point from an earlier frame, whose closest
  // material points the rounds search; the rest keep theirs.
  std::vector<size_t> untracked;
  std::vector<size_t> tracked;
  // Frame 0's tags, whose depth in a solid comes from their spread.
  std::vector<bool> assign_depth;
  // The untracked points, which slide along the surface (SlidingNormals).
  std::vector<bool> sliding;
};

FramesPerId CountFramesPerId(const PointSequence& sequence);

// The frame's points; *material gets each tracked point's material point
// and room for the others'.
FramePoints MakeFramePoints(const Frame& frame, bool reference,
                            const FramesPerId& frames_per_id,
                            const TrackedMaterial& tracked_material,
                            std::vector<MaterialPoint>* material);

// Whether a tracked frame has contours beside its tags: points labelled on
// a wall, or over kMixedShare of its points seen in this frame alone (a
// tracker loses a few tags to one frame; a contour's points are all seen
// once).
constexpr double kMixedShare = 0.1;
bool HasContoursBesideTags(const FramePoints& points);

std::vector<Eigen::Vector3d> Positions(const Frame& frame);

// The principal standard deviations of the frame's points about their
// centroid, ascending, mm.
Eigen::Vector3d PrincipalSpreads(const Frame& frame);

}  // namespace pfdm

#endif  // PFDM_FIT_STAGES_FRAME_POINTS_H_
