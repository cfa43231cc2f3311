// Whether the data reach the apex: a fit of a mid-ventricular segment (no
// apex) closes its cup below the data, and what it says there is
// extrapolated.
#ifndef PFDM_FIT_STAGES_APEX_COVERAGE_H_
#define PFDM_FIT_STAGES_APEX_COVERAGE_H_

#include <vector>

#include "Eigen/Core"
#include "pfdm/fit/stages/sequence_fit.h"

namespace pfdm {

// The apex counts as seen when at least kApexPoints of frame 0's points lie
// within kApexReach of the model's length (apex pole to base rim) of the
// apex pole: long-axis contours and tags reach it, a short-axis stack's
// lowest slice if it is low enough (5 % of the length up: 12 % away); a
// mid-ventricular segment (30 % up, 45 mm across) does not, wherever the
// fit closes its cup below the data.  (Heights alone would not do: a fit
// without an apex may close its cup within 15 % of the length below the
// data.)
constexpr double kApexReach = 0.15;
constexpr int kApexPoints = 3;

// Whether at least kApexPoints of `points` lie within `reach` of the
// model's length of its apex pole: with kApexReach MeasureApexCoverage's
// test, asked of any model (FitFrame asks it of frame 0's start).
bool ApexInData(const Model& model, const std::vector<Eigen::Vector3d>& points,
                double reach = kApexReach);

// Sets fit->apex_in_data, apex_data_distance, lowest_data_height,
// highest_data_height and lowest_data_u from frame
// 0's points (`points`, in the order of fit->frames[0].material) and its
// fitted model; heights along the model's axis, which frame 0 does not bend.
void MeasureApexCoverage(const std::vector<Eigen::Vector3d>& points,
                         SequenceFit* fit);

}  // namespace pfdm

#endif  // PFDM_FIT_STAGES_APEX_COVERAGE_H_
