#include "pfdm/fit/residuals/incompressibility_residual.h"

#include <algorithm>
#include <array>

#include "ceres/jet.h"
#include "pfdm/model/model_point.h"
#include "pfdm/model/wall_volume.h"

namespace pfdm {
namespace {

// The residual's grid: one quad per knot span along u, 16 around.  Frame to
// frame the ratio V / V_0 is what matters, and the 16-gon's 2.6 % loss
// cancels in it (wall_volume_test.cc).
constexpr int kUSteps = 1, kVSteps = 16;

// The functions the wall's volume depends on.
constexpr std::array<int, 8> kVolumeFunctions = {kA0,   kA1,   kA2, kA3,
                                                 kEps1, kEps2, kH,  kWallShift};
constexpr int kNumVolume = static_cast<int>(kVolumeFunctions.size());
using SpanJet = ceres::Jet<double, 2 * kNumVolume>;

// The functions at a knot (the globals where not free over the knots), as
// Jets seeded at `first` onward for the volume's functions.
void Seed(FunctionMask free_mask, const double* globals, const double* knot,
          int first, SpanJet* f) {
  for (int n = 0; n < kNumFunctions; ++n) {
    f[n] = SpanJet((free_mask >> n) & 1u ? knot[n] : globals[n]);
  }
  for (int i = 0; i < kNumVolume; ++i) {
    f[kVolumeFunctions[i]].v[first + i] = 1.0;
  }
}

// (1 - t) a + t b, function by function.
void Mix(const SpanJet* a, const SpanJet* b, double t, SpanJet* f) {
  for (int n = 0; n < kNumFunctions; ++n) f[n] = (1.0 - t) * a[n] + t * b[n];
}

}  // namespace

double IncompressibilityVolume(const Model& model, double u_low,
                               double u_high) {
  return ModelWallVolume(model, u_low, u_high, kUSteps, kVSteps);
}

IncompressibilityResidual::IncompressibilityResidual(
    const ModelConfig& config, bool unit_exponents, double u_low, double u_high,
    double sqrt_weight, double reference_volume, double thickness_mm)
    : config_(config),
      unit_exponents_(unit_exponents),
      u_low_(u_low),
      u_high_(u_high),
      scale_(sqrt_weight * thickness_mm / reference_volume),
      offset_(sqrt_weight * thickness_mm) {
  set_num_residuals(1);
  for (int b = 0; b <= config.num_knots; ++b) {
    mutable_parameter_block_sizes()->push_back(kNumFunctions);
  }
}

bool IncompressibilityResidual::Evaluate(double const* const* parameters,
                                         double* residuals,
                                         double** jacobians) const {
  const KnotGrid& grid = config_.Grid();
  const FunctionMask free_mask = config_.FreeMask();
  const double* globals = parameters[0];
  if (jacobians != nullptr) {
    for (int b = 0; b <= config_.num_knots; ++b) {
      if (jacobians[b]) std::fill_n(jacobians[b], kNumFunctions, 0.0);
    }
  }
  double volume = 0.0;
  SpanJet knot0[kNumFunctions], knot1[kNumFunctions];
  SpanJet low[kNumFunctions], high[kNumFunctions];
  for (int k = 0; k + 1 < config_.num_knots; ++k) {
    const double u0 = grid.KnotU(k), u1 = grid.KnotU(k + 1);
    const double u_low = std::max(u0, u_low_), u_high = std::min(u1, u_high_);
    if (u_low >= u_high) continue;
    Seed(free_mask, globals, parameters[1 + k], 0, knot0);
    Seed(free_mask, globals, parameters[2 + k], kNumVolume, knot1);
    Mix(knot0, knot1, (u_low - u0) / (u1 - u0), low);
    Mix(knot0, knot1, (u_high - u0) / (u1 - u0), high);
    const SpanJet span =
        WallVolume(low, high, u_low, u_high, unit_exponents_, kUSteps, kVSteps);
    volume += span.a;
    if (jacobians == nullptr) continue;
    for (int i = 0; i < kNumVolume; ++i) {
      const int n = kVolumeFunctions[i];
      // d V / d knot k's and knot k + 1's value of function n.
      const double d_knot0 = scale_ * span.v[i];
      const double d_knot1 = scale_ * span.v[kNumVolume + i];
      if ((free_mask >> n) & 1u) {
        if (jacobians[1 + k]) jacobians[1 + k][n] += d_knot0;
        if (jacobians[2 + k]) jacobians[2 + k][n] += d_knot1;
      } else if (jacobians[0]) {
        jacobians[0][n] += d_knot0 + d_knot1;
      }
    }
  }
  residuals[0] = scale_ * volume - offset_;
  return true;
}

}  // namespace pfdm
