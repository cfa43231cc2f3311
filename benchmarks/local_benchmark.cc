// Local deformations' cost: a systolic frame of the analytic LV phantom (N
// tracked tags, K = 17, the default 13 x 24 local grid) fitted from
// end-diastole, with and without the local field (fit/local_fit.h).
// "frame_ms" is the whole frame, "local_ms" the local field's solve within
// it.  Each configuration runs three times; read the medians.
#include "benchmark/benchmark.h"
#include "benchmark_util.h"
#include "pfdm/fit/fit_options.h"
#include "pfdm/fit/stages/sequence_fit.h"
#include "pfdm/phantom/lv_phantom.h"

namespace pfdm {
namespace {

// Args: tags, local (0 off, 1 on).
void BM_LocalFitFrame(benchmark::State& state) {
  LvPhantomOptions phantom_options;
  phantom_options.deformation.lesion = true;
  FitOptions options;
  options.local.enabled = state.range(1) != 0;
  const SequenceFit fit = TimedLvPhantomFits(state, phantom_options, options);
  const FrameFit& frame = fit.frames[1];
  CountFrame(frame, state);
  state.counters["local_ms"] = 1e3 * frame.local_seconds;
  state.counters["local_iterations"] = frame.local_iterations;
}
BENCHMARK(BM_LocalFitFrame)->ArgNames({"points", "local"})->Apply(OffAndOn);

}  // namespace
}  // namespace pfdm

BENCHMARK_MAIN();
