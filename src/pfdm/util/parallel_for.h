// Independent items spread over threads that take the next one as they free
// up (a thread on a slower vCPU holds up no other), the calling thread among
// them.  What each item computes must not depend on which thread ran it or
// on what that thread ran before: the results are then the same, to the
// bit, for any number of threads.
#ifndef PFDM_UTIL_PARALLEL_FOR_H_
#define PFDM_UTIL_PARALLEL_FOR_H_

#include <cstddef>
#include <functional>

namespace pfdm {

// Calls work(worker, i) once for every i in [0, n), on min(threads, n)
// threads (at least one); worker in [0, threads) names the thread, so that
// each may keep state of its own, and is 0 on the calling thread.  The first
// exception an item throws is rethrown here once every thread has stopped
// (the items not yet taken are left).
void ParallelFor(size_t n, int threads,
                 const std::function<void(int worker, size_t i)>& work);

// How many threads ParallelFor(n, threads, ...) runs on: the workers'
// count, for state kept per worker.
int ParallelWorkers(size_t n, int threads);

}  // namespace pfdm

#endif  // PFDM_UTIL_PARALLEL_FOR_H_
