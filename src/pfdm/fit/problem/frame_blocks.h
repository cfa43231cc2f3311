// One frame's parameter blocks in a ceres::Problem: the pose as it is, and
// the globals and each knot as their free entries (gauge.h says which), or
// whole and constant when none is free.
#ifndef PFDM_FIT_PROBLEM_FRAME_BLOCKS_H_
#define PFDM_FIT_PROBLEM_FRAME_BLOCKS_H_

#include <memory>
#include <vector>

#include "ceres/ceres.h"
#include "pfdm/fit/problem/gauge.h"
#include "pfdm/fit/residuals/free_entries.h"
#include "pfdm/model/model.h"
#include "pfdm/solvers/damping_groups.h"
#include "pfdm/solvers/solver.h"

namespace pfdm {

class FrameBlocks {
 public:
  // Adds the blocks to `problem`, the pose free in every frame (its spin
  // after frame 0 is held by SpinGaugeResidual).  Both must outlive this.
  FrameBlocks(FrameKind kind, Model* model, ceres::Problem* problem);

  // The free entries of a block (kGlobalsBlock or a knot index); null when
  // the block is constant.
  const FreeEntries* entries(int block) const {
    return blocks_[block + 1].entries.get();
  }
  // The Ceres parameter block of a block (its free entries, or the whole
  // constant block).
  const double* parameters(int block) const {
    return blocks_[block + 1].parameters;
  }

  // Adds `cost` over the pose (when with_pose) and then the listed blocks,
  // each as the problem holds it.  A cost over whole blocks is wrapped in
  // FreeEntriesCost; one that takes the blocks as they are says so.  A cost
  // without a loss over constant blocks only is a constant: it is deleted,
  // not added, and nullptr returned (Ceres would evaluate it once before
  // solving, telling the problem's EvaluationCallback of the start point
  // first: a pass over every point of the frame for nothing).
  enum class Takes { kWholeBlocks, kProblemBlocks };
  ceres::ResidualBlockId AddResidual(ceres::CostFunction* cost,
                                     ceres::LossFunction* loss, bool with_pose,
                                     const std::vector<int>& blocks,
                                     Takes takes = Takes::kWholeBlocks);
  // As AddResidual without the pose, over the caller's own parameter blocks
  // `own` (passed as they are) and then the listed blocks (whole).
  ceres::ResidualBlockId AddResidual(ceres::CostFunction* cost,
                                     const std::vector<double*>& own,
                                     const std::vector<int>& blocks);

  // Calls f(parameter block, its free functions) for each free block.
  template <typename F>
  void ForEachFree(F f) const {
    for (const Block& block : blocks_) {
      if (block.entries) f(block.parameters, block.entries->free());
    }
  }

  // Copies the free entries into the model state.
  void Store() const;

 private:
  struct Block {
    double* parameters = nullptr;
    std::unique_ptr<FreeEntries> entries;  // Null when the block is constant.
  };

  void Add(double* values, const std::vector<int>& held);
  // `cost` over `leading` (passed through) and then the listed blocks.
  ceres::ResidualBlockId Add(ceres::CostFunction* cost,
                             ceres::LossFunction* loss,
                             const std::vector<double*>& leading,
                             const std::vector<int>& blocks, Takes takes);

  Model* model_;
  ceres::Problem* problem_;
  std::vector<Block> blocks_;  // The globals, then the knots.
};

// The integrator's damping: the groups' multipliers per free entry of each
// free block of `blocks`, and for the pose when it is free in `problem`.
void AddDampingScales(const ceres::Problem& problem, const FrameBlocks& blocks,
                      const DampingGroups& groups, Model* model,
                      SolverOptions* solver);

}  // namespace pfdm

#endif  // PFDM_FIT_PROBLEM_FRAME_BLOCKS_H_
