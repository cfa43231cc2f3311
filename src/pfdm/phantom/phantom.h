// A synthetic SPAMM-like LV phantom from known parameter functions.
#ifndef PFDM_PHANTOM_PHANTOM_H_
#define PFDM_PHANTOM_PHANTOM_H_

#include <vector>

#include "pfdm/model/model.h"
#include "pfdm/util/point_data.h"

namespace pfdm {

struct PhantomOptions {
  int num_frames = 5;     // Systole, end-diastole first.
  int num_points = 2000;  // Tags, each tracked through every frame.
  int num_knots = 17;
  double noise_mm = 0.5;  // Gaussian, per coordinate.
  double outlier_fraction = 0.0;
  double outlier_mm = 10.0;  // Outliers move this far in a random direction.
  unsigned seed = 1;
};

struct Phantom {
  PointSequence points;
  std::vector<Model> truth;  // One per frame.
};

// The paper's scale: an LV 110 mm long and 28 mm in radius at end-diastole,
// contracting 20 % radially (the base only 10 % along axis 2), 20 %
// longitudinally, twisting 7 degrees apex to base (the apex turning
// counter-clockwise seen from the apex), the axis drifting 1.5 mm, seen in
// a pose neither axis-aligned nor centred.
Phantom MakePhantom(const PhantomOptions& options);

// The most points (frames x tags) a phantom is made of.
constexpr double kMaxPhantomPoints = 2e7;

// Throws InputError "--FLAG must be between LOW and HIGH, got V" naming
// pfdm simulate's flag (--frames, --tags, --noise, --outliers) of the
// first option that makes no phantom, or "--frames times --tags must be at
// most ..." for more than kMaxPhantomPoints points in all.
void CheckPhantomOptions(const PhantomOptions& options);

}  // namespace pfdm

#endif  // PFDM_PHANTOM_PHANTOM_H_
