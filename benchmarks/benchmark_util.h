// What the whole-fit benchmarks (fit_benchmark.cc, local_benchmark.cc,
// wall_benchmark.cc) share: how each configuration is run and timed, and
// the counters every one reports.  A header, as each benchmarks/*.cc
// builds into an executable of its own.
#ifndef PFDM_BENCHMARKS_BENCHMARK_UTIL_H_
#define PFDM_BENCHMARKS_BENCHMARK_UTIL_H_

#include "benchmark/benchmark.h"
#include "pfdm/fit/stages/fitter.h"
#include "pfdm/phantom/lv_phantom.h"
#include "pfdm/util/point_data.h"

namespace pfdm {

// Each configuration runs three times, one fit each (a 50,000-point fit
// takes seconds), and reports only the aggregates: read the medians, as
// scripts/performance_tables.py does.
inline void RunThreeTimes(benchmark::internal::Benchmark* b) {
  b->Unit(benchmark::kMillisecond)
      ->Iterations(1)
      ->Repetitions(3)
      ->ReportAggregatesOnly(true);
}

// A 2,000-tag frame and a 50,000-tag one, each with what the second
// argument switches off (0) and on (1), each run three times.
inline void OffAndOn(benchmark::internal::Benchmark* b) {
  b->ArgsProduct({{2000, 50000}, {0, 1}});
  RunThreeTimes(b);
}

// Fits the sequence with the paper's model on 17 knots once per benchmark
// iteration, only the fits timed; returns the last fit.
inline SequenceFit TimedFits(benchmark::State& state,
                             const PointSequence& sequence,
                             const FitOptions& options) {
  SequenceFit fit;
  for (auto _ : state) {
    fit = FitSequence(sequence, ModelConfig::Paper(17), options);
  }
  return fit;
}

// TimedFits of the analytic LV phantom's end-diastole and a systolic frame
// tracked from it, with as many tags as the first argument says.
inline SequenceFit TimedLvPhantomFits(benchmark::State& state,
                                      LvPhantomOptions phantom_options,
                                      const FitOptions& options,
                                      int num_frames = 2) {
  phantom_options.num_tags = static_cast<int>(state.range(0));
  phantom_options.num_frames = num_frames;
  const LvPhantom phantom = MakeLvPhantom(phantom_options);
  return TimedFits(state, phantom.points, options);
}

// The counters every whole-fit benchmark reports of its tracked frame: the
// frame's time from its start and its residual.
inline void CountFrame(const FrameFit& frame, benchmark::State& state) {
  state.counters["frame_ms"] = 1e3 * frame.solve_seconds;
  state.counters["rms_mm"] = frame.rms_mm;
}

}  // namespace pfdm

#endif  // PFDM_BENCHMARKS_BENCHMARK_UTIL_H_
