#include "pfdm/fit/stages/sequence_fit.h"

#include <cstdio>

namespace pfdm {

void AddSolverCounts(const SolverReport& report, FrameFit* fit) {
  fit->iterations += report.iterations;
  fit->residual_evaluations += report.residual_evaluations;
  fit->jacobian_evaluations += report.jacobian_evaluations;
  fit->evaluation_seconds += report.evaluation_seconds;
  fit->linear_solver_seconds += report.linear_solver_seconds;
  fit->minimizer_seconds += report.minimizer_seconds;
}

std::string UnsettledNote(const FrameFit& frame) {
  if (frame.unsettled_mm <= 0.0) return "";
  char text[80];
  std::snprintf(text, sizeof(text),
                "; closest points unsettled (%.2f mm in the last search)",
                frame.unsettled_mm);
  return text;
}

double LengthVariance(const SequenceFit& fit, size_t t) {
  if (t != 0 && !fit.frames[t].tracked) return 0.0;
  return fit.frames[0].covariance.LengthNoiseVariance();
}

}  // namespace pfdm
