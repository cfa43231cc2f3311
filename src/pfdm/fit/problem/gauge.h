// Which entries each frame holds, and why (README "Gauge conventions"): the
// model has redundant directions, and every fit fixes them the same way so
// that the reported parameters are unique.
#ifndef PFDM_FIT_PROBLEM_GAUGE_H_
#define PFDM_FIT_PROBLEM_GAUGE_H_

#include <vector>

#include "Eigen/Core"
#include "pfdm/fit/fit_options.h"
#include "pfdm/model/model.h"

namespace pfdm {

// Frame 0 is the reference configuration; a later frame is tracked when
// some of its points keep a material point from an earlier frame, and
// untracked (contours) otherwise.
enum class FrameKind { kReference, kTracked, kUntracked };

// The block index of the globals among the knots (0..K-1).
constexpr int kGlobalsBlock = -1;

// Weight of the axis gauge (AxisGaugeResidual) per sqrt(point): enough to
// hold the ring centres' mean and trend within 1e-3 mm, no more, since a
// stiffer penalty slows the dynamics solvers (the forward Euler step shrinks
// with the largest eigenvalue) for nothing.
constexpr double kGaugeWeight = 1e1;

// Entries of a parameter block (the globals, or knot `block`) that the gauge
// and the configuration hold.  Frame 0 is the reference configuration: no
// twist or bending by definition; a3 is held (at the value initialization
// gave, with a0 spanning the data: see SpanAxialExtent), since a surface
// seen only through distances fixes the meridian's shape but not how u runs
// along it.  In every frame the axis is the least-squares line of the ring
// centres (AxisGaugeResidual), which leaves the pose to carry translation
// and tilt; offsets constant in u are simply held at zero.  Later frames fit
// the pose too, but not its spin about the long axis (SpinGaugeResidual),
// so tau is rotation about the axis relative to frame 0.  A later frame
// with no tracked point holds tau: without material points a turn of a
// ring about the axis is invisible, and the fit would only drift.
std::vector<int> HeldEntries(const ModelConfig& config, FrameKind kind,
                             int block);

// Length (mm per radian) that converts the spin gauge's angle to motion at
// the model's radius: a0 times the mean of a1 and a2 at the equator.
double SpinGaugeLength(const Model& model);

// The apex pole's axis point in the model frame, in units of a0: a3(u_min)
// sin(u_min) along the axis (frame 0 neither bends nor offsets it there).
double ApexExtent(const Model& model);
// Its height along the model's long axis from the centre, a0 ApexExtent,
// as TopHeight's.
double ApexHeight(const Model& model);

// Frame 0's length along its axis from the apex pole to the base ring,
// a0 (a3(u_max) sin(u_max) - ApexExtent): what SpanAxialExtent sets.
double AxialLength(const Model& model);

// Height along the model axis of the highest data point that is not an
// outlier: with a robust loss, points farther than OutlierBandMm
// (fit/residuals/robust_loss.h) from the surface (a solid's wall) do not
// count, nor any with fewer than two others within that band below it
// (gauge.cc, kRimSupport).  NaN when none counts.
double TopHeight(const std::vector<Eigen::Vector3d>& points,
                 const FitOptions& options, const Model& model);

// The scale gauge of frame 0: sets a0 so that the model, a3 held, reaches
// from its fitted apex to the highest data point along its axis (the base
// rim) raised by `lift` (a solid's, frame_fit's RimLift), keeping the apex,
// the radii in mm and the orientation where they are.
void SpanAxialExtent(const std::vector<Eigen::Vector3d>& points,
                     const FitOptions& options, Model* model,
                     double lift = 0.0);

}  // namespace pfdm

#endif  // PFDM_FIT_PROBLEM_GAUGE_H_
