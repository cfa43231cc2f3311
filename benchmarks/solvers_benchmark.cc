// Each solver's evaluations and wall time on the same tracked frame, as
// ratios to the direct solve (N = 2k and 20k tags).
#include "benchmark/benchmark.h"
#include "pfdm/fitter.h"
#include "pfdm/phantom.h"

namespace pfdm {
namespace {

struct Run {
  double seconds = 0.0;
  double rms = 0.0;
  int iterations = 0;
  int residual_evaluations = 0;
  int jacobian_evaluations = 0;
};

Run FitFrame(const Phantom& phantom, SolverKind kind) {
  FitOptions options;
  options.solver.kind = kind;
  const SequenceFit fit =
      FitSequence(phantom.points, ModelConfig::Paper(17), options);
  const FrameFit& frame = fit.frames[1];  // Tracked: one solve.
  return {frame.solve_seconds, frame.rms_mm, frame.iterations,
          frame.residual_evaluations, frame.jacobian_evaluations};
}

// Args: points, solver (0 direct, 1 damped, 2 integrator).
void BM_Solver(benchmark::State& state) {
  PhantomOptions phantom_options;
  phantom_options.num_points = static_cast<int>(state.range(0));
  phantom_options.num_frames = 2;
  const Phantom phantom = MakePhantom(phantom_options);
  const Run direct = FitFrame(phantom, SolverKind::kDirect);
  Run run;
  for (auto _ : state) {
    run = FitFrame(phantom, static_cast<SolverKind>(state.range(1)));
  }
  state.counters["iterations"] = run.iterations;
  state.counters["frame_s"] = run.seconds;
  state.counters["rms_mm"] = run.rms;
  state.counters["residual_evals_vs_direct"] =
      static_cast<double>(run.residual_evaluations) /
      std::max(direct.residual_evaluations, 1);
  state.counters["jacobian_evals_vs_direct"] =
      static_cast<double>(run.jacobian_evaluations) /
      std::max(direct.jacobian_evaluations, 1);
  state.counters["time_vs_direct"] = run.seconds / direct.seconds;
  state.counters["rms_vs_direct"] = run.rms / direct.rms;
}

BENCHMARK(BM_Solver)
    ->ArgNames({"points", "solver"})
    ->ArgsProduct({{2000, 20000}, {0, 1, 2}})
    ->Unit(benchmark::kSecond)
    ->Iterations(1);

}  // namespace
}  // namespace pfdm

BENCHMARK_MAIN();
