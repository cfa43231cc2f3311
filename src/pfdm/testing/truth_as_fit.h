// A phantom's true states dressed as a converged fit, for the analysis and
// report tests: the numbers they derive from states, without a fit's error.
#ifndef PFDM_TESTING_TRUTH_AS_FIT_H_
#define PFDM_TESTING_TRUTH_AS_FIT_H_

#include "pfdm/fit/stages/sequence_fit.h"
#include "pfdm/phantom/phantom.h"

namespace pfdm {

inline SequenceFit TruthAsFit(const Phantom& phantom) {
  SequenceFit fit;
  fit.config = phantom.truth[0].config;
  for (size_t t = 0; t < phantom.truth.size(); ++t) {
    FrameFit frame;
    frame.frame = static_cast<int>(t);
    frame.state = phantom.truth[t].state;
    frame.termination = "CONVERGENCE";
    fit.frames.push_back(frame);
  }
  return fit;
}

}  // namespace pfdm

#endif  // PFDM_TESTING_TRUTH_AS_FIT_H_
