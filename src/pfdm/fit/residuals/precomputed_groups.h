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
// With one thread, it still decides what to evaluate (speculation, below).
#ifndef PFDM_FIT_RESIDUALS_PRECOMPUTED_GROUPS_H_
#define PFDM_FIT_RESIDUALS_PRECOMPUTED_GROUPS_H_

#include <memory>
#include <vector>

#include "ceres/evaluation_callback.h"
#include "pfdm/fit/residuals/point_group_residual.h"

namespace Eigen {
template <typename Environment>
class ThreadPoolTempl;
struct StlThreadEnvironment;
}  // namespace Eigen

namespace pfdm {

// With `speculate`, a trust-region step's candidate point is evaluated
// with its Jacobians, which Ceres asks for next once it accepts the step:
// one evaluation of the groups instead of two (a 50,000-point frame's
// residuals alone took a fifth of the time of its Jacobians).  Only while
// steps are accepted and far from the end: it stops after a rejected step
// and once a step has lowered the cost by under kSpeculateAbove (the next
// step, lowering it by less still, is likely the last, which Ceres ends
// on without Jacobians).
class PrecomputedGroups : public ceres::EvaluationCallback {
 public:
  // num_threads >= 1: the calling thread and num_threads - 1 workers.
  PrecomputedGroups(int num_threads, bool speculate);
  ~PrecomputedGroups() override;

  // A group and its parameter blocks as the problem holds them (the values
  // Ceres leaves in them before each evaluation).
  void Add(const PointGroupResidual* group, std::vector<double*> blocks);

  void PrepareForEvaluation(bool evaluate_jacobians,
                            bool new_evaluation_point) override;

  // Evaluations of the groups with and without Jacobians so far.
  int jacobian_evaluations() const { return jacobian_evaluations_; }
  int residual_evaluations() const { return residual_evaluations_; }

  // A step's relative decrease of the groups' cost under which the next
  // candidate is evaluated without Jacobians.  The direct solve ends on a
  // step that lowers the cost by under 1e-9 (SolverOptions), and near the
  // minimum the decreases fall fast: the phantom's tracked frames went
  // 0.82, 1.6e-4, end (20,000 points) and 0.99, 0.026, -2e-5, end (50,000;
  // the groups' cost alone can rise while the regularizers' falls).  A
  // wasted speculation costs three to four residual passes, a missed one
  // costs one.
  static constexpr double kSpeculateAbove = 1e-3;

 private:
  // Evaluates every group at the blocks' values; returns the summed
  // squared residual norms.
  double Compute(bool with_jacobians);
  struct Group {
    const PointGroupResidual* residual;
    std::vector<double*> blocks;
  };

  int num_threads_;
  std::unique_ptr<Eigen::ThreadPoolTempl<Eigen::StlThreadEnvironment>> pool_;
  std::vector<Group> groups_;
  int num_points_ = 0;
  bool sorted_ = false;  // Largest first.
  const bool speculate_;
  // At the point last evaluated: whether with Jacobians, and the cost.
  bool have_jacobians_ = false;
  double cost_ = 0.0;
  double accepted_cost_ = 0.0;  // At the last accepted point.
  double last_decrease_ = 0.0;  // The last accepted step's, relative.
  bool candidate_pending_ = false;
  int jacobian_evaluations_ = 0;
  int residual_evaluations_ = 0;
};

}  // namespace pfdm

#endif  // PFDM_FIT_RESIDUALS_PRECOMPUTED_GROUPS_H_
