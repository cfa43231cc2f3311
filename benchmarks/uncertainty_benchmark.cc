// What --uncertainty costs (docs/uncertainty.md, Cost): the default
// phantom's end-diastole and one tracked frame (N tags, K = 17, the local
// field on, one thread) fitted with the covariances, then every number's sd
// (PropagateUncertainty).  Per frame, CPU time of this thread: "fit_ms"
// the fit without the covariances, "covariance_ms" the frames'
// covariances (FrameCovariance::seconds, wall time of one thread),
// "numbers_ms" the numbers' sds; "*_share" each over fit_ms.  The numbers'
// cost does not grow with N (they are measured on the model, not the
// data); it grows with the frames, as each of ED's steps measures every
// frame again.  Each configuration runs three times; read the medians.
#include <time.h>

#include "benchmark/benchmark.h"
#include "benchmark_util.h"
#include "pfdm/fit/fit_options.h"
#include "pfdm/fit/stages/sequence_fit.h"
#include "pfdm/phantom/phantom.h"
#include "pfdm/report/fit_analysis.h"
#include "pfdm/report/number_uncertainty.h"

namespace pfdm {
namespace {

double ThreadCpuSeconds() {
  timespec now;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return now.tv_sec + 1e-9 * now.tv_nsec;
}

// Args: tags.
void BM_Uncertainty(benchmark::State& state) {
  PhantomOptions phantom_options;
  phantom_options.num_points = static_cast<int>(state.range(0));
  phantom_options.num_frames = 2;
  const Phantom phantom = MakePhantom(phantom_options);
  FitOptions options;
  options.uncertainty = true;
  double fit_seconds = 0.0, numbers_seconds = 0.0, covariance_seconds = 0.0;
  size_t frames = 0;
  for (auto _ : state) {
    const double start = ThreadCpuSeconds();
    SequenceFit fit =
        FitSequence(phantom.points, ModelConfig::Paper(17), options);
    const double fitted = ThreadCpuSeconds();
    // The analysis without the sds (a frame without its covariance), then
    // the sds alone.
    SequenceFit without = fit;
    without.frames.back().covariance.computed = false;
    const FitAnalysis analysis = AnalyzeFit(without);
    const double analyzed = ThreadCpuSeconds();
    const NumberSd sd = PropagateUncertainty(fit, analysis);
    numbers_seconds = ThreadCpuSeconds() - analyzed;
    benchmark::DoNotOptimize(sd.computed);
    covariance_seconds = 0.0;
    for (const FrameFit& frame : fit.frames) {
      covariance_seconds += frame.covariance.seconds;
    }
    fit_seconds = fitted - start - covariance_seconds;
    frames = fit.frames.size();
  }
  const double per_frame = 1e3 / frames;
  state.counters["fit_ms"] = fit_seconds * per_frame;
  state.counters["covariance_ms"] = covariance_seconds * per_frame;
  state.counters["numbers_ms"] = numbers_seconds * per_frame;
  state.counters["covariance_share"] = covariance_seconds / fit_seconds;
  state.counters["numbers_share"] = numbers_seconds / fit_seconds;
}
BENCHMARK(BM_Uncertainty)
    ->ArgNames({"points"})
    ->Arg(2000)
    ->Arg(20000)
    ->Arg(50000)
    ->Apply(RunThreeTimes);

}  // namespace
}  // namespace pfdm

BENCHMARK_MAIN();
