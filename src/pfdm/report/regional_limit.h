// What a solid's segments cannot show through the wall.  Fitted with
// --local_transmural off, the local field moves every layer alike, so a
// segment's thickness changes as its ring's does; and tags through the
// wall take their depths from their rank within their ring, which takes a
// segment's own motion into its tags' depths.  On the LV phantom with a
// hypokinetic segment (400 points, 100 noise draws; LvIntervalCalibration
// Test.LesionWall*, docs/uncertainty_calibration.md): through the wall its
// radial contraction read 3.5 points and its thickening 24 above its
// truth, as its neighbours; on both walls' contours its motion showed but
// its thickening did not.
#ifndef PFDM_REPORT_REGIONAL_LIMIT_H_
#define PFDM_REPORT_REGIONAL_LIMIT_H_

#include <string>

#include "pfdm/fit/stages/sequence_fit.h"

namespace pfdm {

enum class RegionalLimit {
  kNone,        // A surface, or a solid with the field through the wall.
  kThickening,  // A solid of contours: each segment's thickening its ring's.
  kRing,        // A solid of tags: each segment reads as its ring.
};

RegionalLimit RegionalLimitOf(const SequenceFit& fit);

// The sentence the report and fit.json give; "" for kNone.
std::string RegionalLimitNote(RegionalLimit limit);

}  // namespace pfdm

#endif  // PFDM_REPORT_REGIONAL_LIMIT_H_
