// What a solid's segments cannot show through the wall.  Fitted with
// --local_transmural off, the local field moves every layer alike, so a
// segment's thickness changes as its ring's does; and tags through the
// wall ranked in every frame (--tag_depths ranked) take their depths from
// their rank within their ring, which takes a segment's own motion into
// its tags' depths.  On the LV phantom with a hypokinetic segment (400
// points, 100 noise draws; LvIntervalCalibrationTest.LesionWall*,
// docs/uncertainty_calibration.md): through the wall, ranked, its radial
// contraction read 3.5 points and its thickening 24 above its truth, as
// its neighbours; with its tags' depths held, or on both walls' contours,
// its motion showed but its thickening did not.  With the field through
// the wall (--local_transmural on) a third of the wall's thickening (the
// layers' table) is the field's bend between the walls, which the tags'
// depths and noise move: on lv_layer_strain_test's phantoms the thirds
// read 20-47 points off their truth with 0.5 mm of noise, 24 without.
#ifndef PFDM_REPORT_REGIONAL_LIMIT_H_
#define PFDM_REPORT_REGIONAL_LIMIT_H_

#include <string>

#include "pfdm/fit/stages/sequence_fit.h"

namespace pfdm {

enum class RegionalLimit {
  kNone,  // A surface.
  // A solid of contours, or of tags at held depths: each segment's
  // thickening its ring's.
  kThickening,
  kRing,  // A solid of tags ranked in every frame: each segment its ring.
  // A solid with the field through the wall: its thirds' thickening the
  // field's bend.
  kThirds,
};

RegionalLimit RegionalLimitOf(const SequenceFit& fit);

// The sentence the report and fit.json give; "" for kNone.
std::string RegionalLimitNote(RegionalLimit limit);

}  // namespace pfdm

#endif  // PFDM_REPORT_REGIONAL_LIMIT_H_
