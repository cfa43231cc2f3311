// pfdm check-jacobians: analytic and autodiff Jacobians against central
// differences at ordinary and singular model states.
#include <cmath>
#include <cstdio>

#include "pfdm/cli/commands.h"
#include "pfdm/fit/residuals/jacobian_check.h"
#include "pfdm/util/error.h"

DEFINE_double(tolerance, 1e-6,
              "check-jacobians: largest relative error allowed");

namespace pfdm {

int RunCheckJacobians() {
  // NaN once failed every comparison and printed nothing on stderr.
  if (!(FLAGS_tolerance >= 0.0) || !std::isfinite(FLAGS_tolerance)) {
    throw InputError("--tolerance must be a number >= 0, got " +
                     std::to_string(FLAGS_tolerance));
  }
  const std::vector<JacobianCheck> checks = CheckJacobians();
  std::printf("%-26s %-8s %-9s %10s %10s %10s %10s %10s\n", "state", "residual",
              "jacobian", "center", "quaternion", "globals", "knot0", "knot1");
  double worst = 0.0;
  for (const JacobianCheck& check : checks) {
    std::printf("%-26s %-8s %-9s", check.state.c_str(), check.residual.c_str(),
                JacobianName(check.jacobian));
    for (double error : check.block_error) std::printf(" %10.2e", error);
    std::printf("%s\n", check.finite ? "" : "  NOT FINITE");
    worst = std::max(worst, check.worst);
  }
  const bool ok = worst <= FLAGS_tolerance;
  std::printf("worst relative error %.2e: %s (tolerance %.1e)\n", worst,
              ok ? "ok" : "FAILED", FLAGS_tolerance);
  return ok ? 0 : 1;
}

}  // namespace pfdm
