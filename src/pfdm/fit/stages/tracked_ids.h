// Whether the ids of tracked points follow the same points from frame to
// frame.  Ids shuffled in one frame once gave a volume of 3.9 ml instead of
// 180 at an RMS of 30 mm, exit 0 (issue 29): each tag was tied to another
// tag's material point.
#ifndef PFDM_FIT_STAGES_TRACKED_IDS_H_
#define PFDM_FIT_STAGES_TRACKED_IDS_H_

#include <functional>

#include "pfdm/util/point_data.h"

namespace pfdm {

// How a frame's points moved from the frame before, on a sample of the
// points the two share by id (at most kIdSample of them).
struct IdMotion {
  int shared = 0;           // Points of the sample, ids in both frames.
  double by_id_mm = 0.0;    // Median distance between same-id points.
  double nearest_mm = 0.0;  // Median distance to the nearest point before.
  double radius_mm = 0.0;   // RMS distance of before's points from their
                            // centroid: the data's size.
};

inline constexpr int kIdSample = 4096;

// With `nearest_if_needed`, nearest_mm is measured only where the rest of
// the motion MayBeScrambled (it takes a k-d tree of the frame before, and
// IdsScrambled needs it only there), else left 0.
IdMotion MeasureIdMotion(const Frame& before, const Frame& after,
                         bool nearest_if_needed = false);

// Whether the ids of `after` are not those of the points of `before`: the
// points of the same id lie apart by half the data's radius (MayBeScrambled)
// and by 4 times what the clouds' nearest neighbours show (a permutation of
// the ids leaves the latter as it is).  A heart moves its tags by a fraction
// of that between frames (frame to frame, measured: see
// tracked_ids_test.cc); at least 10 shared points are needed to say.
bool MayBeScrambled(const IdMotion& motion);
bool IdsScrambled(const IdMotion& motion);

// Throws InputError "SOURCE: frame T: the ids do not follow the points of
// frame S: ..." for the first frame whose ids are scrambled against the
// frame before it.  Calls between (if any) after each frame: a caller's
// interrupt check (SolverOptions::interrupt).
void CheckIdsFollowPoints(const PointSequence& sequence,
                          const std::function<void()>& between = {});

}  // namespace pfdm

#endif  // PFDM_FIT_STAGES_TRACKED_IDS_H_
