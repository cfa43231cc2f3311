// Local deformations' cost: a systolic frame of the analytic LV phantom (N
// tracked tags, K = 17, the default 13 x 24 local grid) fitted from
// end-diastole, with and without the local field (fit/local_fit.h).
// "frame_ms" is the whole frame, "local_ms" the local field's solve within
// it.  Each configuration runs three times; read the medians.
#include "benchmark/benchmark.h"
#include "pfdm/fit/stages/fitter.h"
#include "pfdm/phantom/lv_phantom.h"

namespace pfdm {
namespace {

// Args: tags, local (0 off, 1 on).
void BM_LocalFitFrame(benchmark::State& state) {
  LvPhantomOptions phantom_options;
  phantom_options.num_tags = static_cast<int>(state.range(0));
  phantom_options.num_frames = 2;
  phantom_options.deformation.lesion = true;
  const LvPhantom phantom = MakeLvPhantom(phantom_options);
  FitOptions options;
  options.local.enabled = state.range(1) != 0;
  SequenceFit fit;
  for (auto _ : state) {
    fit = FitSequence(phantom.points, ModelConfig::Paper(17), options);
  }
  const FrameFit& frame = fit.frames[1];
  state.counters["frame_ms"] = 1e3 * frame.solve_seconds;
  state.counters["local_ms"] = 1e3 * frame.local_seconds;
  state.counters["local_iterations"] = frame.local_iterations;
  state.counters["rms_mm"] = frame.rms_mm;
}
BENCHMARK(BM_LocalFitFrame)
    ->ArgNames({"points", "local"})
    ->ArgsProduct({{2000, 50000}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->Repetitions(3)
    ->ReportAggregatesOnly(true);

}  // namespace
}  // namespace pfdm

BENCHMARK_MAIN();
