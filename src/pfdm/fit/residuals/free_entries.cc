#include "pfdm/fit/residuals/free_entries.h"

#include <algorithm>

#include "glog/logging.h"

namespace pfdm {

FreeEntries::FreeEntries(double* values, std::vector<int> free)
    : values_(values), free_(std::move(free)) {
  CHECK(std::is_sorted(free_.begin(), free_.end()));
  std::copy(values, values + kNumFunctions, held_values_.begin());
  for (int f : free_) free_values_.push_back(values[f]);
}

int FreeEntries::IndexOf(int function) const {
  const auto it = std::find(free_.begin(), free_.end(), function);
  return it == free_.end() ? -1 : static_cast<int>(it - free_.begin());
}

void FreeEntries::Expand(const double* parameters, double* values) const {
  std::copy(held_values_.begin(), held_values_.end(), values);
  for (size_t i = 0; i < free_.size(); ++i) values[free_[i]] = parameters[i];
}

void FreeEntries::Store() const {
  for (size_t i = 0; i < free_.size(); ++i) values_[free_[i]] = free_values_[i];
}

FreeEntriesCost::FreeEntriesCost(ceres::CostFunction* inner,
                                 std::vector<const FreeEntries*> entries)
    : inner_(inner), entries_(std::move(entries)) {
  const std::vector<int32_t>& sizes = inner->parameter_block_sizes();
  CHECK_EQ(sizes.size(), entries_.size());
  set_num_residuals(inner->num_residuals());
  for (size_t i = 0; i < sizes.size(); ++i) {
    CHECK(entries_[i] == nullptr || sizes[i] == kNumFunctions);
    mutable_parameter_block_sizes()->push_back(entries_[i] ? entries_[i]->size()
                                                           : sizes[i]);
  }
}

bool FreeEntriesCost::Evaluate(double const* const* parameters,
                               double* residuals, double** jacobians) const {
  const size_t num_blocks = entries_.size();
  const int rows = num_residuals();
  std::vector<FunctionValues> expanded(num_blocks);
  std::vector<const double*> inner_parameters(parameters,
                                              parameters + num_blocks);
  std::vector<std::vector<double>> whole_jacobians(num_blocks);
  std::vector<double*> inner_jacobians(num_blocks, nullptr);
  for (size_t i = 0; i < num_blocks; ++i) {
    if (entries_[i] == nullptr) {
      if (jacobians != nullptr) inner_jacobians[i] = jacobians[i];
      continue;
    }
    entries_[i]->Expand(parameters[i], expanded[i].data());
    inner_parameters[i] = expanded[i].data();
    if (jacobians != nullptr && jacobians[i] != nullptr) {
      whole_jacobians[i].resize(rows * kNumFunctions);
      inner_jacobians[i] = whole_jacobians[i].data();
    }
  }
  if (!inner_->Evaluate(
          inner_parameters.data(), residuals,
          jacobians != nullptr ? inner_jacobians.data() : nullptr)) {
    return false;
  }
  for (size_t i = 0; jacobians != nullptr && i < num_blocks; ++i) {
    if (entries_[i] == nullptr || jacobians[i] == nullptr) continue;
    const std::vector<int>& free = entries_[i]->free();
    const int width = static_cast<int>(free.size());
    for (int r = 0; r < rows; ++r) {
      const double* whole = &whole_jacobians[i][r * kNumFunctions];
      double* kept = jacobians[i] + r * width;
      for (int c = 0; c < width; ++c) kept[c] = whole[free[c]];
    }
  }
  return true;
}

}  // namespace pfdm
