// How a tracked frame's fit follows an error of frame 0's.
//
// A tracked frame's tags keep the material points frame 0's fit gave them.
// Were frame 0's model off by d0 (its covariance's coordinates), the tags'
// material points would be off too: tag i's moves to where the moved model
// meets the tag, dm_i = -L_i^+ dx_i, L_i = dx_0/dm at m_i and dx_i the
// model's move there (along the surface alone for a surface, or for depths
// ranked anew each frame; through the wall too for a solid's held depths).
// The tracked frame's fit, which puts each m_i where its tag is, then takes
// up its residuals' change c_i = K_i dm_i (K_i = dx_t/dm):
//
//   dt = -(J'J)^+ J_d' W c = M d0,
//
// (J'J)^+ the frame's own (FrameCovariance::unit_covariance), J_d its data's
// rows at the tags, W the robust loss's weights.  So the two frames' errors
// are correlated, and a number of both (radial contraction, thickening,
// strain: the frame against end-diastole) varies with frame 0's parameters
// as dy/d0 + dy/dt M, not by two independent shares
// (number_uncertainty.h).  On the LV phantom (400 tags, 0.5 mm noise, 12
// draws) the radial contraction's error from frame 0's fit and from end-
// systole's were correlated -0.49 on mid-wall tags and -0.63 through the
// wall, where the thickening's were -0.51: the independent shares' sd was
// 1.29, 1.37 and 1.26 times the error's.
//
// Frame 0's pose moves every material point alike or turns them about the
// axis, which the tracked frames' gauges hold to frame 0's (gauge.h;
// SpunWith turns them with it): its columns are 0.
#ifndef PFDM_REPORT_TRACKED_RESPONSE_H_
#define PFDM_REPORT_TRACKED_RESPONSE_H_

#include <cstddef>

#include "Eigen/Core"
#include "pfdm/fit/stages/sequence_fit.h"

namespace pfdm {

// The tags M's columns are measured on: every one up to this many, else
// evenly spread ones, each weighing for its share.
inline constexpr size_t kMaxResponseTags = 1000;

// M for frame t of `fit` (rows: frame t's covariance entries, columns:
// frame 0's), or an empty matrix where frame t's material points are not
// frame 0's alone (frame 0 itself, contours, tags beside contours), where
// end-diastole is not frame 0, or without both covariances.
Eigen::MatrixXd TrackedResponse(const SequenceFit& fit, size_t t);

}  // namespace pfdm

#endif  // PFDM_REPORT_TRACKED_RESPONSE_H_
