#include "pfdm/fit/residuals/precomputed_groups.h"

#include <algorithm>
#include <atomic>
#include <limits>
#include <numeric>
#include <utility>

#define EIGEN_USE_THREADS
#include "unsupported/Eigen/CXX11/ThreadPool"

namespace pfdm {
namespace {

// Fewer points than this are evaluated on the calling thread alone: at
// 1,000 points, waking a second thread cost more than it saved (1.48 ms an
// LM iteration against 1.28 with one thread).
constexpr int kMinPointsForThreads = 4096;

}  // namespace

PrecomputedGroups::PrecomputedGroups(int num_threads, bool speculate)
    : num_threads_(num_threads),
      pool_(num_threads > 1 ? std::make_unique<Eigen::ThreadPool>(
                                  num_threads - 1, /*allow_spinning=*/false)
                            : nullptr),
      speculate_(speculate) {}

PrecomputedGroups::~PrecomputedGroups() = default;

void PrecomputedGroups::Add(const PointGroupResidual* group,
                            std::vector<double*> blocks) {
  groups_.push_back({group, std::move(blocks)});
  num_points_ += group->num_samples();
  sorted_ = false;
}

// Ceres' trust-region minimizer asks for: (Jacobians, new point) at the
// start; (no Jacobians, new point) at each step's candidate; (Jacobians,
// same point) when it accepts the candidate.  A candidate after a
// candidate means the first was rejected.
void PrecomputedGroups::PrepareForEvaluation(bool evaluate_jacobians,
                                             bool new_evaluation_point) {
  if (!new_evaluation_point && (have_jacobians_ || !evaluate_jacobians)) {
    // The groups already hold what is asked at this point.
  } else {
    bool with_jacobians = evaluate_jacobians;
    if (!evaluate_jacobians && speculate_) {
      with_jacobians = !candidate_pending_ && last_decrease_ > kSpeculateAbove;
    }
    cost_ = Compute(with_jacobians);
    have_jacobians_ = with_jacobians;
  }
  if (!evaluate_jacobians) {
    // A candidate; the one before it, if still pending, was rejected.
    if (candidate_pending_) last_decrease_ = 0.0;
    candidate_pending_ = true;
  } else if (new_evaluation_point) {
    // A start: no step taken yet, the first candidate speculates.
    accepted_cost_ = cost_;
    last_decrease_ = std::numeric_limits<double>::infinity();
    candidate_pending_ = false;
  } else {
    last_decrease_ =
        accepted_cost_ > 0.0 ? (accepted_cost_ - cost_) / accepted_cost_ : 0.0;
    accepted_cost_ = cost_;
    candidate_pending_ = false;
  }
}

double PrecomputedGroups::Compute(bool with_jacobians) {
  ++(with_jacobians ? jacobian_evaluations_ : residual_evaluations_);
  if (!sorted_) {
    std::stable_sort(
        groups_.begin(), groups_.end(), [](const Group& a, const Group& b) {
          return a.residual->num_samples() > b.residual->num_samples();
        });
    sorted_ = true;
  }
  std::vector<double> costs(groups_.size(), 0.0);
  if (num_threads_ == 1 || num_points_ < kMinPointsForThreads) {
    for (size_t i = 0; i < groups_.size(); ++i) {
      costs[i] = groups_[i].residual->Precompute(groups_[i].blocks.data(),
                                                 with_jacobians);
    }
  } else {
    std::atomic<size_t> next(0);
    auto work = [&] {
      for (size_t i = next++; i < groups_.size(); i = next++) {
        costs[i] = groups_[i].residual->Precompute(groups_[i].blocks.data(),
                                                   with_jacobians);
      }
    };
    Eigen::Barrier done(num_threads_ - 1);
    for (int t = 1; t < num_threads_; ++t) {
      pool_->Schedule([&] {
        work();
        done.Notify();
      });
    }
    work();
    done.Wait();
  }
  return std::accumulate(costs.begin(), costs.end(), 0.0);
}

}  // namespace pfdm
