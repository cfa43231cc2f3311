#include "pfdm/fit/residuals/jacobian_check.h"

#include <set>

#include "gtest/gtest.h"

namespace pfdm {
namespace {

// ceres::GradientChecker (Ridders' differences) agrees with both the
// analytic and the autodiff Jacobians to near machine precision at every
// state, the poles, axes, eps = 1 and zero bending included, on the
// mid-wall and on the solid's endocardium and epicardium (w = -1, +1), and
// inside the wall where the squeeze acts, with and without the wall's
// functions.
TEST(JacobianCheckTest, BothJacobiansMatchNumericDifferencesEverywhere) {
  const std::vector<JacobianCheck> checks = CheckJacobians();
  std::set<std::string> states;
  for (const JacobianCheck& check : checks) {
    states.insert(check.state);
    EXPECT_TRUE(check.finite) << check.state;
    EXPECT_LT(check.worst, 1e-9) << check.state << " " << check.residual << " "
                                 << JacobianName(check.jacobian);
  }
  for (const char* singular :
       {"apex pole", "v on +x axis", "v on +y axis", "eps = 1",
        "eps = 1 at the pole", "zero bending", "identity pose",
        "endocardium at the apex pole", "epicardium on +x axis",
        "inside the wall, squeezed", "middle layer, no wall functions",
        "inside the wall, no shift or squeeze"}) {
    EXPECT_EQ(states.count(singular), 1u) << singular;
  }
  EXPECT_EQ(checks.size(), states.size() * 4);
}

}  // namespace
}  // namespace pfdm
