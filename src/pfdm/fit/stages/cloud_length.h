// Where a cloud of points is longest, when it clearly is: a whole
// ventricle's points spread most along its long axis, so an axis across
// that length is no ventricle's.  Frame 0's start (start_axis.h) doubts
// parallel planes whose normal lies across it, and the verdict fails a fit
// whose long axis does (frame_verdict.h, axis_across).
#ifndef PFDM_FIT_STAGES_CLOUD_LENGTH_H_
#define PFDM_FIT_STAGES_CLOUD_LENGTH_H_

#include <vector>

#include "Eigen/Core"

namespace pfdm {

// Largest over the next principal spread (standard deviations) below which
// the cloud counts as squat, no direction clearly its longest: 1.01-1.19 on
// mid-ventricular segments (tags, slices, the cylinder), 1.46-2.0 on whole
// ventricles (the LV phantoms, biv-me's patient 1).
inline constexpr double kSquatRatio = 1.25;

// An axis more than this from an elongated cloud's length lies across it.
// Over 100 seeds of the LV phantom at 100-2,000 points (tags at every
// depth, slices, the lesion; 2,236 frames), right fits' axes lay within
// 13.5 degrees of it, on ../shared/data's real cases within 16, and fits
// started across it (chance "planes" among 100-150 tags) ended 74-90
// degrees off.
inline constexpr double kAcrossDegrees = 45.0;

struct CloudLength {
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();  // Unit, either sign.
  double ratio = 1.0;  // Largest principal spread over the next.
  bool Elongated() const { return ratio >= kSquatRatio; }
  // Angle (0-90 degrees) between `direction` and the axis, either sign.
  double DegreesFrom(const Eigen::Vector3d& direction) const;
  // Whether `direction` lies across an elongated cloud's length.
  bool Across(const Eigen::Vector3d& direction) const;
};

CloudLength LengthOf(const std::vector<Eigen::Vector3d>& points);

}  // namespace pfdm

#endif  // PFDM_FIT_STAGES_CLOUD_LENGTH_H_
