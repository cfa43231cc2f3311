// Small models shared by the tests.
#ifndef PFDM_TESTING_TEST_MODELS_H_
#define PFDM_TESTING_TEST_MODELS_H_

#include "pfdm/model/model.h"

namespace pfdm {

// The paper model with every knot alike: a spheroid of equatorial radius
// 25 mm and half length 40 mm (a0 = 50, a1 = a2 = 0.5, a3 = 0.8), no
// twist, bending or offsets, at the identity pose.
inline Model TestSpheroid(int num_knots) {
  FunctionValues values = DefaultFunctionValues();
  values[kA0] = 50.0;
  values[kA1] = values[kA2] = 0.5;
  values[kA3] = 0.8;
  return Model::Uniform(ModelConfig::Paper(num_knots), values);
}

}  // namespace pfdm

#endif  // PFDM_TESTING_TEST_MODELS_H_
