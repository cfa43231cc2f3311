#include "pfdm/util/parallel_for.h"

#include <atomic>
#include <set>
#include <stdexcept>
#include <vector>

#include "gtest/gtest.h"

namespace pfdm {
namespace {

TEST(ParallelForTest, EveryItemRunsOnceWhateverTheThreads) {
  for (int threads : {1, 2, 3, 8}) {
    std::vector<std::atomic<int>> runs(100);
    std::vector<int> worker_of(100, -1);
    ParallelFor(runs.size(), threads, [&](int worker, size_t i) {
      ++runs[i];
      worker_of[i] = worker;
    });
    std::set<int> workers;
    for (size_t i = 0; i < runs.size(); ++i) {
      EXPECT_EQ(runs[i], 1) << "item " << i << ", " << threads << " threads";
      EXPECT_GE(worker_of[i], 0);
      EXPECT_LT(worker_of[i], threads);
      workers.insert(worker_of[i]);
    }
    EXPECT_LE(workers.size(), static_cast<size_t>(threads));
    EXPECT_EQ(ParallelWorkers(runs.size(), threads), threads);
  }
}

TEST(ParallelForTest, NoMoreThreadsThanItems) {
  std::vector<int> worker_of(2, -1);
  ParallelFor(2, 16, [&](int worker, size_t i) { worker_of[i] = worker; });
  for (int worker : worker_of) EXPECT_LT(worker, 2);
  EXPECT_EQ(ParallelWorkers(2, 16), 2);
  EXPECT_EQ(ParallelWorkers(0, 4), 1);
  EXPECT_EQ(ParallelWorkers(5, 0), 1);
  int calls = 0;
  ParallelFor(0, 4, [&](int, size_t) { ++calls; });
  EXPECT_EQ(calls, 0);
}

TEST(ParallelForTest, OneThreadRunsTheItemsInOrderOnTheCaller) {
  std::vector<size_t> order;
  ParallelFor(5, 1, [&](int worker, size_t i) {
    EXPECT_EQ(worker, 0);
    order.push_back(i);
  });
  EXPECT_EQ(order, (std::vector<size_t>{0, 1, 2, 3, 4}));
}

TEST(ParallelForTest, AnItemsExceptionReachesTheCaller) {
  for (int threads : {1, 3}) {
    EXPECT_THROW(ParallelFor(50, threads,
                             [](int, size_t i) {
                               if (i == 7) throw std::runtime_error("item 7");
                             }),
                 std::runtime_error);
  }
}

}  // namespace
}  // namespace pfdm
