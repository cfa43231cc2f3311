// ns per data point for the residual alone, the autodiff Jacobian and the
// analytic Jacobian.  Arg(0): residual only; Arg(1): with Jacobians.
// BM_PointGroup: the same per point of a 1,024-point group as a tracked frame
// uses it (two knots' free entries varied, square-root form); Arg(2): the
// pose (centre and quaternion) varied as well, as tracked frames now fit it.
#include <memory>
#include <random>
#include <vector>

#include "benchmark/benchmark.h"
#include "pfdm/fit/residuals/data_cost.h"
#include "pfdm/fit/residuals/point_group_residual.h"
#include "pfdm/model/model.h"

namespace pfdm {
namespace {

constexpr int kPoints = 256;

struct Fixture {
  std::vector<std::unique_ptr<ceres::CostFunction>> costs;
  double center[3] = {1, 2, 3};
  double quaternion[4] = {0.9, 0.1, -0.3, 0.2};
  FunctionValues globals, knot0, knot1;
  std::vector<double> residuals = std::vector<double>(3);
  std::vector<double> storage =
      std::vector<double>(3 * (7 + 3 * kNumFunctions));
};

Fixture MakeFixture(JacobianKind kind) {
  Fixture fixture;
  fixture.globals = DefaultFunctionValues();
  fixture.globals[kA0] = 90.0;
  fixture.knot0 = fixture.knot1 = fixture.globals;
  fixture.knot1[kA1] = 0.6;
  const double norm = std::sqrt(0.81 + 0.01 + 0.09 + 0.04);
  for (double& q : fixture.quaternion) q /= norm;
  std::mt19937 random(1);
  std::uniform_real_distribution<double> u(-1.5, 0.5), v(-3.1, 3.1);
  for (int i = 0; i < kPoints; ++i) {
    fixture.costs.emplace_back(
        MakePointCost(Eigen::Vector3d(1, 2, 3), u(random), v(random), 0.3,
                      ModelConfig::Paper(17).FreeMask(), true, kind));
  }
  return fixture;
}

void Run(benchmark::State& state, JacobianKind kind) {
  Fixture fixture = MakeFixture(kind);
  const double* parameters[] = {fixture.center, fixture.quaternion,
                                fixture.globals.data(), fixture.knot0.data(),
                                fixture.knot1.data()};
  double* jacobians[5];
  double* next = fixture.storage.data();
  for (int i = 0; i < 5; ++i) {
    jacobians[i] = next;
    next += 3 * (i == 0 ? 3 : i == 1 ? 4 : kNumFunctions);
  }
  double** requested = state.range(0) ? jacobians : nullptr;
  for (auto _ : state) {
    for (const auto& cost : fixture.costs) {
      cost->Evaluate(parameters, fixture.residuals.data(), requested);
    }
    benchmark::DoNotOptimize(fixture.residuals.data());
    benchmark::DoNotOptimize(fixture.storage.data());
  }
  state.SetItemsProcessed(state.iterations() * kPoints);
  state.counters["ns_per_point"] = benchmark::Counter(
      state.iterations() * kPoints,
      benchmark::Counter::kIsRate | benchmark::Counter::kInvert,
      benchmark::Counter::kIs1000);
}

void BM_Analytic(benchmark::State& state) {
  Run(state, JacobianKind::kAnalytic);
}
void BM_Autodiff(benchmark::State& state) {
  Run(state, JacobianKind::kAutodiff);
}

void BM_PointGroup(benchmark::State& state) {
  Fixture fixture = MakeFixture(JacobianKind::kAnalytic);
  const ModelConfig config = ModelConfig::Paper(17);
  std::vector<int> free;
  for (int f = 0; f < kNumFunctions; ++f) {
    if ((config.FreeMask() >> f) & 1u) free.push_back(f);
  }
  FreeEntries knot0(fixture.knot0.data(), free),
      knot1(fixture.knot1.data(), free);
  constexpr int kGroup = 1024;  // frame_problem.cc's kPointsPerGroup.
  std::mt19937 random(1);
  std::uniform_real_distribution<double> u(-1.5, 0.5), v(-3.1, 3.1),
      weight(0.0, 1.0);
  // Data spread about the centre: data at the centre itself would make
  // the residual parallel to the quaternion's radial column (R(q) s is
  // quadratic in q), a rank-deficient [J r] that only the QR fallback of
  // square_root_form.cc takes, and no fit poses.
  std::uniform_real_distribution<double> offset(-40.0, 40.0);
  std::vector<PointSample> samples;
  for (int i = 0; i < kGroup; ++i) {
    const Eigen::Vector3d data(1 + offset(random), 2 + offset(random),
                               3 + offset(random));
    samples.emplace_back(data, u(random), v(random), weight(random));
  }
  // Arg 2: the pose varies too, as on every frame since the gauge fix.
  const bool pose = state.range(0) == 2;
  const PointGroupResidual group(std::move(samples), config.FreeMask(), true,
                                 {nullptr, &knot0, &knot1},
                                 {pose, pose, false, true, true});
  const double* parameters[] = {fixture.center, fixture.quaternion,
                                fixture.globals.data(), knot0.parameters(),
                                knot1.parameters()};
  std::vector<double> residuals(group.num_residuals());
  std::vector<double> jacobian0(group.num_residuals() * knot0.size());
  std::vector<double> jacobian1(jacobian0.size());
  std::vector<double> jacobian_center(group.num_residuals() * 3);
  std::vector<double> jacobian_quaternion(group.num_residuals() * 4);
  double* jacobians[] = {pose ? jacobian_center.data() : nullptr,
                         pose ? jacobian_quaternion.data() : nullptr, nullptr,
                         jacobian0.data(), jacobian1.data()};
  for (auto _ : state) {
    group.Evaluate(parameters, residuals.data(),
                   state.range(0) ? jacobians : nullptr);
    benchmark::DoNotOptimize(residuals.data());
    benchmark::DoNotOptimize(jacobian1.data());
  }
  state.SetItemsProcessed(state.iterations() * kGroup);
  state.counters["ns_per_point"] = benchmark::Counter(
      state.iterations() * kGroup,
      benchmark::Counter::kIsRate | benchmark::Counter::kInvert,
      benchmark::Counter::kIs1000);
}

BENCHMARK(BM_Analytic)->Arg(0)->Arg(1);
BENCHMARK(BM_PointGroup)->Arg(0)->Arg(1)->Arg(2);
BENCHMARK(BM_Autodiff)->Arg(0)->Arg(1);

}  // namespace
}  // namespace pfdm

BENCHMARK_MAIN();
