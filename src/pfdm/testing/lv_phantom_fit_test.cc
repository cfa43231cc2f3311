// Fits of the independent analytic LV phantom (phantom/lv_phantom.h), which
// the model did not generate: apex held still while the base descends,
// breathing, rigid motion alone, a full cycle, through-wall tags and other
// knot counts.  The clinical numbers are measured on the fitted model's
// material points and compared with the phantom's truth, measured on its
// own material points by the same definitions.
#include <cmath>
#include <cstdio>

#include "gtest/gtest.h"
#include "pfdm/fit/stages/fitter.h"
#include "pfdm/phantom/lv_phantom.h"
#include "pfdm/report/clinical_summary.h"
#include "pfdm/util/angles.h"

namespace pfdm {
namespace {

struct PhantomFit {
  LvPhantom phantom;
  SequenceFit fit;
  std::vector<ClinicalSummary> clinical;
};

PhantomFit FitPhantom(LvKinematics kinematics,
                      LvTagLayer tags = LvTagLayer::kMidwall, int knots = 17) {
  LvPhantomOptions options;
  options.kinematics = kinematics;
  options.tags = tags;
  PhantomFit result{MakeLvPhantom(options), {}, {}};
  result.fit = FitSequence(result.phantom.points, ModelConfig::Paper(knots),
                           FitOptions());
  std::vector<Model> models;
  for (size_t t = 0; t < result.fit.frames.size(); ++t) {
    models.push_back(result.fit.ModelAt(t));
  }
  result.clinical = SummarizeSequence(models);
  return result;
}

// The truth by the summary's definitions: rings at the same height
// fractions of the ED length, radial contraction the mean of ten rings.
struct Truth {
  double apex_rotation_deg, base_rotation_deg, net_twist_deg;
  double radial_contraction_percent, longitudinal_shortening_percent;
  double volume_ml;
};

Truth TruthOf(const LvFrameTruth& frame) {
  const LvLayerRings& rings = frame.midwall;
  Truth truth;
  truth.apex_rotation_deg =
      LvRingValueAt(rings.rotation_deg, kApicalRingFraction);
  truth.base_rotation_deg =
      LvRingValueAt(rings.rotation_deg, kBasalRingFraction);
  truth.net_twist_deg = truth.base_rotation_deg - truth.apex_rotation_deg;
  truth.radial_contraction_percent = 0.0;
  for (int i = 0; i < kContractionRings; ++i) {
    truth.radial_contraction_percent +=
        LvRingValueAt(rings.radial_contraction_percent,
                      (i + 0.5) / kContractionRings) /
        kContractionRings;
  }
  truth.longitudinal_shortening_percent = frame.longitudinal_shortening_percent;
  truth.volume_ml = frame.volume_ml;
  return truth;
}

void Print(const char* name, const PhantomFit& f) {
  for (size_t t = 0; t < f.clinical.size(); ++t) {
    const ClinicalSummary& c = f.clinical[t];
    const Truth truth = TruthOf(f.phantom.truth[t]);
    std::printf(
        "%s frame %zu rms %.2f  LS %.2f (%.2f)  RC %.2f (%.2f)  apex %.2f "
        "(%.2f)  base %.2f (%.2f)  twist %.2f (%.2f)  volume %.1f (%.1f)\n",
        name, t, f.fit.frames[t].rms_mm, c.longitudinal_shortening_percent,
        truth.longitudinal_shortening_percent, c.radial_contraction_percent,
        truth.radial_contraction_percent, c.apex_rotation_deg,
        truth.apex_rotation_deg, c.base_rotation_deg, truth.base_rotation_deg,
        c.net_twist_deg, truth.net_twist_deg, c.volume_ml, truth.volume_ml);
  }
}

// Largest |b0|, |b2| over the knots: the bend's amplitude, mm.
double MaxBending(const ModelState& state) {
  double largest = 0.0;
  for (const FunctionValues& knot : state.knots) {
    largest = std::max({largest, std::abs(knot[kB0]), std::abs(knot[kB2])});
  }
  return largest;
}

// The tolerances: points for percentages, degrees for rotation.
void ExpectClinicalNumbersOfTheTruth(const PhantomFit& f, double percent,
                                     double rotation, double twist) {
  for (size_t t = 0; t < f.clinical.size(); ++t) {
    const ClinicalSummary& c = f.clinical[t];
    const Truth truth = TruthOf(f.phantom.truth[t]);
    EXPECT_NEAR(c.longitudinal_shortening_percent,
                truth.longitudinal_shortening_percent, percent)
        << "frame " << t;
    EXPECT_NEAR(c.radial_contraction_percent, truth.radial_contraction_percent,
                percent)
        << "frame " << t;
    EXPECT_NEAR(c.apex_rotation_deg, truth.apex_rotation_deg, rotation)
        << "frame " << t;
    EXPECT_NEAR(c.base_rotation_deg, truth.base_rotation_deg, rotation)
        << "frame " << t;
    EXPECT_NEAR(c.net_twist_deg, truth.net_twist_deg, twist) << "frame " << t;
  }
}

// Systole with the apex still, the base descending 17 % and breathing (4 mm
// along the axis, 2 across, 2 degrees of tilt): every clinical number at
// every frame within 1 point, rotation within 0.5 degree, net twist 0.7;
// no bending where the truth has none; a3 reads the longitudinal stretch
// at every knot and the descent shows in the pose.
TEST(LvPhantomFitTest, SystoleWithBreathingReadsTheTruth) {
  const PhantomFit f = FitPhantom(LvKinematics::kSystole);
  Print("systole", f);
  ExpectClinicalNumbersOfTheTruth(f, 1.0, 0.5, 0.7);
  const ClinicalSummary& es = f.clinical.back();
  const double stretch =
      1.0 - f.phantom.truth.back().longitudinal_shortening_percent / 100.0;
  for (size_t k = 1; k < es.longitudinal_ratio.size(); ++k) {
    EXPECT_NEAR(es.longitudinal_ratio[k], stretch, 0.02) << "knot " << k;
  }
  for (const FrameFit& frame : f.fit.frames) {
    EXPECT_LT(MaxBending(frame.state), 1.0) << "frame " << frame.frame;
    EXPECT_LT(frame.rms_mm, 1.5) << "frame " << frame.frame;
  }
  // The apex stays where the phantom holds it, up to breathing: the model's
  // apex pole moves with the phantom's apex.
  const Eigen::Vector3d apex_truth =
      f.phantom.truth.back().world_from_body * Eigen::Vector3d::Zero();
  const Eigen::Vector3d apex_fit = f.fit.ModelAt(f.fit.frames.size() - 1)
                                       .WorldPoint(f.fit.config.u_min, 0.0);
  const Eigen::Vector3d apex_truth0 =
      f.phantom.truth.front().world_from_body * Eigen::Vector3d::Zero();
  const Eigen::Vector3d apex_fit0 =
      f.fit.ModelAt(0).WorldPoint(f.fit.config.u_min, 0.0);
  EXPECT_LT(((apex_fit - apex_fit0) - (apex_truth - apex_truth0)).norm(), 1.0);
}

// Rigid motion alone moves nothing a cardiologist reads: shortening,
// contraction and net twist within 0.3, the volume within 1 %, RMS at the
// noise floor (1.12 mm for tracked frames: the noise of both frames at a
// material point), and a spin reads as rotation of every ring.
struct RigidCase {
  LvKinematics kinematics;
  const char* name;
  double rotation_deg;  // Of every ring at the last frame.
};

class LvPhantomRigidTest : public ::testing::TestWithParam<RigidCase> {};

TEST_P(LvPhantomRigidTest, RigidMotionAloneMovesNoClinicalNumber) {
  const RigidCase& rigid = GetParam();
  const PhantomFit f = FitPhantom(rigid.kinematics);
  Print(rigid.name, f);
  const double volume0 = f.clinical.front().volume_ml;
  for (size_t t = 0; t < f.clinical.size(); ++t) {
    const ClinicalSummary& c = f.clinical[t];
    EXPECT_NEAR(c.longitudinal_shortening_percent, 0.0, 0.3) << "frame " << t;
    EXPECT_NEAR(c.radial_contraction_percent, 0.0, 0.3) << "frame " << t;
    EXPECT_NEAR(c.net_twist_deg, 0.0, 0.3) << "frame " << t;
    EXPECT_NEAR(c.volume_ml, volume0, 0.01 * volume0) << "frame " << t;
    EXPECT_LT(f.fit.frames[t].rms_mm, t == 0 ? 0.55 : 1.2) << "frame " << t;
    EXPECT_LT(MaxBending(f.fit.frames[t].state), 1.0) << "frame " << t;
  }
  const ClinicalSummary& last = f.clinical.back();
  EXPECT_NEAR(last.apex_rotation_deg, rigid.rotation_deg, 0.3);
  EXPECT_NEAR(last.base_rotation_deg, rigid.rotation_deg, 0.3);
}

INSTANTIATE_TEST_SUITE_P(
    Scenarios, LvPhantomRigidTest,
    ::testing::Values(RigidCase{LvKinematics::kRigidAxial, "axial", 0.0},
                      RigidCase{LvKinematics::kRigidLateral, "lateral", 0.0},
                      RigidCase{LvKinematics::kRigidTilt, "tilt", 0.0},
                      RigidCase{LvKinematics::kRigidSpin, "spin", 10.0}),
    [](const auto& info) { return std::string(info.param.name); });

// The same numbers, within 1 point (1 degree), whatever the knot count.
TEST(LvPhantomFitTest, ClinicalNumbersDoNotDependOnTheKnots) {
  const PhantomFit reference = FitPhantom(LvKinematics::kSystole);
  for (int knots : {9, 33}) {
    const PhantomFit f =
        FitPhantom(LvKinematics::kSystole, LvTagLayer::kMidwall, knots);
    const ClinicalSummary& a = f.clinical.back();
    const ClinicalSummary& b = reference.clinical.back();
    EXPECT_NEAR(a.longitudinal_shortening_percent,
                b.longitudinal_shortening_percent, 1.0)
        << knots;
    EXPECT_NEAR(a.radial_contraction_percent, b.radial_contraction_percent, 1.0)
        << knots;
    EXPECT_NEAR(a.net_twist_deg, b.net_twist_deg, 1.0) << knots;
    ExpectClinicalNumbersOfTheTruth(f, 1.0, 0.5, 0.7);
  }
}

// A full cycle (p = 0 -> 1 -> 0, breathing back to zero) ends where it
// began: every clinical number and every parameter function.
TEST(LvPhantomFitTest, FullCycleReturnsToEndDiastole) {
  const PhantomFit f = FitPhantom(LvKinematics::kCycle);
  Print("cycle", f);
  ExpectClinicalNumbersOfTheTruth(f, 1.0, 0.5, 0.7);
  const ClinicalSummary& last = f.clinical.back();
  EXPECT_NEAR(last.longitudinal_shortening_percent, 0.0, 0.3);
  EXPECT_NEAR(last.radial_contraction_percent, 0.0, 0.3);
  EXPECT_NEAR(last.net_twist_deg, 0.0, 0.3);
  EXPECT_NEAR(last.volume_ml, f.clinical.front().volume_ml,
              0.01 * f.clinical.front().volume_ml);
  const ModelState& first = f.fit.frames.front().state;
  const ModelState& end = f.fit.frames.back().state;
  // Within 1.2 %: a2 next to the apex (knot 1, a small radius) reads
  // 1.01 %, the rest under 1 %.
  for (size_t k = 1; k < first.knots.size(); ++k) {
    for (int fn : {kA1, kA2, kA3}) {
      EXPECT_NEAR(end.knots[k][fn] / first.knots[k][fn], 1.0, 0.012)
          << FunctionName(fn) << " knot " << k;
    }
    EXPECT_NEAR(end.knots[k][kTau], 0.0, 0.5 * kRadiansPerDegree) << k;
    EXPECT_NEAR(end.knots[k][kE1o], first.knots[k][kE1o], 0.3) << k;
    EXPECT_NEAR(end.knots[k][kE2o], first.knots[k][kE2o], 0.3) << k;
  }
  EXPECT_LT(MaxBending(end), 1.0);
}

// Tags through a 10 mm wall: the mid-wall surface still reads the motion
// (rotation does not vary through the wall, and the wall's mean radial
// contraction is the mid-wall's).
TEST(LvPhantomFitTest, ThroughWallTagsReadTheMotion) {
  const PhantomFit f = FitPhantom(LvKinematics::kSystole, LvTagLayer::kWall);
  Print("wall", f);
  ExpectClinicalNumbersOfTheTruth(f, 1.0, 0.5, 0.7);
  for (const FrameFit& frame : f.fit.frames) {
    EXPECT_LT(MaxBending(frame.state), 1.0) << "frame " << frame.frame;
  }
}

}  // namespace
}  // namespace pfdm
