// The dynamics (damped and integrator) against the direct solve on the
// paper's fits of a phantom; the solvers' own tests use toy problems
// (solver_test.cc, damped_test.cc, integrator_test.cc).
#include <cmath>
#include <cstdio>
#include <string>

#include "gtest/gtest.h"
#include "pfdm/fit/stages/fitter.h"
#include "pfdm/phantom/phantom.h"
#include "pfdm/solvers/solver.h"

namespace pfdm {
namespace {

// The phantom's truth on the 9 knots of the model fitted to it.
Phantom MakeNineKnotPhantom(int num_points, int num_frames) {
  PhantomOptions options;
  options.num_points = num_points;
  options.num_frames = num_frames;
  options.num_knots = 9;
  return MakePhantom(options);
}

// The paper's dynamic fit, by forward Euler and by RKC with the model
// damping (the default), and the direct least-squares solve of the same
// residuals end at the same model.
// Tolerances: 0.01 mm and 0.02 degree, a fiftieth and a twenty-fifth of the
// fit's own accuracy against the truth (2 % of the radii, 0.5 degree),
// against the largest differences measured, 3e-4 mm and 1.4e-3 degree (the
// damped solve at rest, frame 1); b1 and b3 (unitless, measured 6.5e-4)
// are nearly unobservable where the bending amplitude is near zero, as
// here.  With the model damping every mode decays at a rate near 1: each
// frame rests in tens of steps (forward Euler with Jacobi damping, the
// paper's variant, needs ~1e4 per e-fold and is not run here).
TEST(DynamicsTest, EverySolverReachesTheSameFixedPoint) {
  const Phantom phantom = MakeNineKnotPhantom(400, 3);
  const ModelConfig config = ModelConfig::Paper(9);
  struct Run {
    const char* name;
    SolverKind kind;
    IntegratorKind integrator;
    SequenceFit fit;
  };
  Run runs[] = {{"direct", SolverKind::kDirect, IntegratorKind::kRkc, {}},
                {"damped", SolverKind::kDamped, IntegratorKind::kRkc, {}},
                {"euler", SolverKind::kIntegrator, IntegratorKind::kEuler, {}},
                {"rkc", SolverKind::kIntegrator, IntegratorKind::kRkc, {}}};
  for (Run& run : runs) {
    FitOptions options;
    options.solver.kind = run.kind;
    options.solver.integrator = run.integrator;
    run.fit = FitSequence(phantom.points, config, options);
  }
  const KnotGrid grid = config.Grid();
  const SequenceFit& direct_fit = runs[0].fit;
  for (const Run& run : runs) {
    if (run.kind == SolverKind::kDirect) continue;
    for (int t = 0; t < 3; ++t) {
      SCOPED_TRACE(std::string(run.name) + " frame " + std::to_string(t));
      EXPECT_EQ(run.fit.frames[t].termination, "REST");
      EXPECT_NEAR(run.fit.frames[t].rms_mm / direct_fit.frames[t].rms_mm, 1.0,
                  1e-3);
      const Model direct = direct_fit.ModelAt(t), other = run.fit.ModelAt(t);
      const double a0 = direct.state.globals[kA0];
      EXPECT_NEAR(other.state.globals[kA0], a0, 0.01);
      for (int k = 0; k < grid.num_knots(); ++k) {
        const double u = grid.KnotU(k);
        for (int f : {kA1, kA2, kA3}) {
          EXPECT_NEAR(a0 * other.FunctionAt(f, u), a0 * direct.FunctionAt(f, u),
                      0.01)
              << FunctionName(f) << " knot " << k;
        }
        for (int f : {kE1o, kE2o, kB0, kB2, kB1, kB3}) {
          EXPECT_NEAR(other.FunctionAt(f, u), direct.FunctionAt(f, u), 0.01)
              << FunctionName(f) << " knot " << k;
        }
        EXPECT_NEAR(other.FunctionAt(kTau, u), direct.FunctionAt(kTau, u),
                    0.01 * M_PI / 180)
            << "knot " << k;
      }
    }
  }
  for (int t = 0; t < 3; ++t) {
    SCOPED_TRACE("frame " + std::to_string(t));
    std::printf("frame %d evaluations: euler %d, rkc %d\n", t,
                runs[2].fit.frames[t].jacobian_evaluations,
                runs[3].fit.frames[t].jacobian_evaluations);
    EXPECT_LT(runs[2].fit.frames[t].jacobian_evaluations, 50);
    EXPECT_LT(runs[3].fit.frames[t].jacobian_evaluations, 500);
  }
}

// The fitter maps its parameter groups onto the free tangent coordinates of
// every block: a wrong count would make the solve unusable, and a twist
// damped 3 times harder must change the path (pseudo-time to rest) but
// not where the model rests (a large scale would only slow the slowest
// mode past max_steps).
TEST(DynamicsTest, GroupDampingChangesThePathNotTheFixedPoint) {
  const Phantom phantom = MakeNineKnotPhantom(200, 2);
  const ModelConfig config = ModelConfig::Paper(9);
  FitOptions options;
  options.solver.kind = SolverKind::kIntegrator;
  const SequenceFit plain = FitSequence(phantom.points, config, options);
  options.damping_groups = DampingGroupsFromText("twist=3,pose=3");
  const SequenceFit slow = FitSequence(phantom.points, config, options);
  for (int t = 0; t < 2; ++t) {
    SCOPED_TRACE("frame " + std::to_string(t));
    EXPECT_EQ(slow.frames[t].termination, "REST");
    EXPECT_NE(slow.frames[t].trace.back().pseudo_time,
              plain.frames[t].trace.back().pseudo_time);
    EXPECT_NEAR(slow.frames[t].rms_mm / plain.frames[t].rms_mm, 1.0, 1e-3);
    const Model a = plain.ModelAt(t), b = slow.ModelAt(t);
    for (int k = 0; k < config.num_knots; ++k) {
      const double u = config.Grid().KnotU(k);
      EXPECT_NEAR(b.FunctionAt(kTau, u), a.FunctionAt(kTau, u),
                  0.01 * M_PI / 180);
      EXPECT_NEAR(b.state.globals[kA0] * b.FunctionAt(kA1, u),
                  a.state.globals[kA0] * a.FunctionAt(kA1, u), 0.01);
    }
  }
}

}  // namespace
}  // namespace pfdm
