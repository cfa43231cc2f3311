// The robust loss of the data terms (--loss, --loss_scale): the Ceres loss
// the problems take, the weight it gives each point, and the scale `auto`
// measures from residuals.
//
// A loss rho(s) acts on s = |r|^2, r a point's residual (its 3-vector, or
// its distance along a normal), s in mm^2 and the scale a in mm:
//   huber   rho(s) = s for s <= a^2, 2 a sqrt(s) - a^2 beyond;
//   cauchy  rho(s) = a^2 log(1 + s / a^2).
// At a solution of sum rho(|r_i|^2) the point weighs rho'(|r_i|^2) against
// least squares (its weight in the normal equations, which iteratively
// reweighted least squares solves for): 1 within the scale (huber), and
// a / |r| (huber) or 1 / (1 + |r|^2 / a^2) (cauchy) beyond.
#ifndef PFDM_FIT_RESIDUALS_ROBUST_LOSS_H_
#define PFDM_FIT_RESIDUALS_ROBUST_LOSS_H_

#include <string>
#include <vector>

#include "Eigen/Core"
#include "ceres/loss_function.h"

namespace pfdm {

// Throws InputError naming --loss unless `name` is none, huber or cauchy.
void CheckLossName(const std::string& name);

// The loss at scale_mm (> 0), owned by the caller (or the ceres::Problem it
// goes to); nullptr for "none".  Throws as CheckLossName.
ceres::LossFunction* MakeLoss(const std::string& name, double scale_mm);

// rho'(|r|^2) of each residual: the weight the loss gives the point, in
// (0, 1]; all 1 for "none".
std::vector<double> LossWeights(const std::string& name, double scale_mm,
                                const std::vector<Eigen::Vector3d>& residuals);

// The scale --loss_scale auto takes from the point distances |r_i| of a fit
// without a loss: 1.4826 times their median, the median absolute deviation
// about 0 (residuals of a fit centre on 0), which is sigma for distances
// along a normal with Gaussian noise of sigma (on frame 0 every point's is,
// its closest point taken), whatever up to half of the points do.  At
// least kMinLossScaleMm, so that noise-free data do not make every
// residual the model cannot take an outlier.  kMinLossScaleMm for none.
constexpr double kMinLossScaleMm = 0.05;
double RobustScaleMm(std::vector<double> distances);

// The scale a loss takes for residuals of spread sigma, over sigma: the
// constants that give 95 % of least squares' efficiency on Gaussian noise
// (Holland & Welsch 1977), huber 1.345 and cauchy 2.385; 1 for none.
double LossTuning(const std::string& name);

// Steps that choose points rather than weigh them (the base rim's height,
// the ranks of tags across a solid's wall) leave out, with a loss, the
// points farther than this from where the model can take them: three
// sigmas of the noise, sigma the loss scale over its tuning, which keeps
// all but 0.3 % of Gaussian noise along a normal.  0 for none.
double OutlierBandMm(const std::string& name, double scale_mm);

}  // namespace pfdm

#endif  // PFDM_FIT_RESIDUALS_ROBUST_LOSS_H_
