// The LV phantom's mid-ventricular segment as both walls' contours: three
// short-axis slices at 30 to 72 % of its length, no apex, 400 points of
// frame 0 (noise 0.5 mm).  Its solid's closest-point rounds crept toward the
// base and once collapsed (global_rounds_test.cc, frame_fit_test.cc); one
// surface through both walls misfits it (frame_verdict_test.cc).
#ifndef PFDM_TESTING_SEGMENT_CONTOURS_PHANTOM_H_
#define PFDM_TESTING_SEGMENT_CONTOURS_PHANTOM_H_

#include "pfdm/phantom/lv_phantom.h"

namespace pfdm {

inline PointSequence SegmentWallContours() {
  LvPhantomOptions options;
  options.region = LvRegion::kMidventricular;
  options.sampling = LvSampling::kSaxSlices;
  options.tags = LvTagLayer::kWall;
  options.num_tags = 400;
  options.num_frames = 1;
  return MakeLvPhantom(options).points;
}

}  // namespace pfdm

#endif  // PFDM_TESTING_SEGMENT_CONTOURS_PHANTOM_H_
