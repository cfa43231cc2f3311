#include "pfdm/model/superellipsoid.h"

#include <cmath>

#include "gtest/gtest.h"
#include "pfdm/model/model.h"

namespace pfdm {
namespace {

FunctionValues Shape(double a1, double a2, double a3, double e1, double e2) {
  FunctionValues f = DefaultFunctionValues();
  f[kA0] = 10.0;
  f[kA1] = a1;
  f[kA2] = a2;
  f[kA3] = a3;
  f[kEps1] = e1;
  f[kEps2] = e2;
  return f;
}

// Barr's inside-outside function of the classic superellipsoid: 1 on it.
double InsideOutside(const Eigen::Vector3d& p, const FunctionValues& f) {
  const double x = std::abs(p.x() / (f[kA0] * f[kA1]));
  const double y = std::abs(p.y() / (f[kA0] * f[kA2]));
  const double z = std::abs(p.z() / (f[kA0] * f[kA3]));
  return std::pow(std::pow(x, 2.0 / f[kEps2]) + std::pow(y, 2.0 / f[kEps2]),
                  f[kEps2] / f[kEps1]) +
         std::pow(z, 2.0 / f[kEps1]);
}

TEST(SuperellipsoidTest, ConstantFunctionsGiveTheClassicSuperellipsoid) {
  for (const FunctionValues& f :
       {Shape(0.5, 0.3, 0.9, 1.0, 1.0), Shape(0.4, 0.6, 0.8, 0.5, 1.5),
        Shape(0.7, 0.2, 0.3, 1.8, 0.4)}) {
    for (double u = -1.4; u < 1.5; u += 0.35) {
      for (double v = -3.0; v < 3.1; v += 0.55) {
        const Eigen::Vector3d p =
            Superellipsoid(f.data(), MakeAngles(u, v), false);
        EXPECT_NEAR(InsideOutside(p, f), 1.0, 1e-7) << u << " " << v;
      }
    }
  }
}

TEST(SuperellipsoidTest, UnitExponentShortcutMatchesThePowers) {
  const FunctionValues f = Shape(0.5, 0.3, 0.9, 1.0, 1.0);
  for (double u : {-M_PI / 2, -0.3, 0.0, 0.7}) {
    for (double v : {-M_PI, -1.0, 0.0, M_PI / 2}) {
      const Angles<double> angles = MakeAngles(u, v);
      EXPECT_TRUE(
          Superellipsoid(f.data(), angles, true)
              .isApprox(Superellipsoid(f.data(), angles, false), 1e-12));
    }
  }
}

TEST(SuperellipsoidTest, PolesAndAxesLieWhereExpected) {
  const FunctionValues f = Shape(0.5, 0.3, 0.9, 0.7, 1.3);
  const Eigen::Vector3d apex =
      Superellipsoid(f.data(), MakeAngles(-M_PI / 2, 0.4), false);
  EXPECT_NEAR(apex.z(), -9.0, 1e-9);
  EXPECT_NEAR(apex.head<2>().norm(), 0.0, 1e-6);
  const Eigen::Vector3d on_y =
      Superellipsoid(f.data(), MakeAngles(0.0, M_PI / 2), false);
  EXPECT_NEAR(on_y.y(), 3.0, 1e-9);
  EXPECT_NEAR(on_y.x(), 0.0, 1e-6);
}

}  // namespace
}  // namespace pfdm
