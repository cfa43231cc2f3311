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
// Through the wall, with held depths, M has two parts: the tags' (u, v)
// moved along the surface, and their depths w.  A held depth is measured
// against frame 0's fitted model, so its error is frame 0's residual along
// the normal, eps - J dg: the tag's own noise (FrameCovariance::
// depth_noise counts it in the tracked frame's covariance as independent
// of everything, e A^+ D_n A^+) less the part frame 0's model took up (the
// depth part of M, M_w).  These two are one error, not two: with
// b = dy/dt B the number's response to the depths' errors, the variance
// frame 0's noise puts through the depths is |b (I - H)|^2 = |b|^2 -
// |b H|^2 (H frame 0's hat matrix; frame 0's own share dy/d0 dg is
// orthogonal to it), so number_uncertainty.h takes Var(dy/dt M_w d0) off
// the variance where the two were added (at most the depth noise's own
// share).  The tags' (u, v) follow frame 0's tangential noise, which
// frame 0's fit along the normals does not see: that part of M adds.  On
// the LV phantom (400 tags through the wall, 40 draws) noise in frame 0
// alone moved ESV by sd 0.55 ml where the added shares read 0.99.
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

// M's parts (rows: frame t's covariance entries, columns: frame 0's).
struct TrackedResponse {
  Eigen::MatrixXd along_surface;  // Through the tags' (u, v).
  Eigen::MatrixXd through_wall;   // Through held depths; else empty.
  bool Empty() const { return along_surface.size() == 0; }
  Eigen::MatrixXd Total() const {
    return through_wall.size() == 0 ? along_surface
                                    : along_surface + through_wall;
  }
};

// M for frame t of `fit`, or none (Empty) where frame t's material points
// are not frame 0's alone (frame 0 itself, contours, tags beside contours),
// where end-diastole is not frame 0, or without both covariances.
TrackedResponse MeasureTrackedResponse(const SequenceFit& fit, size_t t);

}  // namespace pfdm

#endif  // PFDM_REPORT_TRACKED_RESPONSE_H_
