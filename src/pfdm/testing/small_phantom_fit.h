// One small phantom fit shared by the tests of what a fit writes (fit.json,
// the output set): fitted once per test binary, not once per test file.
#ifndef PFDM_TESTING_SMALL_PHANTOM_FIT_H_
#define PFDM_TESTING_SMALL_PHANTOM_FIT_H_

#include "pfdm/fit/stages/fitter.h"
#include "pfdm/model/model.h"
#include "pfdm/phantom/phantom.h"

namespace pfdm {

struct FittedPhantom {
  Phantom phantom;
  SequenceFit fit;
};

// Three frames of 600 tags, fitted with the paper's model of 17 knots and
// the default options.
inline const FittedPhantom& SmallPhantomFit() {
  static const FittedPhantom* fitted = [] {
    PhantomOptions options;
    options.num_frames = 3;
    options.num_points = 600;
    auto* f = new FittedPhantom{MakePhantom(options), {}};
    f->fit =
        FitSequence(f->phantom.points, ModelConfig::Paper(17), FitOptions());
    return f;
  }();
  return *fitted;
}

}  // namespace pfdm

#endif  // PFDM_TESTING_SMALL_PHANTOM_FIT_H_
