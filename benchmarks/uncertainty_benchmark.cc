// What --uncertainty costs (docs/uncertainty.md, Cost): the default
// phantom's end-diastole and one tracked frame (N tags, K = 17, the local
// field on, one thread) fitted and analysed (every clinical, strain and
// segment number) without and with it.  Per frame, CPU time of this
// thread: "fit_ms" and "analysis_ms" without it; "covariance_ms" the
// frames' covariances (FrameCovariance::seconds, wall time of one thread),
// "draws_ms" the rest it adds to the fit (the local field's and the
// length's noise draws), "numbers_ms" what it adds to the analysis (the
// delta method and the draws' measurements); "share" all three over
// fit_ms + analysis_ms, the job's own work.  The numbers' cost does not
// grow with N (they are measured on the model, not the data); it grows
// with the frames, as each of ED's steps measures every frame again.
// Each configuration runs three times; read the medians.
// BM_UncertaintyThreads: the analysis with --uncertainty on of one such fit
// (2,000 tags) on one thread and on two (--threads: the delta method's
// steps and the local field's draws spread over them), wall time per
// frame, with what CPU each thread got and whether other processes used
// the second core meanwhile (thread_cpu.h).
#include <time.h>

#include <algorithm>
#include <chrono>

#include "benchmark/benchmark.h"
#include "benchmark_util.h"
#include "pfdm/fit/fit_options.h"
#include "pfdm/fit/stages/sequence_fit.h"
#include "pfdm/phantom/phantom.h"
#include "pfdm/report/fit_analysis.h"
#include "thread_cpu.h"

namespace pfdm {
namespace {

double ThreadCpuSeconds() {
  timespec now;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return now.tv_sec + 1e-9 * now.tv_nsec;
}

// CPU seconds of one fit and of its analysis.
struct JobSeconds {
  double fit = 0.0, analysis = 0.0, covariance = 0.0;
  size_t frames = 0;
};

JobSeconds TimeJob(const Phantom& phantom, bool uncertainty) {
  FitOptions options;
  options.uncertainty = uncertainty;
  JobSeconds seconds;
  const double start = ThreadCpuSeconds();
  const SequenceFit fit =
      FitSequence(phantom.points, ModelConfig::Paper(17), options);
  const double fitted = ThreadCpuSeconds();
  const FitAnalysis analysis = AnalyzeFit(fit);
  benchmark::DoNotOptimize(analysis.sd.computed);
  seconds.fit = fitted - start;
  seconds.analysis = ThreadCpuSeconds() - fitted;
  for (const FrameFit& frame : fit.frames) {
    seconds.covariance += frame.covariance.seconds;
  }
  seconds.frames = fit.frames.size();
  return seconds;
}

// Args: tags.
void BM_Uncertainty(benchmark::State& state) {
  PhantomOptions phantom_options;
  phantom_options.num_points = static_cast<int>(state.range(0));
  phantom_options.num_frames = 2;
  const Phantom phantom = MakePhantom(phantom_options);
  JobSeconds off, on;
  for (auto _ : state) {
    off = TimeJob(phantom, false);
    on = TimeJob(phantom, true);
  }
  const double per_frame = 1e3 / off.frames;
  const double draws = std::max(0.0, on.fit - on.covariance - off.fit);
  const double numbers = std::max(0.0, on.analysis - off.analysis);
  state.counters["fit_ms"] = off.fit * per_frame;
  state.counters["analysis_ms"] = off.analysis * per_frame;
  state.counters["covariance_ms"] = on.covariance * per_frame;
  state.counters["draws_ms"] = draws * per_frame;
  state.counters["numbers_ms"] = numbers * per_frame;
  state.counters["share"] =
      (on.covariance + draws + numbers) / (off.fit + off.analysis);
}
BENCHMARK(BM_Uncertainty)
    ->ArgNames({"points"})
    ->Arg(2000)
    ->Arg(20000)
    ->Arg(50000)
    ->Apply(RunThreeTimes);

// Args: tags, threads.
void BM_UncertaintyThreads(benchmark::State& state) {
  PhantomOptions phantom_options;
  phantom_options.num_points = static_cast<int>(state.range(0));
  phantom_options.num_frames = 2;
  FitOptions options;
  options.uncertainty = true;
  SequenceFit fit = FitSequence(MakePhantom(phantom_options).points,
                                ModelConfig::Paper(17), options);
  fit.threads = static_cast<int>(state.range(1));
  double seconds = 0.0;
  CpuSnapshot cpu_start;
  for (auto _ : state) {
    cpu_start = TakeCpuSnapshot();
    const auto start = std::chrono::steady_clock::now();
    const FitAnalysis analysis = AnalyzeFit(fit);
    benchmark::DoNotOptimize(analysis.sd.computed);
    seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
            .count();
  }
  CountThreadCpu(cpu_start, state);
  state.counters["analysis_ms"] = 1e3 * seconds / fit.frames.size();
}
BENCHMARK(BM_UncertaintyThreads)
    ->ArgNames({"points", "threads"})
    ->Args({2000, 1})
    ->Args({2000, 2})
    ->Apply(RunThreeTimes);

}  // namespace
}  // namespace pfdm

BENCHMARK_MAIN();
