// A problem's bounded entries as an active set for the direct solve.
// Ceres clips a step that leaves the box and goes on from the clipped
// point; the other entries then move as the unclipped step had them, and
// where the data press on a bound the solve zig-zags toward the
// constrained minimum: biv-me's both walls, whose solid's thickness h rests
// at its floor 0 at the top knot in frames 2-12, took 100-237 iterations a
// frame that way against 10-20.  An entry held at its bound (a
// SubsetManifold) leaves the steps' linear system, and the others' steps
// are the constrained problem's own.
#ifndef PFDM_SOLVERS_ACTIVE_BOUNDS_H_
#define PFDM_SOLVERS_ACTIVE_BOUNDS_H_

#include <map>
#include <vector>

#include "ceres/problem.h"

namespace pfdm {

class ActiveBounds {
 public:
  // Lists the bounded entries of `problem`'s variable blocks that have no
  // manifold of their own.  `problem` must outlive this.
  explicit ActiveBounds(ceres::Problem* problem);
  // Releases whatever is held: the problem is as it was given.
  ~ActiveBounds();
  ActiveBounds(const ActiveBounds&) = delete;
  ActiveBounds& operator=(const ActiveBounds&) = delete;

  bool empty() const { return entries_.empty(); }
  int held() const;

  // Whether an entry not held sits at one of its bounds, after an iterate
  // (one released there not until it has left it: it starts the next solve
  // there).
  bool NewlyActive();
  // Holds every such entry at its bound (a block's last free entry
  // excepted: a block held whole is Ceres' to clip); returns how many it
  // newly holds.
  int HoldActive();
  // Releases the held entries whose cost gradient points into the box (the
  // data pull them off the bound); returns how many.  One evaluation of the
  // held blocks' gradient.
  int ReleaseInward();

 private:
  struct Entry {
    double* block;
    int index;
    double lower, upper;
    bool held = false;
    bool released = false;  // On its bound, the data pulling it inside.
  };
  bool Active(const Entry& entry) const {
    return !entry.held && !entry.released && AtBound(entry);
  }
  bool AtBound(const Entry& entry) const;
  // Sets each block's SubsetManifold to its held entries, or none, where
  // that changed.
  void ApplyHolds();
  void SetHeld(double* block, const std::vector<int>& indices);

  ceres::Problem* problem_;
  std::vector<Entry> entries_;
  std::map<double*, std::vector<int>> applied_;  // The manifolds as set.
};

}  // namespace pfdm

#endif  // PFDM_SOLVERS_ACTIVE_BOUNDS_H_
