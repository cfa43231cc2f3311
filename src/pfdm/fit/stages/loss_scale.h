// The robust loss across the sequence fit: --loss_scale auto, measured per
// frame, and every point's weight at the end.
//
// The scale is measured on each frame, from its own rounds without the
// loss once they settle (frame 0's after the wall is decided: a solid's
// residuals, not those of one surface through a wall of tags): sigma, the
// residuals' spread (RobustScaleMm), times the loss's tuning constant
// (LossTuning); the rounds then go on with the loss.  Per frame, because
// the residuals the loss sees differ by frame: frame 0's points all take
// closest points, so their distances are along the normal, one frame's
// noise; a tracked frame's tags keep frame 0's material points and carry
// both frames' noise across the surface, with what the model misses of the
// motion.  On the LV phantom (0.5 mm noise) frame 0 measures sigma 0.51 mm
// and the tracked frames 1.33-1.43 mm.  Frame 0's scale in every frame
// weighed most tracked inliers down against the regularizer: on the clean
// phantom it moved a solid's net twist 0.30 degree and its radial
// contraction 0.3 point from the fit without a loss (cauchy), each frame's
// own 0.04 and 0.09.  The median is robust to the outliers: with 5 % of
// them (10 % of a tracked frame's points, frame 0's misplacing their
// material points too) sigma rises by 10 %.
#ifndef PFDM_FIT_STAGES_LOSS_SCALE_H_
#define PFDM_FIT_STAGES_LOSS_SCALE_H_

#include <string>
#include <vector>

#include "Eigen/Core"
#include "pfdm/fit/correspondence/correspondence.h"
#include "pfdm/fit/fit_options.h"
#include "pfdm/fit/stages/sequence_fit.h"
#include "pfdm/model/model.h"

namespace pfdm {

// Whether the fit measures its loss scale: a loss with loss_scale_auto.
bool MeasuresLossScale(const FitOptions& options);

// `options` with the loss off: the rounds before the scale is measured.
FitOptions WithoutLoss(const FitOptions& options);

// `options` with a frame's scale, when it measures them.
FitOptions WithLossScale(const FitOptions& options, double scale_mm);

// The loss's tuning constant times RobustScaleMm of the points' distances
// from their material points on the model (fit/residuals/robust_loss.h).
double MeasureLossScale(const std::string& loss, const Model& model,
                        const std::vector<Eigen::Vector3d>& points,
                        const std::vector<MaterialPoint>& material);

// The band outside a solid's wall beyond which its ranks leave tags out
// (GlobalRounds::set_rank_band_mm): OutlierBandMm of frame 0's scale in
// every frame.  Frame 0's, because a tag's depth is read along the normal,
// where every frame has the noise of frame 0's distances, not a tracked
// frame's residuals, which are mostly across it: with each frame's own
// scale (a band of 4.4 mm on the LV phantom) the outliers kept their ranks
// and the end-systolic cavity came out 2 % small (42.5 ml against 43.4
// without outliers), with frame 0's (1.25 mm) 1.4 % (0.6 ml).
double RankBandMm(const std::string& loss, double reference_scale_mm);

// With a loss, every frame's points' weights at their final residuals and
// the frame's scale (FrameFit::loss_weights); nothing without one.
void WeighPoints(const std::string& loss, SequenceFit* result);

}  // namespace pfdm

#endif  // PFDM_FIT_STAGES_LOSS_SCALE_H_
