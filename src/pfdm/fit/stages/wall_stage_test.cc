#include "pfdm/fit/stages/wall_stage.h"

#include <algorithm>
#include <cstdio>
#include <random>
#include <string>

#include "gtest/gtest.h"
#include "pfdm/fit/correspondence/correspondence.h"
#include "pfdm/fit/correspondence/held_depths.h"
#include "pfdm/fit/correspondence/transmural.h"
#include "pfdm/testing/stretched_noise.h"
#include "pfdm/testing/test_models.h"
#include "pfdm/testing/test_util.h"

namespace pfdm {
namespace {

std::string FormatSpread(double mm) {
  char text[32];
  std::snprintf(text, sizeof(text), "tags spread %.1f", mm);
  return text;
}

Frame FrameOf(const std::vector<WallLayer>& layers) {
  Frame frame;
  for (size_t i = 0; i < layers.size(); ++i) {
    DataPoint p;
    p.id = static_cast<std::int64_t>(i);
    p.layer = layers[i];
    frame.points.push_back(p);
  }
  return frame;
}

struct ContourCase {
  WallModel wall;
  std::vector<WallLayer> layers;
  bool has_tags;
};

WallDecision FromContours(const ContourCase& c, ModelConfig* config) {
  FitOptions options;
  options.wall = c.wall;
  return DecideWallFromContours(FrameOf(c.layers), c.has_tags, options,
                                "guidepoints", config);
}

TEST(WallStageTest, ContoursDecideTheWallBeforeAnyFit) {
  const WallLayer endo = WallLayer::kEndocardium;
  const WallLayer epi = WallLayer::kEpicardium;
  const WallLayer any = WallLayer::kAnywhere;
  ModelConfig config = ModelConfig::Paper(9);
  WallDecision both =
      FromContours({WallModel::kAuto, {endo, epi}, false}, &config);
  EXPECT_TRUE(both.decided);
  EXPECT_TRUE(config.Solid());
  EXPECT_EQ(both.reason, "endocardial and epicardial contours");
  EXPECT_EQ(both.surface, WallLayer::kAnywhere);

  config = ModelConfig::Paper(9);
  WallDecision endo_only =
      FromContours({WallModel::kAuto, {endo, endo}, false}, &config);
  EXPECT_FALSE(config.Solid());
  EXPECT_EQ(endo_only.reason, "no tracked tags and no contours of both walls");
  EXPECT_EQ(endo_only.surface, WallLayer::kEndocardium);

  WallDecision midwall =
      FromContours({WallModel::kMidwall, {endo, epi}, true}, &config);
  EXPECT_FALSE(config.Solid());
  EXPECT_EQ(midwall.reason, "--wall midwall");

  WallDecision tags =
      FromContours({WallModel::kAuto, {any, any}, true}, &config);
  EXPECT_FALSE(tags.decided);
  EXPECT_EQ(tags.surface, WallLayer::kAnywhere);

  EXPECT_EQ(InputErrorOf([&] {
              FromContours({WallModel::kSolid, {epi, any}, false}, &config);
            }),
            "guidepoints: --wall solid needs tags tracked through the wall "
            "or contours of both walls (lv-cavity,lv-epi)");
}

WallDecision Declared(SurfaceChoice surface,
                      const std::vector<WallLayer>& layers, bool has_tags,
                      WallModel wall = WallModel::kAuto) {
  FitOptions options;
  options.surface = surface;
  options.wall = wall;
  ModelConfig config = ModelConfig::Paper(9);
  WallDecision decision = DecideWallFromContours(
      FrameOf(layers), has_tags, options, "points.csv", &config);
  EXPECT_FALSE(config.Solid());
  return decision;
}

// --surface declares the wall: one surface there, decided before any fit
// (tags are not ranked across a wall), and said in the reason.
TEST(WallStageTest, DeclaredSurfaceIsOneSurfaceOnThatWall) {
  const WallLayer endo = WallLayer::kEndocardium;
  const WallLayer epi = WallLayer::kEpicardium;
  const WallLayer any = WallLayer::kAnywhere;
  const WallDecision mesh = Declared(SurfaceChoice::kEndocardium, {any}, true);
  EXPECT_TRUE(mesh.decided);
  EXPECT_EQ(mesh.reason, "--surface endo");
  EXPECT_EQ(mesh.surface, endo);
  const WallDecision mid =
      Declared(SurfaceChoice::kMidwall, {endo, epi}, false);
  EXPECT_EQ(mid.reason, "--surface midwall");
  EXPECT_EQ(mid.surface, any);
  EXPECT_EQ(Declared(SurfaceChoice::kEpicardium, {epi}, false).surface, epi);
  EXPECT_EQ(InputErrorOf([] {
              Declared(SurfaceChoice::kEndocardium, {endo, epi}, false);
            }),
            "points.csv: --surface endo, but frame 0 has points of the "
            "epicardium (keep one wall's contours, e.g. --contours "
            "lv-cavity)");
  EXPECT_EQ(InputErrorOf([] {
              Declared(SurfaceChoice::kEpicardium, {any}, true,
                       WallModel::kSolid);
            }),
            "--surface epi declares one surface; --wall solid fits two");
}

// Tracked points all named as one wall's (mesh-points' surface column) are
// that wall, decided before the tags' spread is measured; tags of no named
// wall stay undecided.
TEST(WallStageTest, TrackedPointsOfOneNamedWallAreThatSurface) {
  const WallLayer endo = WallLayer::kEndocardium;
  ModelConfig config = ModelConfig::Paper(9);
  const WallDecision mesh =
      FromContours({WallModel::kAuto, {endo, endo}, true}, &config);
  EXPECT_TRUE(mesh.decided);
  EXPECT_EQ(mesh.reason, "tracked points of the endocardium only");
  EXPECT_EQ(mesh.surface, endo);
  const WallDecision mixed = FromContours(
      {WallModel::kAuto, {endo, WallLayer::kAnywhere}, true}, &config);
  EXPECT_FALSE(mixed.decided);
  EXPECT_EQ(mixed.surface, endo);
}

// Frame 0's tags on the mid-wall's normals, `spread(random)` mm off it.
template <typename Spread>
FramePoints TagsAcrossTheWall(const Model& model, Spread spread,
                              std::vector<MaterialPoint>* material) {
  std::mt19937 random(3);
  std::uniform_real_distribution<double> u(-1.2, 0.5), v(-M_PI, M_PI);
  FramePoints frame;
  material->clear();
  for (int i = 0; i < 3000; ++i) {
    const MaterialPoint m{u(random), v(random), 0.0};
    frame.positions.push_back(model.WorldPoint(m.u, m.v) +
                              spread(random) * SurfaceNormal(model, m.u, m.v));
    material->push_back(m);
  }
  frame.assign_depth.assign(frame.positions.size(), true);
  return frame;
}

// Tags spread uniformly through a 10 mm wall make a solid 10 mm thick.
TEST(WallStageTest, TagsThroughTheWallMakeASolidOfTheirThickness) {
  Model model = TestSpheroid(9);
  std::vector<MaterialPoint> material;
  const FramePoints frame = TagsAcrossTheWall(
      model, std::uniform_real_distribution<double>(-5.0, 5.0), &material);
  WallDecision decision;
  ASSERT_TRUE(DecideWallFromTags(frame, material, /*converged=*/true,
                                 WallModel::kAuto, &decision, &model));
  EXPECT_TRUE(decision.decided);
  EXPECT_TRUE(model.config.Solid());
  EXPECT_NEAR(model.state.globals[kH], 10.0, 0.5);
  EXPECT_NEAR(model.state.knots[4][kH], 10.0, 0.5);
  const double spread = std::stod(decision.reason.substr(12));
  EXPECT_NEAR(spread, 10.0, 1.0) << decision.reason;
  const std::string text = FormatSpread(spread) +
                           " mm across the wall, 0 of 3,000 (0.0 %) left out "
                           "as outliers (more than ";
  EXPECT_EQ(decision.reason.substr(0, text.size()), text) << decision.reason;
  EXPECT_NE(decision.reason.find(" mm off their neighbours): a solid (at "
                                 "least 4.0 mm), "),
            std::string::npos)
      << decision.reason;
  EXPECT_NE(decision.reason.find(" mm thick to start (0 beyond the wall left "
                                 "out)"),
            std::string::npos)
      << decision.reason;
}

// Tags on one surface with 0.5 mm noise spread about 1.2 mm: one surface;
// --wall solid makes a solid all the same.  An unconverged solve decides
// nothing from a spread.
TEST(WallStageTest, TagsOnOneSurfaceKeepItOne) {
  const std::normal_distribution<double> noise(0.0, 0.5);
  const std::uniform_real_distribution<double> wall(-5.0, 5.0);
  std::vector<MaterialPoint> material;
  Model model = TestSpheroid(9);
  FramePoints frame = TagsAcrossTheWall(model, noise, &material);
  WallDecision decision;
  EXPECT_FALSE(DecideWallFromTags(frame, material, true, WallModel::kAuto,
                                  &decision, &model));
  EXPECT_FALSE(model.config.Solid());
  EXPECT_NE(decision.reason.find(": one surface (under 4.0 mm)"),
            std::string::npos)
      << decision.reason;

  frame = TagsAcrossTheWall(model, wall, &material);
  EXPECT_FALSE(DecideWallFromTags(frame, material, false, WallModel::kAuto,
                                  &decision, &model));
  EXPECT_NE(decision.reason.find(
                ", but frame 0's mid-wall solve did not converge: one surface"),
            std::string::npos)
      << decision.reason;

  frame = TagsAcrossTheWall(model, noise, &material);
  EXPECT_TRUE(DecideWallFromTags(frame, material, true, WallModel::kSolid,
                                 &decision, &model));
  EXPECT_TRUE(model.config.Solid());
  EXPECT_NE(decision.reason.find("(--wall solid)"), std::string::npos);
}

// Each 20th tag 5-10 mm off along the normal, either way, the others
// `spread(random)` mm off.
template <typename Spread>
auto WithOutliers(Spread spread) {
  return [spread, i = 0](std::mt19937& random) mutable {
    const double across = spread(random);
    if (i++ % 20 != 0) return across;
    const double size =
        std::uniform_real_distribution<double>(5.0, 10.0)(random);
    return across + (i % 40 == 1 ? size : -size);
  };
}

// Tags on one surface with 0.5 mm noise, 5 % of them 5-10 mm off: all of
// them spread 6 mm, a wall; the 150 outliers left out, the rest spread 1.7
// mm, one surface.
TEST(WallStageTest, OutliersOffOneSurfaceKeepItOne) {
  Model model = TestSpheroid(9);
  std::vector<MaterialPoint> material;
  const FramePoints frame = TagsAcrossTheWall(
      model, WithOutliers(std::normal_distribution<double>(0.0, 0.5)),
      &material);
  EXPECT_GT(WallSpreadMm(WorldPoints(model, material),
                         MidwallDistances(model, frame.positions, material)),
            6.0);
  WallDecision decision;
  EXPECT_FALSE(DecideWallFromTags(frame, material, true, WallModel::kAuto,
                                  &decision, &model));
  EXPECT_FALSE(model.config.Solid());
  EXPECT_NEAR(std::stod(decision.reason.substr(12)), 1.7, 0.15)
      << decision.reason;
  EXPECT_NE(decision.reason.find(" mm across the wall, 150 of 3,000 (5.0 %) "
                                 "left out as outliers (more than "),
            std::string::npos)
      << decision.reason;
  EXPECT_NE(decision.reason.find(" mm off their neighbours): one surface "
                                 "(under 4.0 mm)"),
            std::string::npos)
      << decision.reason;
}

// Tags through a 10 mm wall, 5 % of them 5-10 mm off along the normal: a
// solid, which starts from the tags inside the wall, those more than half
// a wall beyond it left out: 10.8 mm thick (10.0 without outliers, 11.3 with
// all of them; transmural_test.cc says why).
TEST(WallStageTest, OutliersOffAWallLeaveItsThickness) {
  Model model = TestSpheroid(9);
  std::vector<MaterialPoint> material;
  const FramePoints frame = TagsAcrossTheWall(
      model, WithOutliers(std::uniform_real_distribution<double>(-5.0, 5.0)),
      &material);
  WallDecision decision;
  ASSERT_TRUE(DecideWallFromTags(frame, material, true, WallModel::kAuto,
                                 &decision, &model));
  EXPECT_NEAR(model.state.globals[kH], 10.75, 0.05) << decision.reason;
  EXPECT_NE(decision.reason.find(", 10.8 mm thick to start (30 beyond the "
                                 "wall left out)"),
            std::string::npos)
      << decision.reason;
}

// Frame 0's tags (ids 0-2, in the tracked material) take the layer they lie
// on and its (u, v); a contour point (id 9, not tracked) is left alone.  A
// tracked frame's noise is read from its tags alone: none without them.
// Measured depths shrunk for noise of sigma: ShrunkDepth(w, 2 sigma / h)
// with the shell's h of 10 mm, (u, v) kept; no noise keeps them.
TEST(WallStageTest, MeasuredDepthsShrinkForTheNoise) {
  const Model shell = TestShell(9);
  ASSERT_EQ(shell.FunctionsAt(0.3)[kH], 10.0);
  TrackedMaterial tracked = {
      {1, {0.3, 1.0, 0.95}}, {2, {-0.4, -2.0, -1.3}}, {3, {0.1, 0.5, 0.2}}};
  const TrackedMaterial measured = tracked;
  ShrinkMeasuredDepths(shell, 0.0, &tracked);
  for (const auto& [id, m] : tracked) {
    EXPECT_EQ(m.w, std::clamp(measured.at(id).w, -1.0, 1.0)) << id;
  }
  tracked = measured;
  ShrinkMeasuredDepths(shell, 0.5, &tracked);
  for (const auto& [id, m] : tracked) {
    EXPECT_EQ(m.w, ShrunkDepth(measured.at(id).w, 0.1)) << id;
    EXPECT_EQ(m.u, measured.at(id).u) << id;
    EXPECT_EQ(m.v, measured.at(id).v) << id;
  }
  // Toward the middle, most near the walls.
  EXPECT_LT(tracked[1].w, 0.95);
  EXPECT_GT(tracked[2].w, -1.0);
  EXPECT_NEAR(tracked[3].w, 0.2, 1e-3);
}

TEST(WallStageTest, TagsHoldTheLayerTheyLieOn) {
  Model model = TestSpheroid(9);
  model.config.MakeSolid();
  model.state.globals[kH] = 10.0;
  for (FunctionValues& knot : model.state.knots) knot[kH] = 10.0;
  const std::vector<MaterialPoint> truth = {
      {-0.5, 1.0, -0.6}, {0.1, -2.0, 0.2}, {-0.2, 0.5, 0.9}};
  Frame first;
  TrackedMaterial tracked;
  for (int i = 0; i < 3; ++i) {
    DataPoint p;
    p.id = i;
    p.position = model.WorldPoint(truth[i].u, truth[i].v, truth[i].w);
    first.points.push_back(p);
    // Ranked at the mid-wall, 0.03 off in (u, v).
    tracked[i] = {truth[i].u + 0.03, truth[i].v + 0.03, 0.0};
  }
  DataPoint contour;
  contour.id = 9;
  first.points.push_back(contour);
  HoldTagDepths(first, model, 0.0, &tracked);
  ASSERT_EQ(tracked.size(), 3u);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(tracked[i].w, truth[i].w, 1e-5) << i;
    EXPECT_NEAR(tracked[i].u, truth[i].u, 1e-5) << i;
    EXPECT_NEAR(tracked[i].v, truth[i].v, 1e-5) << i;
  }
  // No point seen in two frames: no tags, no noise.
  const FramesPerId once = {{0, 1}, {1, 1}, {2, 1}, {9, 1}};
  const std::vector<MaterialPoint> material = {truth[0], truth[1], truth[2],
                                               truth[0]};
  EXPECT_FALSE(FrameTagNoiseMm(model, first, material, once).has_value());
  const FramesPerId twice = {{0, 2}, {1, 2}, {2, 2}, {9, 1}};
  first.points[3].position = first.points[0].position;
  EXPECT_NEAR(*FrameTagNoiseMm(model, first, material, twice), 0.0, 1e-9);
}

// A tracked frame whose radii contracted by a fifth since frame 0: its
// tags' noise, 0.5 mm per coordinate in each frame, read from their own
// residuals and from their neighbours' as 0.5 given frame 0's model, lower
// as if frame 0's noise reached the frame whole without it.
TEST(WallStageTest, TagNoiseTakesFrameZerosShareAsStretched) {
  const Model first = TestSpheroid(9);
  const Model later = RadiallyScaled(first, 0.8);
  std::mt19937 random(19);
  std::uniform_real_distribution<double> u(-1.2, 0.4), v(-3.1, 3.1);
  std::vector<MaterialPoint> material;
  FramesPerId frames_per_id;
  for (int i = 0; i < 5000; ++i) {
    material.push_back({u(random), v(random), 0.0});
    frames_per_id[i] = 2;
  }
  const std::vector<Eigen::Vector3d> residuals =
      StretchedTagResiduals(first, later, material, 0.5, 23);
  Frame frame;
  for (int i = 0; i < 5000; ++i) {
    DataPoint p;
    p.id = i;
    p.position = later.WorldPoint(material[i].u, material[i].v) - residuals[i];
    frame.points.push_back(p);
  }
  for (TagNoiseFrom from :
       {TagNoiseFrom::kResiduals, TagNoiseFrom::kNeighbours}) {
    const double given = *FrameTagNoiseMm(later, frame, material, frames_per_id,
                                          false, from, &first);
    const double without =
        *FrameTagNoiseMm(later, frame, material, frames_per_id, false, from);
    EXPECT_NEAR(given, 0.5, 0.02);
    EXPECT_LT(without, given - 0.01);
  }
}

}  // namespace
}  // namespace pfdm
