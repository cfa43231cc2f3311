// The whole job a user waits for, `pfdm fit` end to end through the library:
// read the points, fit every frame, write every output.  Phantoms of N tags
// x 5 frames (written to a scratch CSV first, so reading is timed too) and,
// when ../shared/data is present, biv-me patient 1's LV endocardial contours
// (25 frames, no tracked points).  Reports each phase in ms (the start,
// StartSequence's choice of the long axis, with the checks after the
// frames: SequenceFit::start_seconds, checks_seconds), the tracked
// frames' mean, the tracked frame's minimizer time, the analysis (the
// clinical numbers, AnalyzeFit, which WriteFitOutputs runs first) apart
// from the writing, and the ratios the README quotes: frame 0 over a
// tracked frame, outputs' share of the job; and the CPU each thread got and
// whether other processes were busy (thread_cpu.h).
#include <sys/resource.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>

#include "benchmark/benchmark.h"
#include "pfdm/fit/correspondence/correspondence.h"
#include "pfdm/fit/stages/fitter.h"
#include "pfdm/fit/stages/initialization.h"
#include "pfdm/io/fit_output.h"
#include "pfdm/io/landmark_axis.h"
#include "pfdm/io/mitral_valve_planes.h"
#include "pfdm/io/point_source.h"
#include "pfdm/io/point_writer.h"
#include "pfdm/phantom/phantom.h"
#include "pfdm/report/fit_analysis.h"
#include "pfdm/report/gnuplot.h"
#include "pfdm/util/atomic_file.h"
#include "thread_cpu.h"

