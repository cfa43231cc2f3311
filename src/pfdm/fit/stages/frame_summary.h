// The last stage of a frame's fit: its residuals and distances on the final
// model, and the check that they are finite.
#ifndef PFDM_FIT_STAGES_FRAME_SUMMARY_H_
#define PFDM_FIT_STAGES_FRAME_SUMMARY_H_

#include <string>
#include <vector>

#include "Eigen/Core"
#include "pfdm/fit/stages/sequence_fit.h"
#include "pfdm/model/model.h"

namespace pfdm {

// Sets fit's residuals (model minus data at fit->material), RMS, mean and
// largest distance, and its state to model's.
void Summarize(const Model& model, const std::vector<Eigen::Vector3d>& points,
               FrameFit* fit);

// Never a silent absurd fit (an infinite RMS once printed CONVERGENCE):
// throws InputError naming the source and frame when the summary or the
// state is not finite.
void CheckFinite(const std::string& source, const FrameFit& fit);

}  // namespace pfdm

#endif  // PFDM_FIT_STAGES_FRAME_SUMMARY_H_
