#include "pfdm/fit/stages/tracked_ids.h"

#include <algorithm>
#include <cstdio>
#include <random>
#include <string>

#include "gtest/gtest.h"
#include "pfdm/fit/stages/fitter.h"
#include "pfdm/io/mesh_source.h"
#include "pfdm/io/point_reader.h"
#include "pfdm/phantom/lv_phantom.h"
#include "pfdm/phantom/phantom.h"
#include "pfdm/testing/test_util.h"
#include "pfdm/util/error.h"

namespace pfdm {
namespace {

// The largest share of the data's radius and of the nearest-neighbour
// distance that any frame's ids moved by, printed for the record.
struct Worst {
  double of_radius = 0.0, of_nearest = 0.0;
};

Worst WorstMotion(const PointSequence& sequence) {
  Worst worst;
  for (size_t t = 1; t < sequence.frames.size(); ++t) {
    const IdMotion m =
        MeasureIdMotion(sequence.frames[t - 1], sequence.frames[t]);
    EXPECT_GE(m.shared, 10) << sequence.source << " frame " << t;
    worst.of_radius = std::max(worst.of_radius, m.by_id_mm / m.radius_mm);
    worst.of_nearest = std::max(worst.of_nearest, m.by_id_mm / m.nearest_mm);
  }
  std::printf(
      "%s: ids moved at most %.3f of the radius, %.2f times the "
      "nearest-neighbour distance\n",
      sequence.source.c_str(), worst.of_radius, worst.of_nearest);
  return worst;
}

// The frame's ids permuted among its points.
void ScrambleIds(Frame* frame, unsigned seed) {
  std::vector<std::int64_t> ids;
  for (const DataPoint& p : frame->points) ids.push_back(p.id);
  std::mt19937 random(seed);
  std::shuffle(ids.begin(), ids.end(), random);
  for (size_t i = 0; i < ids.size(); ++i) frame->points[i].id = ids[i];
}

LvPhantom LvSystole(LvTagLayer tags) {
  LvPhantomOptions options;
  options.tags = tags;
  return MakeLvPhantom(options);
}

// Measured frame to frame: the model phantom's ids move at most 0.069 of
// the radius and 1.35 times the nearest-neighbour distance, the LV
// phantom's (systole with breathing) 0.073 and 1.49 with mid-wall tags,
// 0.070 and 1.27 with tags through the wall; the bound is 0.5 and 4.
TEST(TrackedIdsTest, PhantomsIdsFollowTheirPoints) {
  for (const PointSequence& points : {MakePhantom(PhantomOptions()).points,
                                      LvSystole(LvTagLayer::kMidwall).points,
                                      LvSystole(LvTagLayer::kWall).points}) {
    const Worst worst = WorstMotion(points);
    EXPECT_LT(worst.of_radius, 0.1) << points.source;
    EXPECT_LT(worst.of_nearest, 2.0) << points.source;
    EXPECT_NO_THROW(CheckIdsFollowPoints(points)) << points.source;
  }
}

// A permutation moves the median point by more than the radius and leaves
// the nearest neighbours where they were.
TEST(TrackedIdsTest, IdsScrambledInOneFrameAreAnInputErrorNamingIt) {
  LvPhantom phantom = LvSystole(LvTagLayer::kMidwall);
  phantom.points.source = "tags.csv";
  ScrambleIds(&phantom.points.frames[2], 3);
  const IdMotion m =
      MeasureIdMotion(phantom.points.frames[1], phantom.points.frames[2]);
  std::printf(
      "scrambled: %.1f mm by id, %.2f mm to the nearest, radius "
      "%.1f mm\n",
      m.by_id_mm, m.nearest_mm, m.radius_mm);
  EXPECT_GT(m.by_id_mm, 0.9 * m.radius_mm);
  EXPECT_GT(m.by_id_mm, 10.0 * m.nearest_mm);
  EXPECT_TRUE(IdsScrambled(m));
  try {
    FitSequence(phantom.points, ModelConfig::Paper(17), FitOptions());
    FAIL() << "not refused";
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_EQ(message.rfind("tags.csv: frame 2: the point ids do not follow "
                            "the points of frame 1 (scrambled?): ",
                            0),
              0u)
        << message;
    EXPECT_EQ(message.find('\n'), std::string::npos);
  }
}

// A frame moved far away with its ids kept is not scrambled: the nearest
// points moved with it.
TEST(TrackedIdsTest, AFrameMovedFarKeepsItsIds) {
  PointSequence points = MakePhantom(PhantomOptions()).points;
  for (DataPoint& p : points.frames[3].points) {
    p.position += Eigen::Vector3d(300.0, 0.0, 0.0);
  }
  const IdMotion m = MeasureIdMotion(points.frames[2], points.frames[3]);
  EXPECT_GT(m.by_id_mm, 0.5 * m.radius_mm);
  EXPECT_FALSE(IdsScrambled(m));
}

// The nearest points' tree is built, where asked only if needed, only
// where the ids moved by half the radius: not between any two frames of a
// phantom, whose motion without it is the same but for nearest_mm; for a
// scrambled frame and a frame moved far away it is, and tells the two
// apart.
TEST(TrackedIdsTest, TheNearestPointsAreMeasuredOnlyWhereIdsMovedFar) {
  LvPhantom phantom = LvSystole(LvTagLayer::kMidwall);
  const std::vector<Frame>& frames = phantom.points.frames;
  for (size_t t = 1; t < frames.size(); ++t) {
    const IdMotion full = MeasureIdMotion(frames[t - 1], frames[t]);
    const IdMotion cheap = MeasureIdMotion(frames[t - 1], frames[t], true);
    EXPECT_FALSE(MayBeScrambled(cheap)) << t;
    EXPECT_EQ(cheap.shared, full.shared) << t;
    EXPECT_EQ(cheap.by_id_mm, full.by_id_mm) << t;
    EXPECT_EQ(cheap.radius_mm, full.radius_mm) << t;
    EXPECT_EQ(cheap.nearest_mm, 0.0) << t;
    EXPECT_GT(full.nearest_mm, 0.0) << t;
  }
  Frame moved = frames[2];
  for (DataPoint& p : moved.points) p.position += Eigen::Vector3d(300, 0, 0);
  Frame scrambled = frames[2];
  ScrambleIds(&scrambled, 3);
  for (const Frame* after : {&moved, &scrambled}) {
    const IdMotion full = MeasureIdMotion(frames[1], *after);
    const IdMotion if_needed = MeasureIdMotion(frames[1], *after, true);
    EXPECT_TRUE(MayBeScrambled(if_needed));
    EXPECT_EQ(if_needed.nearest_mm, full.nearest_mm);
    EXPECT_EQ(IdsScrambled(if_needed), after == &scrambled);
  }
}

TEST(TrackedIdsTest, ContoursShareNoIds) {
  PointSequence points;
  points.frames.resize(2);
  for (int t = 0; t < 2; ++t) {
    for (int i = 0; i < 50; ++i) {
      points.frames[t].points.push_back(
          {t * 50 + i, Eigen::Vector3d(i, (i * 7) % 11, t)});
    }
  }
  EXPECT_EQ(MeasureIdMotion(points.frames[0], points.frames[1]).shared, 0);
  EXPECT_NO_THROW(CheckIdsFollowPoints(points));
}

// Real meshes with corresponding vertices: biv-me's 25 fitted LV
// endocardia and the CAP mean shape's ED and ES endocardium.  Measured:
// at most 0.086 of the radius and 1.73 times the nearest-neighbour
// distance (biv-me, frame to frame), 0.255 and 1.12 (CAP, ED to ES).
// biv-me's contours number their points afresh in every frame.
TEST(TrackedIdsTest, RealMeshVerticesFollowTheirPoints) {
  const std::string shared = SharedDataDirectory();
  if (shared.empty()) GTEST_SKIP() << "../shared/data is absent";
  MeshSettings biv_me;
  biv_me.mesh_filter = "LV_ENDOCARDIAL";
  for (const PointSequence& points :
       {ReadMeshPoints(shared + "/biv-me-patient1/obj", biv_me),
        ReadMeshPoints(shared + "/cap-lv-mean/mean_shape.csv",
                       MeshSettings())}) {
    const Worst worst = WorstMotion(points);
    EXPECT_LT(worst.of_radius, 0.3) << points.source;
    EXPECT_LT(worst.of_nearest, 2.0) << points.source;
    EXPECT_NO_THROW(CheckIdsFollowPoints(points)) << points.source;
  }
  const PointSequence contours =
      ReadGpFiles(shared + "/biv-me-patient1/guidepoints", {});
  ASSERT_EQ(contours.frames.size(), 25u);
  EXPECT_EQ(MeasureIdMotion(contours.frames[0], contours.frames[1]).shared, 0);
  EXPECT_NO_THROW(CheckIdsFollowPoints(contours));
}

}  // namespace
}  // namespace pfdm
