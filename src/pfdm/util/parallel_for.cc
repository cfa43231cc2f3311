#include "pfdm/util/parallel_for.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace pfdm {

int ParallelWorkers(size_t n, int threads) {
  return static_cast<int>(std::clamp<size_t>(n, 1, std::max(threads, 1)));
}

void ParallelFor(size_t n, int threads,
                 const std::function<void(int worker, size_t i)>& work) {
  const int workers = ParallelWorkers(n, threads);
  std::atomic<size_t> next(0);
  std::atomic<bool> failed(false);
  std::exception_ptr first_error;
  std::mutex error_mutex;
  const auto take_items = [&](int worker) {
    for (size_t i = next++; i < n && !failed; i = next++) {
      try {
        work(worker, i);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(error_mutex);
        if (!first_error) first_error = std::current_exception();
        failed = true;
      }
    }
  };
  std::vector<std::thread> others;
  for (int worker = 1; worker < workers; ++worker) {
    others.emplace_back(take_items, worker);
  }
  take_items(0);
  for (std::thread& thread : others) thread.join();
  if (first_error) std::rethrow_exception(first_error);
}

}  // namespace pfdm