namespace pfdm {
namespace {

// CPU seconds of this process and of its waited-for children (gnuplot):
// on a machine shared with other work they stay put where wall times grow.
double CpuSeconds() {
  double seconds = 0.0;
  for (int who : {RUSAGE_SELF, RUSAGE_CHILDREN}) {
    rusage usage{};
    getrusage(who, &usage);
    for (const timeval& t : {usage.ru_utime, usage.ru_stime}) {
      seconds += t.tv_sec + 1e-6 * t.tv_usec;
    }
  }
  return seconds;
}

double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
      .count();
}

std::string ScratchFolder(const std::string& name) {
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / "pfdm_job_benchmark" / name;
  std::filesystem::create_directories(path);
  return path.string();
}

// Times one job on the points at `path` and fills the state's counters.
void RunJob(benchmark::State& state, const std::string& path,
            const std::string& contours, int num_threads,
            const VtkOutput& vtk_output = VtkOutput(),
            bool landmark_axis = false) {
  const std::string out = ScratchFolder("out");
  FitOptions options;
  options.solver.num_threads = num_threads;
  // As `pfdm fit` takes biv-me's axis: from its APEX_POINT and valves.
  if (landmark_axis) AddLandmarkAxis(path, &options);
  double read = 0, axis_start = 0, checks = 0, frame0 = 0, tracked = 0,
         tracked_minimizer = 0, write = 0, correspondence0 = 0, job_cpu = 0,
         write_cpu = 0, analysis = 0;
  int num_tracked = 0;
  CpuSnapshot cpu_start;
  for (auto _ : state) {
    cpu_start = TakeCpuSnapshot();
    const double job_cpu_start = CpuSeconds();
    auto start = std::chrono::steady_clock::now();
    const PointSequence points = ReadPoints(path, "auto", contours);
    read = SecondsSince(start);
    SvgRendering plots;  // As `pfdm fit`: gnuplot loads during the fit.
    const SequenceFit fit =
        FitSequence(points, ModelConfig::Paper(17), options);
    start = std::chrono::steady_clock::now();
    // As `pfdm fit` closes biv-me's volumes: at the mitral valve planes.
    const FitAnalysis fit_analysis =
        AnalyzeFit(fit, landmark_axis ? MitralValvePlanes(path)
                                      : std::vector<BasePlane>());
    analysis = SecondsSince(start);
    start = std::chrono::steady_clock::now();
    const double write_cpu_start = CpuSeconds();
    WriteFitOutputs(out, points, fit, fit_analysis, options, vtk_output,
                    &plots);
    write = SecondsSince(start);
    write_cpu = CpuSeconds() - write_cpu_start;
    job_cpu = CpuSeconds() - job_cpu_start;
    axis_start = fit.start_seconds;
    checks = fit.checks_seconds;
    frame0 = fit.frames[0].solve_seconds;
    correspondence0 = fit.frames[0].correspondence_seconds;
    tracked = tracked_minimizer = 0;
    num_tracked = static_cast<int>(fit.frames.size()) - 1;
    for (size_t t = 1; t < fit.frames.size(); ++t) {
      tracked += fit.frames[t].solve_seconds;
      tracked_minimizer += fit.frames[t].minimizer_seconds;
    }
  }
  CountThreadCpu(cpu_start, state);
  const double job =
      read + axis_start + frame0 + tracked + checks + analysis + write;
  const double per_tracked = tracked / std::max(num_tracked, 1);
  state.counters["job_ms"] = 1e3 * job;
  state.counters["read_ms"] = 1e3 * read;
  state.counters["start_ms"] = 1e3 * axis_start;
  state.counters["checks_ms"] = 1e3 * checks;
  state.counters["frame0_ms"] = 1e3 * frame0;
  state.counters["frame0_correspondence_ms"] = 1e3 * correspondence0;
  state.counters["tracked_ms"] = 1e3 * per_tracked;
  state.counters["tracked_minimizer_ms"] =
      1e3 * tracked_minimizer / std::max(num_tracked, 1);
  state.counters["analysis_ms"] = 1e3 * analysis;
  state.counters["outputs_ms"] = 1e3 * write;
  state.counters["frame0_x_tracked"] = frame0 / per_tracked;
  state.counters["outputs_share"] = write / job;
  // The same share in CPU time (gnuplot's included): what a quiet machine
  // would show, where the wall-clock share swings with the load.
  state.counters["outputs_cpu_ms"] = 1e3 * write_cpu;
  state.counters["outputs_cpu_share"] = write_cpu / job_cpu;
}

// Args: tags, threads.
void BM_PhantomJob(benchmark::State& state) {
  PhantomOptions phantom_options;
  phantom_options.num_points = static_cast<int>(state.range(0));
  phantom_options.num_frames = 5;
  const std::string path = ScratchFolder("phantom") + "/points_" +
                           std::to_string(phantom_options.num_points) + ".csv";
  WriteFileAtomically(path, ToPointsCsv(MakePhantom(phantom_options).points));
  RunJob(state, path, "", static_cast<int>(state.range(1)));
}
BENCHMARK(BM_PhantomJob)
    ->ArgNames({"tags", "threads"})
    ->Args({2000, 1})
    ->Args({20000, 1})
    ->Args({20000, 2})
    ->Args({50000, 1})
    ->Args({50000, 2})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->Repetitions(3)
    ->ReportAggregatesOnly(true);

// The outputs as the default writes them (0: one binary .vtp per frame,
// float32) and as pfdm wrote them before (1: .vtk and .vtp, doubles), at
// 100,000 tags x 5 frames and a million.  Args: tags, outputs.
void BM_OutputsJob(benchmark::State& state) {
  PhantomOptions phantom_options;
  phantom_options.num_points = static_cast<int>(state.range(0));
  phantom_options.num_frames = 5;
  const std::string path = ScratchFolder("phantom") + "/points_" +
                           std::to_string(phantom_options.num_points) + ".csv";
  if (!std::filesystem::exists(path)) {
    WriteFileAtomically(path, ToPointsCsv(MakePhantom(phantom_options).points));
  }
  RunJob(
      state, path, "", 1,
      state.range(1) == 0 ? VtkOutput() : VtkOutputFromNames("both", "double"));
}
BENCHMARK(BM_OutputsJob)
    ->ArgNames({"tags", "outputs"})
    ->ArgsProduct({{100000, 1000000}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->Repetitions(1);

// biv-me patient 1: every frame untracked.  Args: threads, contours (0:
// lv-endo without the landmarks' axis or the valve planes, as the table's
// first biv-me row always ran; 1: lv-cavity and 2: lv-cavity,lv-epi as
// `pfdm fit` runs them, the landmarks giving the axis and the mitral valve
// planes closing the volumes: issue 33's cases).
void BM_BivMeJob(benchmark::State& state) {
  const std::string folder =
      std::string(PFDM_SHARED_DATA_DIR) + "/biv-me-patient1/guidepoints";
  if (!std::filesystem::exists(folder)) {
    state.SkipWithError("../shared/data is absent");
    return;
  }
  const int contours = static_cast<int>(state.range(1));
  const char* names[] = {"lv-endo", "lv-cavity", "lv-cavity,lv-epi"};
  RunJob(state, folder, names[contours], static_cast<int>(state.range(0)),
         VtkOutput(), /*landmark_axis=*/contours > 0);
}
BENCHMARK(BM_BivMeJob)
    ->ArgNames({"threads", "contours"})
    ->Args({1, 0})
    ->Args({1, 1})
    ->Args({1, 2})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->Repetitions(3)
    ->ReportAggregatesOnly(true);

// Frame 0's first correspondence round alone: a 20,000-tag phantom's
// frame 0 against the initialized model.  Args: exhaustive (1: every
// refinement step, as before the early stop), threads, jet (1: ceres::Jet
// derivatives, as before the closed-form ones).
void BM_ClosestMaterialPoints(benchmark::State& state) {
  PhantomOptions phantom_options;
  phantom_options.num_points = 20000;
  phantom_options.num_frames = 1;
  const Phantom phantom = MakePhantom(phantom_options);
  std::vector<Eigen::Vector3d> points;
  for (const DataPoint& p : phantom.points.frames[0].points) {
    points.push_back(p.position);
  }
  const Model model = InitializeModel(ModelConfig::Paper(17), points, {});
  CorrespondenceOptions options;
  if (state.range(0) == 1) options.step_tolerance_mm = 0.0;
  options.num_threads = static_cast<int>(state.range(1));
  options.jet_derivatives = state.range(2) == 1;
  std::int64_t evaluations = 0;
  options.evaluations = &evaluations;
  for (auto _ : state) {
    benchmark::DoNotOptimize(ClosestMaterialPoints(model, points, options));
  }
  // Surface evaluations (point and its derivatives in u and v) per point.
  state.counters["evaluations_per_point"] =
      static_cast<double>(evaluations) /
      (static_cast<double>(state.iterations()) * points.size());
  state.counters["us_per_point"] = benchmark::Counter(
      static_cast<double>(state.iterations()) * points.size(),
      benchmark::Counter::kIsRate | benchmark::Counter::kInvert,
      benchmark::Counter::kIs1000);
}
BENCHMARK(BM_ClosestMaterialPoints)
    ->ArgNames({"exhaustive", "threads", "jet"})
    ->Args({1, 1, 0})
    ->Args({0, 1, 1})
    ->Args({0, 1, 0})
    ->Args({0, 2, 0})
    ->Unit(benchmark::kMillisecond)
    ->Repetitions(3)
    ->ReportAggregatesOnly(true);

}  // namespace
}  // namespace pfdm

BENCHMARK_MAIN();
