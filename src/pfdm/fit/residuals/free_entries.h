// A block of function values (the globals or one knot) whose held entries
// stay out of the solve: the Ceres parameter block is only the free entries.
// Holding entries with ceres::SubsetManifold instead costs a dense product
// of every residual block's Jacobian with the manifold's 14 x m basis, which
// was a third of the Jacobian time of a 50,000-point frame.
#ifndef PFDM_FIT_RESIDUALS_FREE_ENTRIES_H_
#define PFDM_FIT_RESIDUALS_FREE_ENTRIES_H_

#include <memory>
#include <vector>

#include "ceres/cost_function.h"
#include "pfdm/model/parameter_function.h"

namespace pfdm {

class FreeEntries {
 public:
  // values: the whole block, whose held entries are read now and whose
  // free ones Store() writes.  free: the free entries, ascending.
  FreeEntries(double* values, std::vector<int> free);

  // The Ceres parameter block.
  double* parameters() { return free_values_.data(); }
  int size() const { return static_cast<int>(free_.size()); }
  const std::vector<int>& free() const { return free_; }
  // Where entry `function` sits in parameters(), or -1 if it is held.
  int IndexOf(int function) const;

  // The whole block for the free entries in `parameters`.
  void Expand(const double* parameters, double* values) const;
  // Writes the free entries back into the whole block.
  void Store() const;

 private:
  double* values_;
  FunctionValues held_values_;
  std::vector<int> free_;
  std::vector<double> free_values_;
};

// Presents a cost function over whole blocks as one over the free entries
// of those listed (entries[i] == nullptr passes block i through unchanged):
// it expands the parameters, evaluates `inner` and keeps the Jacobian
// columns of the free entries.  Owns `inner`.
class FreeEntriesCost : public ceres::CostFunction {
 public:
  FreeEntriesCost(ceres::CostFunction* inner,
                  std::vector<const FreeEntries*> entries);
  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override;

 private:
  std::unique_ptr<ceres::CostFunction> inner_;
  std::vector<const FreeEntries*> entries_;
};

}  // namespace pfdm

#endif  // PFDM_FIT_RESIDUALS_FREE_ENTRIES_H_
