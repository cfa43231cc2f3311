#include "pfdm/fit/stages/trajectory_recorder.h"

#include <algorithm>
#include <cmath>

namespace pfdm {

TrajectoryRecorder::TrajectoryRecorder(int per_decade, const Model* model,
                                       std::vector<TrajectoryPoint>* trajectory)
    : ratio_(per_decade > 0 ? std::pow(10.0, 1.0 / per_decade) : 0.0),
      model_(model),
      trajectory_(trajectory) {}

void TrajectoryRecorder::Step(int iteration, double pseudo_time) {
  latest_ = {iteration, pseudo_time, model_->state};
  if (iteration + 1.0 < next_) return;
  trajectory_->push_back(latest_);
  next_ = std::max(next_ + 1.0, (iteration + 1.0) * ratio_);
}

void TrajectoryRecorder::Finish() {
  if (ratio_ > 0.0 && (trajectory_->empty() ||
                       trajectory_->back().iteration != latest_.iteration)) {
    trajectory_->push_back(latest_);
  }
}

}  // namespace pfdm
