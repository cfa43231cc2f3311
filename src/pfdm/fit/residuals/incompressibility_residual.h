// The myocardium keeps its volume: a soft constraint on a solid's wall
// volume against frame 0's (--incompressible, issue 32).
#ifndef PFDM_FIT_RESIDUALS_INCOMPRESSIBILITY_RESIDUAL_H_
#define PFDM_FIT_RESIDUALS_INCOMPRESSIBILITY_RESIDUAL_H_

#include "ceres/cost_function.h"
#include "pfdm/model/model.h"

namespace pfdm {

// The wall's volume between the rings u_low < u_high on the residual's grid
// (WallVolume, one quad per knot span in u, 16 around): what the residual
// compares, frame 0's included.
double IncompressibilityVolume(const Model& model, double u_low, double u_high);

// r = sqrt(w) t (V(q) / V_0 - 1), one residual over the globals and every
// knot (whole blocks, in that order): V the wall's volume between the
// rings u_low and u_high (IncompressibilityVolume; the fit takes frame 0's
// data's, where the data say what the wall does), V_0 frame 0's, t frame 0's
// mean wall thickness (mm), which makes the relative change the thickness that
// would account for it, in millimetres as the data's residuals are.  The bend,
// the twist and the offsets leave V unchanged (wall_volume.h), so only a0..a3,
// the exponents, h and the shift have derivatives: per knot span, forward
// mode over those functions at its two knots.
class IncompressibilityResidual : public ceres::CostFunction {
 public:
  IncompressibilityResidual(const ModelConfig& config, bool unit_exponents,
                            double u_low, double u_high, double sqrt_weight,
                            double reference_volume, double thickness_mm);

  static ceres::CostFunction* Create(const ModelConfig& config,
                                     bool unit_exponents, double u_low,
                                     double u_high, double sqrt_weight,
                                     double reference_volume,
                                     double thickness_mm) {
    return new IncompressibilityResidual(config, unit_exponents, u_low, u_high,
                                         sqrt_weight, reference_volume,
                                         thickness_mm);
  }

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override;

 private:
  ModelConfig config_;
  bool unit_exponents_;
  double u_low_, u_high_;
  double scale_;   // sqrt(w) t / V_0.
  double offset_;  // sqrt(w) t.
};

}  // namespace pfdm

#endif  // PFDM_FIT_RESIDUALS_INCOMPRESSIBILITY_RESIDUAL_H_
