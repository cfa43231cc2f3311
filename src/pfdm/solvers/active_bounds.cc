#include "pfdm/solvers/active_bounds.h"

#include <algorithm>
#include <limits>
#include <map>

#include "ceres/manifold.h"

namespace pfdm {
namespace {

// Ceres' value for "no bound".
constexpr double kNoBound = std::numeric_limits<double>::max();

}  // namespace

ActiveBounds::ActiveBounds(ceres::Problem* problem) : problem_(problem) {
  std::vector<double*> blocks;
  problem_->GetParameterBlocks(&blocks);
  for (double* block : blocks) {
    if (problem_->IsParameterBlockConstant(block) ||
        problem_->HasManifold(block)) {
      continue;
    }
    for (int i = 0; i < problem_->ParameterBlockSize(block); ++i) {
      const double lower = problem_->GetParameterLowerBound(block, i);
      const double upper = problem_->GetParameterUpperBound(block, i);
      if (lower > -kNoBound || upper < kNoBound) {
        entries_.push_back({block, i, lower, upper});
      }
    }
  }
}

ActiveBounds::~ActiveBounds() {
  for (const auto& [block, indices] : applied_) {
    if (!indices.empty()) problem_->SetManifold(block, nullptr);
  }
}

int ActiveBounds::held() const {
  return static_cast<int>(std::count_if(entries_.begin(), entries_.end(),
                                        [](const Entry& e) { return e.held; }));
}

bool ActiveBounds::AtBound(const Entry& entry) const {
  const double value = entry.block[entry.index];
  return value <= entry.lower || value >= entry.upper;
}

bool ActiveBounds::NewlyActive() {
  bool active = false;
  for (Entry& entry : entries_) {
    if (entry.released && !AtBound(entry)) entry.released = false;
    active = active || Active(entry);
  }
  return active;
}

int ActiveBounds::HoldActive() {
  std::map<double*, int> held_per_block;
  for (const Entry& entry : entries_) {
    if (entry.held) ++held_per_block[entry.block];
  }
  int newly = 0;
  for (Entry& entry : entries_) {
    if (!Active(entry)) continue;
    int& held = held_per_block[entry.block];
    if (held + 1 >= problem_->ParameterBlockSize(entry.block)) continue;
    entry.held = true;
    ++held;
    ++newly;
  }
  if (newly > 0) ApplyHolds();
  return newly;
}

int ActiveBounds::ReleaseInward() {
  std::vector<double*> blocks;
  for (const auto& [block, indices] : applied_) {
    if (!indices.empty()) blocks.push_back(block);
  }
  if (blocks.empty()) return 0;
  for (double* block : blocks) SetHeld(block, {});
  ceres::Problem::EvaluateOptions options;
  options.parameter_blocks = blocks;
  std::vector<double> gradient;
  double cost = 0.0;
  problem_->Evaluate(options, &cost, nullptr, &gradient, nullptr);
  std::map<double*, int> offset;
  int at = 0;
  for (double* block : blocks) {
    offset[block] = at;
    at += problem_->ParameterBlockSize(block);
  }
  int released = 0;
  for (Entry& entry : entries_) {
    if (!entry.held) continue;
    const double g = gradient[offset[entry.block] + entry.index];
    const bool at_lower = entry.block[entry.index] <= entry.lower;
    // Moving into the box lowers the cost: the bound holds nothing back.
    if ((at_lower && g < 0.0) || (!at_lower && g > 0.0)) {
      entry.held = false;
      entry.released = true;
      ++released;
    }
  }
  ApplyHolds();
  return released;
}

void ActiveBounds::ApplyHolds() {
  std::map<double*, std::vector<int>> held;
  for (const Entry& entry : entries_) {
    if (entry.held) held[entry.block].push_back(entry.index);
  }
  for (const auto& [block, indices] : applied_) {
    if (!indices.empty() && !held.count(block)) SetHeld(block, {});
  }
  for (const auto& [block, indices] : held) SetHeld(block, indices);
}

void ActiveBounds::SetHeld(double* block, const std::vector<int>& indices) {
  std::vector<int>& applied = applied_[block];
  if (applied == indices) return;
  problem_->SetManifold(
      block, indices.empty()
                 ? nullptr
                 : new ceres::SubsetManifold(
                       problem_->ParameterBlockSize(block), indices));
  applied = indices;
}

}  // namespace pfdm
