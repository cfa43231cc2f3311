// The delta method: each derived number's standard deviation from the
// covariance of the frames' parameters (fit/problem/frame_covariance.h).
//
// A number y = f(x) of a frame's free parameters x (pose, globals, knots)
// with covariance C has var y ~ g' C g, g = df/dx at the fit.  g is taken
// by central differences along each coordinate of x, not by Jets: the
// numbers are measured on sampled rings, segments and closed surfaces
// (material_rings, wall_motion, model_surface) in double, and templating
// all of them for ceres::Jet would double the report's code for a gradient
// that 2n evaluations give.  The step is kStepSd of the coordinate's own
// sd: the scale over which the interval must hold, and far over the
// round-off of the sampled means (docs/uncertainty.md).
//
// A number of frame t is measured against end-diastole's model (ED), so it
// depends on two frames' parameters.  Frame t's covariance is conditional
// on ED's model (frame_covariance.h), and a tracked frame's fit follows
// ED's errors through the material points ED's fit gave its tags (M_t,
// tracked_response.h): var y = g_t' C_t g_t + h' C_ED h, h = g_ED + M_t' g_t
// (M_t's part along the surface), less what ED's noise through held depths
// counted twice (M_t's part through them against the depth noise in C_t),
// and ED's spin about its axis, which every frame shares, turns them all
// (SpunWith).  ED's own numbers (and everything at t = ED) vary both at
// once.  The ejection fraction, (EDV - ESV) / EDV, takes the two volumes'
// rows, summed along ED's parameters (ESV follows them), likewise.
#ifndef PFDM_REPORT_NUMBER_UNCERTAINTY_H_
#define PFDM_REPORT_NUMBER_UNCERTAINTY_H_

#include <functional>
#include <vector>

#include "Eigen/Core"
#include "pfdm/fit/problem/frame_covariance.h"
#include "pfdm/fit/stages/sequence_fit.h"
#include "pfdm/model/base_plane.h"
#include "pfdm/model/model.h"
#include "pfdm/report/fit_analysis.h"
#include "pfdm/report/frame_numbers.h"
#include "pfdm/report/number_sd.h"

namespace pfdm {

// The finite differences' step, in sds of the coordinate varied.
inline constexpr double kStepSd = 0.5;

// `model` moved by `delta` along the covariance's coordinates `entries`
// (the pose's rotation coordinates as one rotation vector applied on the
// left, as ceres::QuaternionManifold's tangent).
Model Nudged(const Model& model, const std::vector<CovarianceEntry>& entries,
             const Eigen::VectorXd& delta);

// d numbers / d x at `model` (rows: numbers, columns: covariance's
// entries), central differences with steps kStepSd sd; a column of an
// entry without variance is 0.
using NumbersOf = std::function<std::vector<double>(const Model&)>;
Eigen::MatrixXd NumberJacobian(const Model& model,
                               const FrameCovariance& covariance,
                               const NumbersOf& numbers);

// NumberJacobian for numbers that are told where each step moved the model
// (MovedRange): FrameMeasurer measures again only there.
using MovedNumbersOf =
    std::function<std::vector<double>(const Model&, const MovedU&)>;
Eigen::MatrixXd NumberJacobian(const Model& model,
                               const FrameCovariance& covariance,
                               const MovedNumbersOf& numbers);
// The same with the steps spread over `threads` threads (util/parallel_for.h),
// each measuring with a MovedNumbersOf of its own from `make` (what it keeps
// between steps is its own); every step is measured as with one thread, so
// the Jacobian is the same to the bit.
using MakeMovedNumbers = std::function<MovedNumbersOf()>;
Eigen::MatrixXd NumberJacobian(const Model& model,
                               const FrameCovariance& covariance,
                               const MakeMovedNumbers& make, int threads);
// Where a step along `entry` moves `model`: a knot's between its
// neighbours, the pose's and the globals' everywhere.
MovedU MovedRange(const Model& model, const CovarianceEntry& entry);

// diag(D C D'): each number's variance.
Eigen::VectorXd Variances(const Eigen::MatrixXd& jacobian,
                          const Eigen::MatrixXd& covariance);

std::vector<double> Flatten(const FrameNumbers& numbers);
// Every frame's sds (or biases) in Flatten's order, frame after frame, then
// the ejection fraction's ratio, EDV and ESV.
std::vector<double> Flatten(const NumberSd& sd);
// numbers' fields set from values, in Flatten's order.
void Unflatten(const double* values, FrameNumbers* numbers);

// `model` (frame t's) turned with ED's spin about its long axis: moved_ed
// is ed turned (and moved) by a step of the delta method, whose turn about
// ed's axis (through its centre) is applied to `model` likewise.  The
// frames are independent but for this: a later frame's tags keep the
// material points ED's fit gave them and its gauge holds ED's spin (gauge.h),
// so a spin of ED, which the data of a near-round LV hardly fix, relabels
// the longitudes of every frame alike and changes no number; taken as
// independent it would read as a turn of every segment (on the LV phantom,
// segment rotation sd 3.8 degrees against a spread of 0.4).
Model SpunWith(const Model& ed, const Model& moved_ed, const Model& model);
// The angle of that turn (0: `model` is returned unchanged).
double EdSpin(const Model& ed, const Model& moved_ed);

// Every number's sd in `analysis` (AnalyzeFit(fit, ...)): computed false
// unless every frame has its covariance (--uncertainty on).
NumberSd PropagateUncertainty(const SequenceFit& fit,
                              const FitAnalysis& analysis);

}  // namespace pfdm

#endif  // PFDM_REPORT_NUMBER_UNCERTAINTY_H_
