#include "pfdm/fit/stages/frame_verdict.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "gtest/gtest.h"
#include "pfdm/fit/correspondence/correspondence.h"
#include "pfdm/fit/stages/fitter.h"
#include "pfdm/fit/stages/frame_points.h"
#include "pfdm/fit/stages/parallel_planes.h"
#include "pfdm/phantom/lv_phantom.h"
#include "pfdm/testing/false_planes_phantom.h"
#include "pfdm/testing/segment_contours_phantom.h"
#include "pfdm/testing/test_models.h"

namespace pfdm {
namespace {

const Phantom& SmallPhantom() {
  static const Phantom* phantom = new Phantom(MakeTestPhantom(1000, 3));
  return *phantom;
}

// A fit of the phantom, its verdicts cleared, for the reasons to be judged
// one at a time; the prior's step is left out (options without a prior),
// since the changes below move the state away from its solution.
SequenceFit Judged(const std::function<void(SequenceFit*)>& change) {
  static const SequenceFit* fit = new SequenceFit(
      FitSequence(SmallPhantom().points, ModelConfig::Paper(17), FitOptions()));
  SequenceFit copy = *fit;
  for (FrameFit& frame : copy.frames) frame.verdict = Verdict();
  change(&copy);
  FitOptions no_prior;
  no_prior.prior_weight = 0.0;
  const PointSequence& points = SmallPhantom().points;
  JudgeFrames(points, CountFramesPerId(points), no_prior, &copy);
  return copy;
}

std::string Codes(const FrameFit& frame) {
  std::string codes;
  for (const VerdictReason& reason : frame.verdict.reasons()) {
    codes += (codes.empty() ? "" : ",") + reason.code + "/" +
             QualityName(reason.severity);
  }
  return codes;
}

// The project's phantom with its 0.5 mm noise: no reason in any frame.
TEST(FrameVerdictTest, ACleanFitIsOk) {
  const SequenceFit fit =
      FitSequence(SmallPhantom().points, ModelConfig::Paper(17), FitOptions());
  for (const FrameFit& frame : fit.frames) {
    EXPECT_EQ(frame.verdict.quality(), Quality::kOk) << Codes(frame);
  }
}

// Points moving by less than the frames' median RMS (about 1 mm) in the
// last search change nothing the fit reports.
TEST(FrameVerdictTest, SaysWhenTheSolverOrTheRoundsDidNotFinish) {
  const SequenceFit fit = Judged([](SequenceFit* f) {
    f->frames[0].unsettled_mm = 0.4;
    f->frames[1].termination = "NO_CONVERGENCE";
    f->frames[1].unsettled_mm = 2.5;
    f->frames[2].unsettled_mm = 22.6;
  });
  EXPECT_EQ(Codes(fit.frames[0]), "");
  EXPECT_EQ(Codes(fit.frames[1]), "solver/warning,unsettled/warning");
  EXPECT_EQ(Codes(fit.frames[2]), "unsettled/failed");
  EXPECT_EQ(fit.frames[2].verdict.reasons()[0].text.rfind(
                "closest points still moving (22.60 mm in the last search, "
                "the frames' median RMS ",
                0),
            0u)
      << fit.frames[2].verdict.reasons()[0].text;
}

// The phantom's radius (RMS distance from the centroid) is about 40 mm: 12
// mm is 30 % of it, 3.5 mm 9 %, and either several times the other
// frames' RMS (about 1 mm).
TEST(FrameVerdictTest, WeighsTheRmsAgainstTheFramesAndTheDataSize) {
  const SequenceFit fit =
      Judged([](SequenceFit* f) { f->frames[0].rms_mm = 12.0; });
  EXPECT_EQ(Codes(fit.frames[0]), "rms_frames/warning,rms_size/failed");
  EXPECT_EQ(Codes(fit.frames[1]), "");
  const SequenceFit warned =
      Judged([](SequenceFit* f) { f->frames[0].rms_mm = 3.5; });
  EXPECT_EQ(Codes(warned.frames[0]), "rms_frames/warning,rms_size/warning");
}

// Both walls' contours fitted as one surface (--wall midwall): the RMS is
// about half the 10 mm wall's thickness, and the reason says why and what
// to do; the solid the walls choose by default fits them (no rms_size).
TEST(FrameVerdictTest, NamesBothWallsOnOneSurfaceAsTheMisfitsCause) {
  const PointSequence walls = SegmentWallContours();
  FitOptions one_surface;
  one_surface.wall = WallModel::kMidwall;
  one_surface.local.enabled = false;
  const SequenceFit midwall =
      FitSequence(walls, ModelConfig::Paper(9), one_surface);
  EXPECT_GT(midwall.frames[0].rms_mm, 3.5);
  std::string text;
  for (const VerdictReason& reason : midwall.frames[0].verdict.reasons()) {
    if (reason.code == "rms_size") text = reason.text;
  }
  EXPECT_NE(text.find("(one surface through both walls' contours; --wall "
                      "solid fits each wall)"),
            std::string::npos)
      << text;
  FitOptions solid = one_surface;
  solid.wall = WallModel::kAuto;
  const SequenceFit both = FitSequence(walls, ModelConfig::Paper(9), solid);
  EXPECT_LT(both.frames[0].rms_mm, 1.0);
  EXPECT_EQ(Codes(both.frames[0]).find("rms_size"), std::string::npos);
}

// With a robust loss the RMS reasons judge the points it keeps (weight at
// least 0.5): frame 0 with 10 % of its points 30 mm off reads RMS 9.5 mm,
// 24 % of the radius, a failure without the weights; with them its kept
// points' RMS is the fit's own, and 10 % down-weighted is no reason.  Half
// of them down-weighted is: more outliers than a tracker makes.
TEST(FrameVerdictTest, WithARobustLossJudgesTheKeptPoints) {
  const auto spoil = [](double share) {
    return [share](SequenceFit* f) {
      FrameFit& frame = f->frames[0];
      frame.loss_weights.assign(frame.residuals.size(), 1.0);
      frame.loss_scale_mm = 1.0;
      double sum = 0.0;
      for (size_t i = 0; i < frame.residuals.size(); ++i) {
        if (i < share * frame.residuals.size()) {
          frame.residuals[i] = Eigen::Vector3d(30.0, 0.0, 0.0);
          frame.loss_weights[i] = 0.01;
        }
        sum += frame.residuals[i].squaredNorm();
      }
      frame.rms_mm = std::sqrt(sum / frame.residuals.size());
    };
  };
  SequenceFit fit = Judged(spoil(0.1));
  EXPECT_GT(fit.frames[0].rms_mm, 9.0);
  EXPECT_EQ(Codes(fit.frames[0]), "");
  fit = Judged([&](SequenceFit* f) {
    spoil(0.1)(f);
    f->frames[0].loss_weights.clear();
  });
  EXPECT_EQ(Codes(fit.frames[0]), "rms_frames/warning,rms_size/failed");
  fit = Judged(spoil(0.5));
  EXPECT_EQ(Codes(fit.frames[0]), "outliers/warning");
  EXPECT_EQ(fit.frames[0].verdict.reasons()[0].text.rfind(
                "the robust loss weighs 50 % of the points below 0.5", 0),
            0u)
      << fit.frames[0].verdict.reasons()[0].text;
}

// --prior 1 (1,000 times the default) holds every frame near the one
// before: one step without it moves the points by more than the frame's
// RMS once the motion adds up.  At the default no frame's step comes near.
TEST(FrameVerdictTest, NamesAPriorThatHoldsTheModel) {
  FitOptions options;
  options.prior_weight = 1.0;
  const SequenceFit fit =
      FitSequence(SmallPhantom().points, ModelConfig::Paper(17), options);
  for (int t = 0; t < 3; ++t) {
    EXPECT_TRUE(fit.frames[t].verdict.Has("prior")) << Codes(fit.frames[t]);
  }
  EXPECT_EQ(fit.frames[2].verdict.quality(), Quality::kFailed)
      << Codes(fit.frames[2]);
  EXPECT_EQ(fit.frames[2].verdict.reasons().back().text.rfind(
                "without the prior (--prior) one step would move the points "
                "by ",
                0),
            0u);
}

// Noise-free tags of the independent LV phantom fit to 0.002-0.06 mm, and
// a step without the prior moves them by about as much: a share of the
// RMS near 1, but nothing any image resolves (kPriorPullFloorMm).  Before
// the floor such frames read "the prior, not the data, holds the model",
// the tracked one at 2,000 tags "failed".
TEST(FrameVerdictTest, ATinyPullOnNoiseFreeTagsIsNoReason) {
  const SequenceFit fit = FitSequence(LvTwoFrameTags(2000, 1000, 0.0),
                                      ModelConfig::Paper(9), FitOptions());
  for (const FrameFit& frame : fit.frames) {
    EXPECT_LT(frame.rms_mm, 0.1);
    EXPECT_FALSE(frame.verdict.Has("prior")) << Codes(frame);
  }
}

// The probe's move, measured on every k-th of 20,000 material points,
// reads the RMS of all of them within 1 % (a twist growing toward the
// base and a shift moves each point differently); on 3,000, which are all
// measured, exactly.
TEST(FrameVerdictTest, MoveOfASampleIsTheMoveOfAll) {
  const Model before = TwistedTestModel();
  Model after = before;
  for (size_t k = 0; k < after.state.knots.size(); ++k) {
    after.state.knots[k][kTau] += 0.002 * k;
    after.state.knots[k][kE1o] += 0.05 * std::sin(k);
  }
  std::mt19937 random(3);
  std::uniform_real_distribution<double> u(-1.5, 0.5), v(-M_PI, M_PI);
  std::vector<MaterialPoint> material;
  for (int i = 0; i < 20000; ++i) material.push_back({u(random), v(random)});
  auto all_of = [&](const std::vector<MaterialPoint>& points) {
    const std::vector<Eigen::Vector3d> a = WorldPoints(before, points);
    const std::vector<Eigen::Vector3d> b = WorldPoints(after, points);
    double sum = 0.0;
    for (size_t i = 0; i < a.size(); ++i) sum += (b[i] - a[i]).squaredNorm();
    return std::sqrt(sum / a.size());
  };
  const double all = all_of(material);
  EXPECT_GT(all, 0.1);
  EXPECT_NEAR(RmsMoveMm(before, after, material), all, 0.01 * all);
  material.resize(3000);
  EXPECT_EQ(RmsMoveMm(before, after, material), all_of(material));
}

TEST(FrameVerdictTest, SaysWhenAShapeFunctionIsAtItsBound) {
  const SequenceFit fit =
      Judged([](SequenceFit* f) { f->frames[1].state.knots[3][kA3] = 1.0; });
  EXPECT_EQ(Codes(fit.frames[1]), "at_bound/warning");
}

TEST(FrameVerdictTest, SaysWhenKnotSpansInsideTheDataAreEmpty) {
  const SequenceFit fit = Judged([](SequenceFit* f) {
    // Every point of frame 1 off the spans 6 to 9 (u ~ -0.5 .. 0).
    const KnotGrid grid = f->config.Grid();
    for (MaterialPoint& m : f->frames[1].material) {
      const int k = grid.Span(m.u).k0;
      if (k >= 6 && k <= 9) m.u = grid.KnotU(12);
    }
  });
  EXPECT_EQ(Codes(fit.frames[1]), "sparse_rings/warning");
}

// Frame t made a frame of contours (untracked) that lost its upper slices:
// its points above `share` of frame 0's span in mm from its own lowest one
// left out.
void CutAbove(double share, int t, SequenceFit* fit) {
  const std::vector<double> first =
      AxialHeights(fit->ModelAt(0), fit->frames[0].material);
  const auto [low0, high0] = std::minmax_element(first.begin(), first.end());
  std::vector<MaterialPoint>& material = fit->frames[t].material;
  const std::vector<double> heights = AxialHeights(fit->ModelAt(t), material);
  const double cut = *std::min_element(heights.begin(), heights.end()) +
                     share * (*high0 - *low0);
  std::vector<MaterialPoint> kept;
  for (size_t i = 0; i < material.size(); ++i) {
    if (heights[i] <= cut) kept.push_back(material[i]);
  }
  material = kept;
  fit->frames[t].tracked = false;
}

// Half of frame 0's span is a warning; 85 % of it (9 slices less the
// basal one keep 7/8) is none.
TEST(FrameVerdictTest, SaysWhenALaterFramesDataSpanLessOfTheAxis) {
  const SequenceFit fit = Judged([](SequenceFit* f) {
    CutAbove(0.5, 2, f);
    CutAbove(0.85, 1, f);
  });
  EXPECT_EQ(Codes(fit.frames[2]), "short_span/warning");
  EXPECT_NE(fit.frames[2].verdict.reasons()[0].text.find("span 50 %"),
            std::string::npos)
      << fit.frames[2].verdict.reasons()[0].text;
  EXPECT_EQ(Codes(fit.frames[1]), "");
  EXPECT_EQ(Codes(fit.frames[0]), "");
}

// Tracked points keep their material points, whatever the model's length:
// a tracked frame's span is not judged.
TEST(FrameVerdictTest, ATrackedFramesSpanIsNotJudged) {
  const SequenceFit fit = Judged([](SequenceFit* f) {
    CutAbove(0.5, 2, f);
    f->frames[2].tracked = true;
  });
  EXPECT_FALSE(fit.frames[2].verdict.Has(kShortSpanCode))
      << Codes(fit.frames[2]);
}

// A solid's thickness at its floor 0 at knots 14 and 16 (the top one) of
// frame 1: its walls meet below the top knot, said once with the count;
// frame 2's meet at the top knot alone (the valve's hinge), not a reason.
TEST(FrameVerdictTest, SaysWhereASolidsWallsMeetBelowTheTopKnot) {
  const SequenceFit fit = Judged([](SequenceFit* f) {
    f->config.MakeSolid();
    for (FrameFit& frame : f->frames) {
      for (FunctionValues& knot : frame.state.knots) knot[kH] = 8.0;
    }
    f->frames[1].state.knots[14][kH] = 0.0;
    f->frames[1].state.knots[16][kH] = 0.0;
    f->frames[2].state.knots[16][kH] = 0.0;
  });
  ASSERT_EQ(fit.frames[1].state.knots.size(), 17u);
  ASSERT_TRUE(fit.frames[1].verdict.Has("walls_meet")) << Codes(fit.frames[1]);
  for (const VerdictReason& reason : fit.frames[1].verdict.reasons()) {
    if (reason.code != "walls_meet") continue;
    EXPECT_NE(reason.text.find("at 1 knots below the top one"),
              std::string::npos)
        << reason.text;
  }
  EXPECT_FALSE(fit.frames[0].verdict.Has("walls_meet"));
  EXPECT_FALSE(fit.frames[2].verdict.Has("walls_meet")) << Codes(fit.frames[2]);
}

// A solid's tags at depths near the wall's middle (rms 0.1), no contours:
// nothing places the walls.  Depths that fill the wall (rms 0.58) do.
TEST(FrameVerdictTest, SaysWhenNothingPlacesASolidsWalls) {
  const SequenceFit fit = Judged([](SequenceFit* f) {
    f->config.MakeSolid();
    for (size_t t = 0; t < f->frames.size(); ++t) {
      std::vector<MaterialPoint>& material = f->frames[t].material;
      for (size_t i = 0; i < material.size(); ++i) {
        const double filling = -1.0 + 2.0 * (i + 0.5) / material.size();
        material[i].w = t == 1 ? (i % 2 == 0 ? 0.1 : -0.1) : filling;
      }
    }
  });
  ASSERT_TRUE(fit.frames[1].verdict.Has(kWallsUnseenCode))
      << Codes(fit.frames[1]);
  for (const VerdictReason& reason : fit.frames[1].verdict.reasons()) {
    if (reason.code != kWallsUnseenCode) continue;
    EXPECT_EQ(reason.severity, Quality::kWarning);
    EXPECT_NE(reason.text.find("rms depth 0.10"), std::string::npos)
        << reason.text;
  }
  EXPECT_FALSE(fit.frames[0].verdict.Has(kWallsUnseenCode));
  EXPECT_FALSE(fit.frames[2].verdict.Has(kWallsUnseenCode));
}

TEST(FrameVerdictTest, FailsAFrameZeroThatNeverMoved) {
  const SequenceFit fit = Judged([](SequenceFit* f) {
    f->frames[0].trace = {{0, 0.0, 0.0, 100.0, 1.0}, {1, 0.0, 0.0, 99.99, 1.0}};
    f->frames[0].costs = TermCosts{99.99};
  });
  EXPECT_EQ(Codes(fit.frames[0]), "not_moved/failed");
}

// Rounds that ran out and went back to their best state: the last round's
// cost is no end of the fit, the kept state's is.
TEST(FrameVerdictTest, AFrameZeroBackAtItsBestRoundMoved) {
  const SequenceFit fit = Judged([](SequenceFit* f) {
    f->frames[0].trace = {{0, 0.0, 0.0, 100.0, 1.0}, {9, 0.0, 0.0, 900.0, 1.0}};
    f->frames[0].costs = TermCosts{2.0, 0.5};
  });
  EXPECT_EQ(Codes(fit.frames[0]), "");
}

// A later frame's model turned a quarter turn about x: its axis lies
// across the data's length.
TEST(FrameVerdictTest, FailsAModelAcrossTheDatasLength) {
  const SequenceFit fit = Judged([](SequenceFit* f) {
    const Eigen::Quaterniond turn(
        Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX()));
    std::array<double, 4>& q = f->frames[1].state.quaternion;
    const Eigen::Quaterniond turned =
        Eigen::Quaterniond(q[0], q[1], q[2], q[3]) * turn;
    q = {turned.w(), turned.x(), turned.y(), turned.z()};
  });
  EXPECT_EQ(Codes(fit.frames[1]), "axis_across/failed");
  EXPECT_EQ(Codes(fit.frames[0]), "");
}

// The LV phantom's 150 tags through the wall, seed 1011, fitted from the
// normal of the 7 "parallel planes" chance makes of them (a hint along it,
// as the start once took it): frame 0 ends across the LV at an RMS of 5 %
// of the data's radius, under rms_size's bound, and CONVERGENCE; only this
// reason says so.  Fitted from its own start, no frame has it.
TEST(FrameVerdictTest, FailsTheFitThatFalsePlanesStarted) {
  const LvPhantom phantom = FalsePlanesPhantom();
  const std::vector<Eigen::Vector3d> points =
      Positions(phantom.points.frames[0]);
  const auto planes = FindParallelPlanes(points);
  ASSERT_TRUE(planes.has_value());
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : points) centroid += p;
  centroid /= static_cast<double>(points.size());
  FitOptions options;
  options.local.enabled = false;
  options.hint = AxisHint{centroid - 40.0 * planes->normal,
                          centroid + 40.0 * planes->normal};
  const SequenceFit across =
      FitSequence(phantom.points, ModelConfig::Paper(9), options);
  EXPECT_TRUE(across.frames[0].verdict.Has("axis_across"))
      << Codes(across.frames[0]);
  EXPECT_EQ(across.frames[0].verdict.quality(), Quality::kFailed);
  options.hint.reset();
  const SequenceFit right =
      FitSequence(phantom.points, ModelConfig::Paper(9), options);
  const Eigen::Vector3d truth =
      phantom.truth[0].world_from_body.linear().col(2);
  EXPECT_GT(right.ModelAt(0).Rotation().col(2).dot(truth),
            std::cos(10.0 * M_PI / 180.0));
  for (const FrameFit& frame : right.frames) {
    EXPECT_FALSE(frame.verdict.Has("axis_across")) << Codes(frame);
  }
}

TEST(FrameVerdictTest, FailsFlatData) {
  PointSequence flat = SmallPhantom().points;
  for (Frame& frame : flat.frames) {
    for (DataPoint& p : frame.points) p.position.z() *= 1e-3;
  }
  SequenceFit fit = Judged([](SequenceFit*) {});
  for (FrameFit& frame : fit.frames) frame.verdict = Verdict();
  JudgeFrames(flat, CountFramesPerId(flat), FitOptions(), &fit);
  EXPECT_TRUE(fit.frames[0].verdict.Has("flat_data"));
  EXPECT_EQ(fit.frames[0].verdict.quality(), Quality::kFailed);
}

}  // namespace
}  // namespace pfdm
