// Whole-frame fits: a tracked phantom frame of N points, K = 17, solved from
// the previous frame's fit.  Reports time per LM iteration (the minimizer's
// time, without building the problem) split into evaluation (residuals and
// Jacobians) and linear solve, the frame's time from its start, and the
// time per iteration as a multiple of this machine's arithmetic floor.  Each
// configuration runs three times (one fit is ~1.5 s at N = 50k); read the
// medians.
//
// Floor per LM iteration = (Jacobian flops + J^T J flops + factorization
// flops) / (dense matrix-multiply rate, measured on the CPU of a one-thread
// fit just before it, the fit pinned there), for the problem a tracked frame
// poses: a data point's 3 rows have 2 x 10 non-zero knot columns (two knots
// of the paper's 10 free functions) and the pose's 6 (centre, and the
// quaternion's 3 tangent directions: tracked frames fit the pose too).
//  - Jacobian: ~650 flops per point, counted in ShapeAndJacobian and
//    EvaluateSample (a sine-cosine pair as 20; 5 per point), plus the
//    pose's 3 x 6 entries (~60).
//  - J^T J: 3 x 26 x 27 flops per point (the symmetric half, 2 flops per
//    multiply-add).  PointGroupResidual gets it with fewer (the moments of
//    analytic_point_residual.cc); the floor still counts the plain product,
//    the arithmetic the problem itself poses.
//  - Cholesky: p^3 / 3 for p = 17 x 10 + 6 parameters.
#include <pthread.h>
#include <sched.h>

#include <chrono>
#include <cstdio>
#include <optional>

#include "Eigen/Core"
#include "benchmark/benchmark.h"
#include "benchmark_util.h"
#include "pfdm/fit/fit_options.h"
#include "pfdm/fit/stages/sequence_fit.h"
#include "pfdm/phantom/phantom.h"
#include "thread_cpu.h"

namespace pfdm {
namespace {

constexpr double kJacobianFlopsPerPoint = 710.0;
constexpr double kColumnsPerPoint = 26.0;
constexpr double kRowsPerPoint = 3.0;
constexpr double kParameters = 17.0 * 10.0 + 6.0;

// Flops per second of a 512 x 512 dense matrix product, the best case for
// this machine's arithmetic, on the CPU the calling thread runs on.
double MeasureMatrixMultiplyRate() {
  const int n = 512;
  const Eigen::MatrixXd a = Eigen::MatrixXd::Random(n, n);
  const Eigen::MatrixXd b = Eigen::MatrixXd::Random(n, n);
  Eigen::MatrixXd c(n, n);
  double best = 1e30;
  for (int repeat = 0; repeat < 5; ++repeat) {
    const auto start = std::chrono::steady_clock::now();
    c.noalias() = a * b;
    benchmark::DoNotOptimize(c.data());
    best = std::min(best, std::chrono::duration<double>(
                              std::chrono::steady_clock::now() - start)
                              .count());
  }
  return 2.0 * n * n * n / best;
}

// Keeps the calling thread on the CPU it runs on until destroyed, so that a
// one-thread fit and its floor's matrix product share a core: this VM's two
// vCPUs have run the same products up to 1.5x apart, which one is slower
// changing with the host's other work.
class PinnedToThisCpu {
 public:
  PinnedToThisCpu() {
    pthread_getaffinity_np(pthread_self(), sizeof(old_), &old_);
    cpu_set_t one;
    CPU_ZERO(&one);
    CPU_SET(sched_getcpu(), &one);
    pthread_setaffinity_np(pthread_self(), sizeof(one), &one);
  }
  ~PinnedToThisCpu() {
    pthread_setaffinity_np(pthread_self(), sizeof(old_), &old_);
  }

