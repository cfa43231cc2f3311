// A frame's point groups evaluated ahead of Ceres, on threads that take the
// groups as they free up.  Ceres 2.1's ParallelFor hands thread t the
// residual blocks t, t + T, t + 2T, ..., fixed in advance, so one thread on
// a slower core holds up every evaluation: on the project's 2-core VM one
// vCPU ran the same matrix products 1.3-1.5x slower than the other (its
// host's other hyperthread busy, presumably; a laptop's efficiency cores
// would do the same), and with two threads that thread's half of the
// groups took 450 ms against the other's 275.  Here the largest groups go
// first and each thread takes the next as it is done; Ceres' evaluation
// then copies the results (PointGroupResidual::Precompute), through the
// EvaluationCallback that Ceres provides for sharing work across blocks.
#ifndef PFDM_FIT_PRECOMPUTED_GROUPS_H_
#define PFDM_FIT_PRECOMPUTED_GROUPS_H_

#include <memory>
#include <vector>

#include "ceres/evaluation_callback.h"
#include "pfdm/fit/point_group_residual.h"

namespace Eigen {
template <typename Environment>
class ThreadPoolTempl;
struct StlThreadEnvironment;
}  // namespace Eigen

namespace pfdm {

class PrecomputedGroups : public ceres::EvaluationCallback {
 public:
  // num_threads > 1: the calling thread and num_threads - 1 workers.
  explicit PrecomputedGroups(int num_threads);
  ~PrecomputedGroups() override;

  // A group and its parameter blocks as the problem holds them (the values
  // Ceres leaves in them before each evaluation).
  void Add(const PointGroupResidual* group, std::vector<double*> blocks);

  void PrepareForEvaluation(bool evaluate_jacobians,
                            bool new_evaluation_point) override;

 private:
  struct Group {
    const PointGroupResidual* residual;
    std::vector<double*> blocks;
  };

  int num_threads_;
  std::unique_ptr<Eigen::ThreadPoolTempl<Eigen::StlThreadEnvironment>> pool_;
  std::vector<Group> groups_;
  int num_points_ = 0;
  bool sorted_ = false;  // Largest first.
};

}  // namespace pfdm

#endif  // PFDM_FIT_PRECOMPUTED_GROUPS_H_
