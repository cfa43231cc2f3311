// Issue 30's calibration of the frames' covariance on the independent LV
// phantom (phantom/lv_phantom.h), which the model did not generate: over
// many noise draws, the reference inside the 95 % interval of each judged
// knot value for 90-98 % of the draws, and the intervals narrowing like
// 1/sqrt(N) (4 times the points: half the width).
//
// What "truth" is here.  The phantom's shape is not a superellipsoid with
// knots, so a knot value has no true value of its own; the reference is the
// fit of the same tags without noise (the phantom draws placement and noise
// from separate streams: noise_mm 0 gives the same tags).  The fit to noisy
// data minus that reference is the noise's part of the error, which is what
// sigma^2 (J'J)^-1 claims to measure; the model's misfit (the reference
// against the phantom's own truth) is a bias no interval from the noise can
// cover, and is the LV phantom fit tests' business.
//
// PFDM_CALIBRATION_SEEDS and PFDM_CALIBRATION_SCALE (points times this)
// enlarge the run for scripts/uncertainty_calibration.sh, which writes the
// table in docs/uncertainty.md from the lines printed here.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "gtest/gtest.h"
#include "pfdm/fit/stages/fitter.h"
#include "pfdm/io/fit_output.h"
#include "pfdm/phantom/lv_phantom.h"

