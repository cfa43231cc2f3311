// Small models shared by the tests.
#ifndef PFDM_TESTING_TEST_MODELS_H_
#define PFDM_TESTING_TEST_MODELS_H_

#include <cmath>

#include "Eigen/Geometry"
#include "pfdm/model/local_field.h"
#include "pfdm/model/model.h"
#include "pfdm/phantom/lv_phantom.h"
#include "pfdm/phantom/phantom.h"

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

// A solid spherical shell: mid-wall radius 30 mm, wall 10 mm (25 to 35
// mm), no twist, bending or offsets, at the identity pose.
inline Model TestShell(int num_knots) {
  ModelConfig config = ModelConfig::Paper(num_knots);
  config.MakeSolid();
  FunctionValues f = DefaultFunctionValues();
  f[kA0] = 60.0;
  f[kA1] = f[kA2] = f[kA3] = 0.5;
  f[kH] = 10.0;
  return Model::Uniform(config, f);
}

// A local field's grid of rows x cols nodes over the model's u range.
inline LocalGrid GridOver(const ModelConfig& config, int rows, int cols) {
  LocalGrid grid;
  grid.rows = rows;
  grid.cols = cols;
  grid.u_min = config.u_min;
  grid.u_max = config.u_max;
  return grid;
}

// Gives the model a local field of 5 x 8 nodes over its u range, node
// values amplitude sin(1.7 i) mm: uneven, nowhere zero by accident.
inline void AddTestLocalField(double amplitude, Model* model) {
  model->state.local = LocalField::Zero(GridOver(model->config, 5, 8));
  for (size_t i = 0; i < model->state.local.values.size(); ++i) {
    model->state.local.values[i] = amplitude * std::sin(1.7 * i);
  }
}

// `model` with each knot of its own (a1, a2, a3 and the twist tau = twist
// k vary along u, the radii scaled by `scale`), a local field, and a pose
// off the identity: a frame's or end-diastole's model for the
// measurements' tests.
inline Model UnevenTestModel(Model model, double scale, double twist) {
  for (size_t k = 0; k < model.state.knots.size(); ++k) {
    FunctionValues& f = model.state.knots[k];
    f[kA1] *= scale * (1.0 + 0.05 * std::sin(1.3 * k));
    f[kA2] *= scale * (1.0 + 0.04 * std::cos(0.7 * k));
    f[kA3] *= 1.0 + 0.03 * std::sin(0.9 * k);
    f[kTau] = twist * k;
  }
  AddTestLocalField(0.8, &model);
  model.state.center = {1.0, -2.0, 3.0};
  const Eigen::Quaterniond q(
      Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 0.5).normalized()));
  model.state.quaternion = {q.w(), q.x(), q.y(), q.z()};
  return model;
}

// The default phantom with num_points points over num_frames frames.
inline Phantom MakeTestPhantom(int num_points, int num_frames) {
  PhantomOptions options;
  options.num_points = num_points;
  options.num_frames = num_frames;
  return MakePhantom(options);
}

// The default phantom's frame 3: twisted, offset and contracted.
inline Model TwistedTestModel() { return MakeTestPhantom(1, 5).truth[3]; }

// The independent LV phantom's mid-wall tags at ED and ES.
inline PointSequence LvTwoFrameTags(int num_tags, int seed, double noise_mm) {
  LvPhantomOptions lv;
  lv.num_frames = 2;
  lv.num_tags = num_tags;
  lv.seed = seed;
  lv.noise_mm = noise_mm;
  return MakeLvPhantom(lv).points;
}

}  // namespace pfdm

#endif  // PFDM_TESTING_TEST_MODELS_H_
