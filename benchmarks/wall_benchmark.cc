// The solid's cost (issue 15): a systolic frame of the analytic LV phantom
// with tags through a 10 mm wall (N tracked tags, K = 17, local field off),
// fitted as one surface (--wall midwall) and as a solid (--wall solid).
// Three frames: "frame0_ms" is frame 0 with its correspondence rounds,
// "first_tracked_ms" frame 1 (a solid's: its pilot fit, whose tags' noise
// the held depths need, fitter.cc, then its fit), "frame_ms" frame 2, a
// tracked frame as every later one is, "solves" and "iterations" its solves
// (a solid's ranked, --tag_depths ranked: the predictor's step, its tags
// ranked, the solve; held, the default: one) and their steps,
// "per_point_ns" its evaluation time (residuals and Jacobians) per tag and
// iteration.  Each configuration runs three times; read the medians.
#include "benchmark/benchmark.h"
#include "benchmark_util.h"
#include "pfdm/fit/fit_options.h"
#include "pfdm/fit/stages/sequence_fit.h"
#include "pfdm/phantom/lv_phantom.h"

namespace pfdm {
namespace {

// Args: tags, solid (0 one surface, 1 a solid of tags ranked in every
// frame, 2 one of tags at frame 0's held depths).
void BM_WallFitFrame(benchmark::State& state) {
  LvPhantomOptions phantom_options;
  phantom_options.tags = LvTagLayer::kWall;
  FitOptions options;
  options.local.enabled = false;
  options.wall = state.range(1) != 0 ? WallModel::kSolid : WallModel::kMidwall;
  options.hold_tag_depths = state.range(1) == 2;
  const SequenceFit fit =
      TimedLvPhantomFits(state, phantom_options, options, /*num_frames=*/3);
  const FrameFit& frame = fit.frames[2];
  CountFrame(frame, state);
  state.counters["frame0_ms"] = 1e3 * fit.frames[0].solve_seconds;
  state.counters["first_tracked_ms"] = 1e3 * fit.frames[1].solve_seconds;
  state.counters["solves"] = frame.correspondence_rounds;
  state.counters["iterations"] = frame.iterations;
  state.counters["per_point_ns"] =
      frame.iterations > 0
          ? 1e9 * frame.evaluation_seconds / (frame.iterations * state.range(0))
          : 0.0;
}
BENCHMARK(BM_WallFitFrame)
    ->ArgNames({"points", "solid"})
    ->Apply([](benchmark::internal::Benchmark* b) {
      b->ArgsProduct({{2000, 50000}, {0, 1, 2}});
      RunThreeTimes(b);
    });

}  // namespace
}  // namespace pfdm

BENCHMARK_MAIN();