namespace pfdm {
namespace {

constexpr int kKnots = 9;

// 100 seeds take 12-31 s a case on the project's 2-core VM (2026-12-06;
// 20 minutes at a load of 20-30 on 2026-12-02): run by
// scripts/uncertainty_calibration.py (PFDM_CALIBRATION_SEEDS set), which
// judges coverage and the shrinking at 4N.  Without it (CI) each case runs
// kCiSeeds draws, 1-3 s, and judges the errors in their sds: their rms
// about 1 where the intervals hold (kCiZ), above it where they are too
// narrow.
bool FullCalibrationAsked() {
  return std::getenv("PFDM_CALIBRATION_SEEDS") != nullptr;
}

constexpr int kCiSeeds = 10;
// 10 draws of some 20 correlated values: a calibrated case's pooled rms of
// (fit - reference) / sd read 0.74-0.91 over the cases (2026-12-06).
constexpr double kCiZLow = 0.5, kCiZHigh = 1.4;
// Tags through the wall: the radii's errors are larger than their sds say
// (rms 2.6 in sds over the 10 draws, 1.6 over 100, 2026-12-06; about 1
// where they hold).
constexpr double kWallRadiiZ = 1.5;

int EnvInt(const char* name, int fallback) {
  const char* value = std::getenv(name);
  return value == nullptr ? fallback : std::atoi(value);
}

struct Case {
  std::string name;
  LvTagLayer tags = LvTagLayer::kMidwall;
  LvSampling sampling = LvSampling::kTags;
  bool lesion = false;
  int num_points = 150;
  // Noise on the later frame only: frame 0's fit, which sets the tracked
  // tags' material points, is the noise-free one.
  bool exact_frame0 = false;
};

// The judged values: a1, a2, a3 (mm) at the knots away from the apex pole
// on both frames (frame 0's a3, held, has the length's sd alone), tau
// (rad) on the second where tags track the turn, and a solid's thickness h
// (mm; of tags through the wall, h after their noise is taken out of it,
// TakeOutTagNoise, a shift the covariance does not see).
struct Judged {
  int frame, function, knot;
};

// With frame 0 exact its values are the reference's: not judged.
std::vector<Judged> JudgedValues(const Case& c) {
  const bool tracked = c.sampling == LvSampling::kTags;
  std::vector<int> functions = {kA1, kA2, kA3};
  if (c.tags == LvTagLayer::kWall) functions.push_back(kH);
  std::vector<Judged> judged;
  for (int k : {2, 4, 6}) {
    if (!c.exact_frame0) {
      for (int f : functions) judged.push_back({0, f, k});
    }
    for (int f : functions) judged.push_back({1, f, k});
    if (tracked) judged.push_back({1, kTau, k});
  }
  return judged;
}

LvPhantomOptions PhantomOptions(const Case& c, unsigned seed, int num_points,
                                double noise_mm) {
  LvPhantomOptions options;
  options.num_frames = 2;
  options.num_tags = num_points;
  options.tags = c.tags;
  options.sampling = c.sampling;
  options.deformation.lesion = c.lesion;
  options.noise_mm = noise_mm;
  options.seed = seed;
  return options;
}

// Each judged value's fit (and its sd) for one draw.
struct Draw {
  std::vector<double> value, sd;
};

Draw FitDraw(const Case& c, unsigned seed, int num_points, double noise_mm) {
  LvPhantom phantom =
      MakeLvPhantom(PhantomOptions(c, seed, num_points, noise_mm));
  if (c.exact_frame0 && noise_mm > 0.0) {
    phantom.points.frames[0] =
        MakeLvPhantom(PhantomOptions(c, seed, num_points, 0.0))
            .points.frames[0];
  }
  FitOptions options;
  options.uncertainty = true;
  // Held depths shrink frame 0's depths by the tracked frames' noise,
  // which an exact frame 0 does not have (its h then read wide: 0.85-0.96
  // coverage on frame 1 over 100 draws): the exact case ranks.
  options.hold_tag_depths = !c.exact_frame0;
  // The covariance is the global model's; the local field after it
  // changes no knot value (docs/uncertainty.md), and would take most of
  // the test's time.
  options.local.enabled = false;
  const SequenceFit fit =
      FitSequence(phantom.points, ModelConfig::Paper(kKnots), options);
  Draw draw;
  for (const Judged& j : JudgedValues(c)) {
    const Model model = fit.ModelAt(j.frame);
    const double u = model.config.Grid().KnotU(j.knot);
    draw.value.push_back(ReportedValue(model, j.function, u));
    draw.sd.push_back(ReportedSd(model, fit.frames[j.frame].covariance,
                                 j.function, j.knot,
                                 LengthVariance(fit, j.frame)));
  }
  return draw;
}

struct Calibration {
  std::vector<Judged> judged;
  std::vector<int> inside;
  std::vector<double> sd_n, sd_4n;
  // Per value, the sum over the draws of ((fit - reference) / sd)^2.
  std::vector<double> z_square;
  int seeds = 0, ratio_seeds = 0;
  double Pooled() const {
    int sum = 0;
    for (int i : inside) sum += i;
    return sum / static_cast<double>(seeds * inside.size());
  }
  // The rms of the errors in sds over the draws and the values `take`s.
  template <typename Take>
  double ZRms(const Take& take) const {
    double sum = 0.0;
    int count = 0;
    for (size_t j = 0; j < judged.size(); ++j) {
      if (!take(judged[j])) continue;
      sum += z_square[j];
      count += seeds;
    }
    return std::sqrt(sum / count);
  }
  double ZRms() const {
    return ZRms([](const Judged&) { return true; });
  }
};

// Coverage of the noise-free fit by the 95 % intervals over `seeds` draws;
// sd at N and 4N points averaged over the first ratio_seeds.
Calibration Calibrate(const Case& c, int seeds, int ratio_seeds) {
  const int scale = EnvInt("PFDM_CALIBRATION_SCALE", 1);
  const int n = c.num_points * scale;
  Calibration result;
  result.judged = JudgedValues(c);
  const size_t m = result.judged.size();
  result.inside.assign(m, 0);
  result.sd_n.assign(m, 0.0);
  result.sd_4n.assign(m, 0.0);
  result.z_square.assign(m, 0.0);
  result.seeds = seeds;
  result.ratio_seeds = ratio_seeds;
  for (int s = 0; s < seeds; ++s) {
    const unsigned seed = 1000 + s;
    const Draw reference = FitDraw(c, seed, n, 0.0);
    const Draw noisy = FitDraw(c, seed, n, 0.5);
    for (size_t j = 0; j < m; ++j) {
      const double z = (noisy.value[j] - reference.value[j]) / noisy.sd[j];
      result.inside[j] += std::abs(z) <= 1.96;
      result.z_square[j] += z * z;
      if (s < ratio_seeds) result.sd_n[j] += noisy.sd[j] / ratio_seeds;
    }
    if (s < ratio_seeds) {
      const Draw large = FitDraw(c, seed, 4 * n, 0.5);
      for (size_t j = 0; j < m; ++j) {
        result.sd_4n[j] += large.sd[j] / ratio_seeds;
      }
    }
  }
  return result;
}

// "calibration CASE frame F FUNCTION knot K coverage C sd S -> S4 ratio R
// z Z" per value (Z the rms of its errors in sds), then the case's pooled
// coverage and rms: the script's table.
void Print(const Case& c, const Calibration& r) {
  for (size_t j = 0; j < r.judged.size(); ++j) {
    std::printf(
        "calibration %s frame %d %s knot %d coverage %.3f sd %.4g -> %.4g "
        "ratio %.3f z %.2f\n",
        c.name.c_str(), r.judged[j].frame, FunctionName(r.judged[j].function),
        r.judged[j].knot, r.inside[j] / double(r.seeds), r.sd_n[j], r.sd_4n[j],
        r.sd_4n[j] / r.sd_n[j], std::sqrt(r.z_square[j] / r.seeds));
  }
  std::printf("calibration %s pooled %.3f seeds %d points %d z %.2f\n",
              c.name.c_str(), r.Pooled(), r.seeds,
              c.num_points * EnvInt("PFDM_CALIBRATION_SCALE", 1), r.ZRms());
}

// What a case must show: its pooled coverage in [low, high], each value's
// at least min_each (100 draws: a binomial sd of 2.2 points at 95 %), and
// sd(4N)/sd(N) within 0.5 +- ratio_tolerance.
struct Expected {
  double low = 0.90, high = 0.98, min_each = 0.88, ratio_tolerance = 0.06;
};

Calibration RunCase(const Case& c) {
  const bool full = FullCalibrationAsked();
  const int seeds = full ? EnvInt("PFDM_CALIBRATION_SEEDS", 100) : kCiSeeds;
  const Calibration r = Calibrate(c, seeds, full ? std::min(seeds, 10) : 0);
  Print(c, r);
  return r;
}

// In CI (no full calibration asked), that the errors' rms in sds lies in
// kCiZLow-kCiZHigh; returns whether that was the check.
bool ExpectedCiZ(const Calibration& r, const std::string& name) {
  if (FullCalibrationAsked()) return false;
  EXPECT_GT(r.ZRms(), kCiZLow) << name;
  EXPECT_LT(r.ZRms(), kCiZHigh) << name;
  return true;
}

void ExpectCalibrated(const Case& c, const Expected& e = Expected()) {
  const Calibration r = RunCase(c);
  if (ExpectedCiZ(r, c.name)) return;
  EXPECT_GE(r.Pooled(), e.low) << c.name;
  EXPECT_LE(r.Pooled(), e.high) << c.name;
  for (size_t j = 0; j < r.judged.size(); ++j) {
    EXPECT_GE(r.inside[j], e.min_each * r.seeds) << c.name << " value " << j;
    const double ratio = r.sd_4n[j] / r.sd_n[j];
    // a3's length term (ReportedSd) is the noise of the highest points,
    // whose number grows with the points' but whose spread along the axis
    // does not: it shrinks more slowly (0.66-0.82 measured at 100 seeds).
    if (r.judged[j].function == kA3) {
      EXPECT_LT(ratio, 0.85) << c.name << " " << j;
      continue;
    }
    // The loss-free fit's regularizers scale with the points, and sigma's
    // degrees of freedom are the effective ones: 1/sqrt(4).
    EXPECT_NEAR(ratio, 0.5, e.ratio_tolerance) << c.name << " " << j;
  }
}

// Every value's coverage at least 90 % (CI: the errors' rms in sds
// within kCiZLow-kCiZHigh).
void ExpectEachHolds(const Calibration& r, const std::string& name) {
  if (ExpectedCiZ(r, name)) return;
  for (size_t j = 0; j < r.judged.size(); ++j) {
    EXPECT_GE(r.inside[j], 0.90 * r.seeds) << j;
  }
}

// 100 draws (seed 1000-1099), 150 tags: pooled 0.961, each value
// 0.93-1.00, sd ratio 0.46-0.51 (a3 0.65-0.79).  a3 carries frame 0's
// length error, its top's and its apex's (ReportedSd): without it the
// tracked frame's a3 covered 75-85 %, its material points sharing frame
// 0's error (below, MidwallTagsWithFrameZeroExact; docs/uncertainty.md).
TEST(LvUncertaintyCalibrationTest, MidwallTags) {
  ExpectCalibrated({"midwall-tags"});
}

// The tracked frame with frame 0 exact: a3 98-99 % with or without the
// length term (75-85 % with frame 0 noisy and without), a1, a2 and tau 95-99 %
// (100 draws, 2026-12-05).  Frame 0's error, which every tag's material point
// shares, is what the tracked frame's covariance leaves out; with noise on
// frame 1 alone nothing else is missing.  Frame 0's own values are the
// noise-free fit's and not judged.
TEST(LvUncertaintyCalibrationTest, MidwallTagsWithFrameZeroExact) {
  Case c{"midwall-tags-exact-frame0"};
  c.exact_frame0 = true;
  ExpectEachHolds(RunCase(c), c.name);
}

// Tags through the wall: the fit makes the model a solid, whose thickness,
// transmural twist and shift are in the covariance with the rest; each
// tag's depth w, ranked across the wall on frame 0 from the noisy data, is
// then held (its shrunk distance, the default since 2026-12-07).  The
// radii's intervals are too narrow: 77-87 % coverage on frame 1 over 100
// draws (2026-12-07; 76-90 % ranked in every frame), frame 0's 79-84 %;
// tau covers 95-99 %, h 93-99 % on frame 0 and 97-98 % on frame 1
// (99-100 % ranked).  Frame
// 0 is where the radii go wrong (below, WallTagsWithFrameZeroExact), and
// the tracked frame inherits its error.  Why frame 0: its depths, ranked
// in whole rings, keep the shape of the rounds' start, the mid-wall fit
// before the wall is decided (lv_wall_rank_shape_test.cc), and that fit's
// error from the noise is two to three times its Gauss-Newton sd; its
// spin, which its data fix least, follows the start's, which moves with
// the noise (docs/uncertainty.md, "The solid's start").  The test shows
// it: the radii's pooled coverage under 0.88, tau in 90-99 %, h at least
// 90 %.
TEST(LvUncertaintyCalibrationTest, WallTagsRadiiAreTooNarrow) {
  Case c{"wall-tags"};
  c.tags = LvTagLayer::kWall;
  const Calibration r = RunCase(c);
  if (!FullCalibrationAsked()) {
    const auto radius = [](const Judged& j) {
      return j.function == kA1 || j.function == kA2;
    };
    const auto tau = [](const Judged& j) { return j.function == kTau; };
    EXPECT_GT(r.ZRms(radius), kWallRadiiZ);
    EXPECT_GT(r.ZRms(tau), kCiZLow);
    EXPECT_LT(r.ZRms(tau), kCiZHigh);
    return;
  }
  int tau_inside = 0, tau_count = 0, radii_inside = 0, radii_count = 0;
  for (size_t j = 0; j < r.judged.size(); ++j) {
    const Judged& judged = r.judged[j];
    if (judged.function == kTau) {
      tau_inside += r.inside[j];
      tau_count += r.seeds;
      EXPECT_NEAR(r.sd_4n[j] / r.sd_n[j], 0.5, 0.06) << j;
    } else if (judged.function == kA1 || judged.function == kA2) {
      radii_inside += r.inside[j];
      radii_count += r.seeds;
    } else if (judged.function == kH) {
      EXPECT_GE(r.inside[j], 0.90 * r.seeds) << j;
    }
  }
  EXPECT_LT(radii_inside, 0.88 * radii_count);
  EXPECT_GE(tau_inside, 0.90 * tau_count);
  EXPECT_LE(tau_inside, 0.99 * tau_count);
}

// The same tags with frame 0 exact (noise on frame 1 only), ranked in
// every frame (FitDraw: held depths would shrink the exact depths by
// frame 1's noise): the tracked frame's radii cover 97-99 %, tau 98-99 %
// (100 draws, 2026-12-06).  Its own ranking of depths, afresh from its
// noisy tags, costs its intervals nothing; what it lacks above is frame
// 0's error.
TEST(LvUncertaintyCalibrationTest, WallTagsWithFrameZeroExact) {
  Case c{"wall-tags-exact-frame0"};
  c.tags = LvTagLayer::kWall;
  c.exact_frame0 = true;
  ExpectEachHolds(RunCase(c), c.name);
}

// Short-axis contours, re-searched every round: no tracked points, so tau
// is held and not judged.  Pooled 0.986, sd ratio 0.44-0.48 (frame 0's
// a3 0.71): the model's misfit of the slices' points counts in sigma as
// noise, so the intervals are a little wide; frame 1's a3 covers 100 %
// (docs/uncertainty.md).
TEST(LvUncertaintyCalibrationTest, SaxContours) {
  Case c{"sax-contours"};
  c.sampling = LvSampling::kSaxSlices;
  Expected e;
  e.high = 0.99;
  e.ratio_tolerance = 0.07;
  ExpectCalibrated(c, e);
}

// One wall's contours alone (the endocardium's, biv-me's lv-cavity; the
// epicardium's), the same slices: one surface, sought on that wall.
// 100 draws: pooled 0.984 and 0.974, every value 0.94-1.00.  The
// epicardium's frame 0 a3 covered 0.85 (sd 0.189 mm) while its length's sd
// held the top's draws alone; its error is mostly the fitted apex's (sd
// 0.351 mm along the axis, 0.147 on the endocardium), and with the apex's
// variance added (FrameCovariance::apex_length_variance) it covers 0.95
// (sd 0.244 mm; docs/uncertainty.md).
TEST(LvUncertaintyCalibrationTest, SaxOneWallsContours) {
  Expected e;
  e.high = 0.99;
  e.ratio_tolerance = 0.07;
  for (LvTagLayer wall : {LvTagLayer::kEndocardium, LvTagLayer::kEpicardium}) {
    Case c{"sax-" + LvTagLayerName(wall) + "-contours"};
    c.tags = wall;
    c.sampling = LvSampling::kSaxSlices;
    ExpectCalibrated(c, e);
  }
}

// Both walls' contours on the same slices (biv-me's lv-cavity,lv-epi): a
// solid, each wall's points sought on its own wall every round; h judged
// besides the radii.  100 draws (2026-12-06): pooled 0.986, each value
// 0.97-1.00, sd ratio 0.44-0.48 (frame 0's a3 0.66): like the mid-wall's
// contours, a little wide (the slices' misfit counts in sigma) and
// shrinking a little faster than 1/sqrt(4) as the regularizers scale with
// the points.  The later frame's a3 covered 0.89 while a top slice of 16
// points was read as no slice in a quarter of the fits (its rim 1 mm
// lower: NeededTopSectors).
TEST(LvUncertaintyCalibrationTest, SaxWallContours) {
  Case c{"sax-wall-contours"};
  c.tags = LvTagLayer::kWall;
  c.sampling = LvSampling::kSaxSlices;
  Expected e;
  e.high = 0.99;
  e.ratio_tolerance = 0.08;
  ExpectCalibrated(c, e);
}

// The lesion: a segment's contraction the global model cannot follow.
// Pooled 0.972, each value 0.93-1.00 (without a3's length term 0.923, the
// tracked frame's a3 79-90 %).
TEST(LvUncertaintyCalibrationTest, LesionMidwallTags) {
  Case c{"lesion-midwall-tags"};
  c.lesion = true;
  ExpectCalibrated(c);
}

}  // namespace
}  // namespace pfdm
