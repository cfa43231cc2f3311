// The LV phantom's 150 tags through the wall, seed 1011 (2 frames, noise
// 0.5 mm): chance clumps of them pass FindParallelPlanes as 7 "parallel
// planes" whose normal lies 87 degrees across the LV.  A start that took
// that normal as the axis fitted frame 0 93 degrees off, at an RMS that
// looked normal (start_axis_test.cc, frame_verdict_test.cc).
#ifndef PFDM_TESTING_FALSE_PLANES_PHANTOM_H_
#define PFDM_TESTING_FALSE_PLANES_PHANTOM_H_

#include "pfdm/phantom/lv_phantom.h"

namespace pfdm {

inline LvPhantom FalsePlanesPhantom() {
  LvPhantomOptions options;
  options.num_frames = 2;
  options.num_tags = 150;
  options.tags = LvTagLayer::kWall;
  options.seed = 1011;
  return MakeLvPhantom(options);
}

}  // namespace pfdm

#endif  // PFDM_TESTING_FALSE_PLANES_PHANTOM_H_
