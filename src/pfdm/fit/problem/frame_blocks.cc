#include "pfdm/fit/problem/frame_blocks.h"

#include <algorithm>
#include <limits>
#include <utility>

namespace pfdm {
namespace {

bool Contains(const std::vector<int>& list, int value) {
  return std::find(list.begin(), list.end(), value) != list.end();
}

}  // namespace

FrameBlocks::FrameBlocks(FrameKind kind, Model* model, ceres::Problem* problem)
    : model_(model), problem_(problem) {
  ModelState& state = model->state;
  problem->AddParameterBlock(state.center.data(), 3);
  problem->AddParameterBlock(state.quaternion.data(), 4,
                             new ceres::QuaternionManifold);
  Add(state.globals.data(), HeldEntries(model->config, kind, kGlobalsBlock));
  for (int k = 0; k < model->config.num_knots; ++k) {
    Add(state.knots[k].data(), HeldEntries(model->config, kind, k));
  }
}

ceres::ResidualBlockId FrameBlocks::AddResidual(ceres::CostFunction* cost,
                                                ceres::LossFunction* loss,
                                                bool with_pose,
                                                const std::vector<int>& blocks,
                                                Takes takes) {
  std::vector<double*> pose;
  if (with_pose) {
    pose = {model_->state.center.data(), model_->state.quaternion.data()};
  }
  return Add(cost, loss, pose, blocks, takes);
}

ceres::ResidualBlockId FrameBlocks::AddResidual(
    ceres::CostFunction* cost, const std::vector<double*>& own,
    const std::vector<int>& blocks) {
  return Add(cost, nullptr, own, blocks, Takes::kWholeBlocks);
}

ceres::ResidualBlockId FrameBlocks::Add(ceres::CostFunction* cost,
                                        ceres::LossFunction* loss,
                                        const std::vector<double*>& leading,
                                        const std::vector<int>& blocks,
                                        Takes takes) {
  std::vector<double*> parameters = leading;
  std::vector<const FreeEntries*> entries(leading.size(), nullptr);
  bool compact = false;
  for (int b : blocks) {
    const Block& block = blocks_[b + 1];
    parameters.push_back(block.parameters);
    entries.push_back(block.entries.get());
    compact = compact || block.entries != nullptr;
  }
  if (loss == nullptr && !compact &&
      std::all_of(parameters.begin(), parameters.end(),
                  [this](double* parameter) {
                    return problem_->IsParameterBlockConstant(parameter);
                  })) {
    delete cost;
    return nullptr;
  }
  if (compact && takes == Takes::kWholeBlocks) {
    cost = new FreeEntriesCost(cost, std::move(entries));
  }
  return problem_->AddResidualBlock(cost, loss, parameters);
}

void FrameBlocks::Store() const {
  for (const Block& block : blocks_) {
    if (block.entries) block.entries->Store();
  }
}

void FrameBlocks::Add(double* values, const std::vector<int>& held) {
  Block block;
  std::vector<int> free;
  for (int f = 0; f < kNumFunctions; ++f) {
    if (!Contains(held, f)) free.push_back(f);
  }
  if (free.empty()) {
    block.parameters = values;
    problem_->AddParameterBlock(values, kNumFunctions);
    problem_->SetParameterBlockConstant(values);
    blocks_.push_back(std::move(block));
    return;
  }
  block.entries = std::make_unique<FreeEntries>(values, std::move(free));
  block.parameters = block.entries->parameters();
  problem_->AddParameterBlock(block.parameters, block.entries->size());
  auto bound = [&](int f, double lower, double upper) {
    const int index = block.entries->IndexOf(f);
    if (index < 0) return;
    problem_->SetParameterLowerBound(block.parameters, index, lower);
    problem_->SetParameterUpperBound(block.parameters, index, upper);
  };
  for (int f : {kA1, kA2, kA3}) bound(f, 1e-3, 1.0);
  for (int f : {kEps1, kEps2}) bound(f, 0.1, 4.0);
  // A wall may thin to nothing (where both walls' long-axis contours end
  // together at the valve's hinge), never turn inside out: biv-me's both
  // walls read h down to -5 mm at the top knot without this floor.
  bound(kH, 0.0, std::numeric_limits<double>::max());
  blocks_.push_back(std::move(block));
}

void AddDampingScales(const ceres::Problem& problem, const FrameBlocks& blocks,
                      const DampingGroups& groups, Model* model,
                      SolverOptions* solver) {
  blocks.ForEachFree([&](double* block, const std::vector<int>& free) {
    std::vector<double>& scales = solver->damping_scale[block];
    for (int f : free) scales.push_back(groups.Of(Function(f)));
  });
  for (double* pose :
       {model->state.center.data(), model->state.quaternion.data()}) {
    if (problem.IsParameterBlockConstant(pose)) continue;
    solver->damping_scale[pose].assign(problem.ParameterBlockTangentSize(pose),
                                       groups.pose);
  }
}

}  // namespace pfdm
