#include "pfdm/phantom/phantom.h"

#include <cmath>

#include "gtest/gtest.h"
#include "pfdm/fit/correspondence/correspondence.h"
#include "pfdm/util/error.h"

namespace pfdm {
namespace {

TEST(PhantomTest, NoiseFreeTagsLieOnTheTruthAndKeepTheirIds) {
  PhantomOptions options;
  options.noise_mm = 0.0;
  options.num_points = 300;
  const Phantom phantom = MakePhantom(options);
  ASSERT_EQ(phantom.points.frames.size(), 5u);
  for (size_t t = 0; t < 5; ++t) {
    const Frame& frame = phantom.points.frames[t];
    ASSERT_EQ(frame.points.size(), 300u);
    EXPECT_EQ(frame.index, static_cast<int>(t));
    std::vector<Eigen::Vector3d> positions;
    for (size_t i = 0; i < frame.points.size(); ++i) {
      EXPECT_EQ(frame.points[i].id, static_cast<int>(i));
      positions.push_back(frame.points[i].position);
    }
    // Searched to the end: the default stops within 1e-4 mm.
    CorrespondenceOptions exhaustive;
    exhaustive.step_tolerance_mm = 0.0;
    const auto material =
        ClosestMaterialPoints(phantom.truth[t], positions, exhaustive);
    for (size_t i = 0; i < positions.size(); ++i) {
      EXPECT_LT((phantom.truth[t].WorldPoint(material[i].u, material[i].v) -
                 positions[i])
                    .norm(),
                1e-6);
    }
  }
}

TEST(PhantomTest, NoiseHasTheRequestedSpread) {
  PhantomOptions clean, noisy;
  clean.noise_mm = 0.0;
  noisy.noise_mm = 0.5;
  const Phantom a = MakePhantom(clean), b = MakePhantom(noisy);
  double sum_squared = 0.0;
  int count = 0;
  for (size_t i = 0; i < a.points.frames[2].points.size(); ++i) {
    sum_squared += (a.points.frames[2].points[i].position -
                    b.points.frames[2].points[i].position)
                       .squaredNorm();
    count += 3;
  }
  EXPECT_NEAR(std::sqrt(sum_squared / count), 0.5, 0.03);
}

TEST(PhantomTest, SizeMatchesThePaper) {
  const Phantom phantom = MakePhantom(PhantomOptions());
  const Model& ed = phantom.truth[0];
  const double length =
      (ed.WorldPoint(ed.config.u_max, 0.0) - ed.WorldPoint(-M_PI / 2, 0.0))
          .dot(ed.Rotation().col(2));
  EXPECT_NEAR(length, 110.0, 1e-9);
}

// Refused before anything is allocated: 1,000 frames of 1e6 tags would be
// 40 GB.  2e7 points in all is the bound, frames x tags of 20 x 1e6 passes.
TEST(PhantomTest, TooManyPointsInAllAreRefusedUpFront) {
  PhantomOptions options;
  options.num_frames = 1000;
  options.num_points = 1000000;
  try {
    CheckPhantomOptions(options);
    FAIL() << "not refused";
  } catch (const InputError& error) {
    EXPECT_STREQ(error.what(),
                 "--frames times --tags must be at most 2e+07 points, got "
                 "1000 x 1000000");
  }
  options.num_frames = 20;
  EXPECT_NO_THROW(CheckPhantomOptions(options));
  options.num_frames = 21;
  EXPECT_THROW(CheckPhantomOptions(options), InputError);
}

}  // namespace
}  // namespace pfdm