 private:
  cpu_set_t old_;
};

double FloorFlopsPerIteration(int num_points) {
  return num_points *
             (kJacobianFlopsPerPoint +
              kRowsPerPoint * kColumnsPerPoint * (kColumnsPerPoint + 1.0)) +
         kParameters * kParameters * kParameters / 3.0;
}

void BM_MatrixMultiplyRate(benchmark::State& state) {
  double rate = 0.0;
  for (auto _ : state) rate = MeasureMatrixMultiplyRate();
  state.counters["gflops"] = rate / 1e9;
}
BENCHMARK(BM_MatrixMultiplyRate)->Iterations(1);

// Args: points, threads, linear solver, jacobian (0 analytic, 1 autodiff),
// sparse library (ceres::SparseLinearAlgebraLibraryType).
void BM_FitFrame(benchmark::State& state) {
  const int num_points = static_cast<int>(state.range(0));
  PhantomOptions phantom_options;
  phantom_options.num_points = num_points;
  phantom_options.num_frames = 2;
  const Phantom phantom = MakePhantom(phantom_options);
  FitOptions options;
  options.solver.num_threads = static_cast<int>(state.range(1));
  options.solver.linear_solver =
      static_cast<ceres::LinearSolverType>(state.range(2));
  options.jacobian =
      state.range(3) == 0 ? JacobianKind::kAnalytic : JacobianKind::kAutodiff;
  options.solver.sparse_library =
      static_cast<ceres::SparseLinearAlgebraLibraryType>(state.range(4));
  // One thread: pinned, and the floor measured on its CPU just before.
  std::optional<PinnedToThisCpu> pinned;
  if (options.solver.num_threads == 1) pinned.emplace();
  const double rate = MeasureMatrixMultiplyRate();
  const CpuSnapshot cpu_start = TakeCpuSnapshot();
  const SequenceFit fit = TimedFits(state, phantom.points, options);
  CountThreadCpu(cpu_start, state);
  pinned.reset();
  const FrameFit& frame = fit.frames[1];  // Tracked: one solve.
  const double iterations = std::max(frame.iterations, 1);
  const double per_iteration = frame.minimizer_seconds / iterations;
  state.counters["iterations"] = frame.iterations;
  state.counters["jacobian_evaluations"] = frame.jacobian_evaluations;
  state.counters["residual_evaluations"] = frame.residual_evaluations;
  CountFrame(frame, state);
  state.counters["setup_ms"] =
      1e3 * (frame.solve_seconds - frame.minimizer_seconds);
  state.counters["ms_per_iter"] = 1e3 * per_iteration;
  state.counters["evaluation_ms_per_iter"] =
      1e3 * frame.evaluation_seconds / iterations;
  state.counters["linear_ms_per_iter"] =
      1e3 * frame.linear_solver_seconds / iterations;
  state.counters["x_floor"] =
      per_iteration * rate / FloorFlopsPerIteration(num_points);
  state.counters["gflops"] = rate / 1e9;
}

void FitArguments(benchmark::internal::Benchmark* b) {
  b->ArgNames({"points", "threads", "solver", "autodiff", "sparse"});
  // pfdm's default linear solver (DENSE_SCHUR since the contour jobs'
  // speed-up, issue 33), and the alternatives it was chosen over.
  const int kDefault = FitOptions().solver.linear_solver;
  constexpr int kSparse = ceres::SPARSE_NORMAL_CHOLESKY;
  constexpr int kEigen = ceres::EIGEN_SPARSE;
  // The interactive case: a 2,000-point frame from the previous frame.
  b->Args({2000, 1, kDefault, 0, kEigen});
  for (int points : {1000, 10000, 50000}) {
    for (int threads : {1, 2}) b->Args({points, threads, kDefault, 0, kEigen});
    // The alternatives the default was chosen over (docs/performance.md).
    b->Args({points, 1, kSparse, 0, kEigen});
    b->Args({points, 1, kSparse, 0, ceres::SUITE_SPARSE});
    b->Args({points, 1, ceres::DENSE_NORMAL_CHOLESKY, 0, kEigen});
    if (points <= 10000) {
      b->Args({points, 1, ceres::DENSE_QR, 0, kEigen});
      b->Args({points, 1, kDefault, 1, kEigen});
    }
  }
}
BENCHMARK(BM_FitFrame)->Apply(FitArguments)->Apply(RunThreeTimes);

}  // namespace
}  // namespace pfdm

BENCHMARK_MAIN();
