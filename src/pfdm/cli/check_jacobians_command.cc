// pfdm check-jacobians: analytic and autodiff Jacobians against central
// differences at ordinary and singular model states.
#include <cstdio>
#include <sstream>

#include "pfdm/cli/commands.h"
#include "pfdm/fit/residuals/jacobian_check.h"
#include "pfdm/util/error.h"

DEFINE_double(tolerance, 1e-6,
              "check-jacobians: largest relative error allowed, 0 to below 1");

namespace pfdm {

int RunCheckJacobians() {
  // NaN once failed every comparison and printed nothing on stderr; a
  // relative error of 1 or more is no agreement at all.
  if (!(FLAGS_tolerance >= 0.0 && FLAGS_tolerance < 1.0)) {
    std::ostringstream text;
    text << "--tolerance must be at least 0 and below 1, got "
         << FLAGS_tolerance;
    throw InputError(text.str());
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
