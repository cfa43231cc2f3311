// The model states kept along a frame's solver path
// (FitOptions::trajectory_per_decade).
#ifndef PFDM_FIT_STAGES_TRAJECTORY_RECORDER_H_
#define PFDM_FIT_STAGES_TRAJECTORY_RECORDER_H_

#include <vector>

#include "pfdm/fit/stages/sequence_fit.h"
#include "pfdm/model/model.h"

namespace pfdm {

// Keeps the model state at log-spaced iterations of a frame's path, and
// the last one, which is where the frame ends.
class TrajectoryRecorder {
 public:
  // *model is read at every step.  With per_decade 0 nothing is recorded:
  // the caller steps it not at all (GlobalRounds) and Finish adds nothing.
  TrajectoryRecorder(int per_decade, const Model* model,
                     std::vector<TrajectoryPoint>* trajectory);

  void Step(int iteration, double pseudo_time);
  // Keeps the last step seen, when it is not kept already.
  void Finish();

 private:
  double ratio_;
  const Model* model_;
  std::vector<TrajectoryPoint>* trajectory_;
  TrajectoryPoint latest_;
  double next_ = 0.0;
};

}  // namespace pfdm

#endif  // PFDM_FIT_STAGES_TRAJECTORY_RECORDER_H_
