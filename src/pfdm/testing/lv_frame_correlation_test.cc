// Whether a tracked frame's errors and end-diastole's are correlated, and
// what the delta method makes of it (report/tracked_response.h).
//
// Each draw of the LV phantom's ED and ES (400 tags, 0.5 mm noise) is fitted
// with and without noise; a number of ES against ED (radial contraction,
// thickening) errs by a = f(ED noisy, ES noise-free) - f(noise-free), ED's
// part, plus b = f(ED noise-free, ES noisy) - f(noise-free), ES's part, each
// measured on the global models (the local field's share is sampled apart:
// local_field_noise.h).  The delta method's ED share is that of a with ES's
// response to ED's parameters, whose covariance with b is its own.
// PFDM_CALIBRATION_SEEDS draws (default 3); the table is printed.
#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

#include "gtest/gtest.h"
#include "pfdm/fit/stages/wall_stage.h"
#include "pfdm/report/frame_numbers.h"
#include "pfdm/testing/interval_calibration_table.h"
#include "pfdm/testing/lv_interval_cases.h"

namespace pfdm {
namespace {

using interval_cases::Case;
using interval_cases::kEs;
using interval_cases::PhantomOptions;

struct Drawn {
  SequenceFit fit;
  FitAnalysis analysis;
};

Drawn FitDraw(const Case& c, int seed, bool noise) {
  LvPhantomOptions options = PhantomOptions(c, seed);
  if (!noise) options.noise_mm = 0.0;
  FitOptions fit_options;
  fit_options.uncertainty = noise;
  Drawn drawn{FitSequence(MakeLvPhantom(options).points, ModelConfig::Paper(9),
                          fit_options),
              {}};
  drawn.analysis = AnalyzeFit(drawn.fit, {}, RegionLayout());
  return drawn;
}

// Each draw's fit with noise and without, tags through the wall, made
// once for the tests below.
struct DrawPair {
  Drawn noisy, free;
};

const std::vector<DrawPair>& WallDraws() {
  static const std::vector<DrawPair>* draws = [] {
    auto* out = new std::vector<DrawPair>;
    const Case c{LvTagLayer::kWall};
    for (int seed = 0; seed < CalibrationSeeds(); ++seed) {
      out->push_back({FitDraw(c, seed, true), FitDraw(c, seed, false)});
    }
    return out;
  }();
  return *draws;
}

// ES's numbers measured against ED's, each frame's global model from its
// own fit.
FrameNumbers Measure(const Drawn& ed_of, const Drawn& es_of) {
  const Model ed = GlobalModelOf(ed_of.fit.config, ed_of.fit.frames[0]);
  return MeasureFrame(ed, SampleReference(ed, ed_of.analysis.layout),
                      ed_of.analysis.regions,
                      GlobalModelOf(es_of.fit.config, es_of.fit.frames[kEs]),
                      VolumePlaneOf(es_of.analysis, kEs));
}

using Pick = std::function<double(const ClinicalSummary&)>;

// ES's sds with frame `zeroed`'s covariance set to 0 (-1: none).
ClinicalSummary EsSds(SequenceFit fit, const FitAnalysis& analysis,
                      int zeroed) {
  if (zeroed >= 0) {
    fit.frames[zeroed].covariance.covariance.setZero();
    fit.frames[zeroed].covariance.depth_noise.resize(0, 0);
  }
  return PropagateUncertainty(fit, analysis).clinical[kEs];
}

// ES's covariance zeroed: ED's direct share (the response is measured along
// ES's coordinates' sds, so it goes too); ED's zeroed: ES's own; neither.
struct Shares {
  ClinicalSummary ed_alone, own, all;
};

struct Sums {
  double aa = 0, bb = 0, ab = 0, ed_alone = 0, ed_followed = 0, own = 0;
};

void Add(const Drawn& noisy, const Drawn& free, const Shares& shares,
         const Pick& pick, Sums* s) {
  const double f0 = pick(Measure(free, free).clinical);
  const double a = pick(Measure(noisy, free).clinical) - f0;
  const double b = pick(Measure(free, noisy).clinical) - f0;
  s->aa += a * a;
  s->bb += b * b;
  s->ab += a * b;
  const double ed = pick(shares.ed_alone);
  const double own = pick(shares.own);
  const double all = pick(shares.all);
  s->ed_alone += ed * ed;
  // Through held depths ED's share is less than nothing where what ED's
  // model took up of ES's depth noise outweighs it.
  s->ed_followed += all * all - own * own;
  s->own += own * own;
}

double SignedRoot(double x) { return x < 0.0 ? -std::sqrt(-x) : std::sqrt(x); }

void Print(const char* name, const Sums& s, int n) {
  std::printf(
      "%-22s ED part rms %.3f, ES part %.3f, correlation %+.2f, error "
      "%.3f | delta: ED %.3f (alone %.3f), ES %.3f, sd %.3f (alone %.3f)\n",
      name, std::sqrt(s.aa / n), std::sqrt(s.bb / n),
      s.ab / std::sqrt(s.aa * s.bb), std::sqrt((s.aa + s.bb + 2 * s.ab) / n),
      SignedRoot(s.ed_followed / n), std::sqrt(s.ed_alone / n),
      std::sqrt(s.own / n), SignedRoot((s.ed_followed + s.own) / n),
      std::sqrt((s.ed_alone + s.own) / n));
}

// Through the wall (held depths) ES follows ED's errors: over 16 draws radial
// contraction's two parts were correlated -0.60 and the thickening's -0.26,
// and the delta method's ED share of radial contraction fell from 0.169 to
// 0.10 with ES's response (its sd 0.330 -> 0.305 against an error of
// 0.219; docs/uncertainty.md), and below nothing (-0.09, sd 0.270, 3
// draws) when ED's noise was counted once through the held depths (the
// next test).
TEST(LvFrameCorrelationTest, WallTagsFollowEndDiastole) {
  const Pick radial = [](const ClinicalSummary& s) {
    return s.radial_contraction_percent;
  };
  const Pick thickening = [](const ClinicalSummary& s) {
    return s.wall_thickening_percent;
  };
  Sums r, t;
  const int n = CalibrationSeeds();
  for (const auto& [noisy, free] : WallDraws()) {
    ASSERT_TRUE(noisy.fit.config.Solid());
    const Shares shares{EsSds(noisy.fit, noisy.analysis, kEs),
                        EsSds(noisy.fit, noisy.analysis, 0),
                        EsSds(noisy.fit, noisy.analysis, -1)};
    Add(noisy, free, shares, radial, &r);
    Add(noisy, free, shares, thickening, &t);
  }
  Print("radial contraction %", r, n);
  Print("wall thickening %", t, n);
  // The response, and the depth noise counted once, take a third or more
  // of ED's share off in every run.
  EXPECT_LT(r.ed_followed, 0.6 * r.ed_alone);
  EXPECT_LT(t.ed_followed, 0.9 * t.ed_alone);
  if (n >= 12) EXPECT_LT(r.ab / std::sqrt(r.aa * r.bb), -0.3);
}

// Through held depths ED's noise reaches ES twice in the delta method's
// terms: as ES's depth noise and as ED's model moving the depths, one
// error (tracked_response.h).  Over 40 draws ESV's sd read 1.26 ml where
// the two were added, against an error of 0.96; 1.08 with the shared part
// taken off.  Every run: taking it off narrows ESV's sd by a twentieth or
// more (3 draws: 1.171 -> 1.050; with the ES covariance's depth noise
// cleared nothing is taken off); with 12 or more draws the sd is within
// 25 % of the error.
TEST(LvFrameCorrelationTest, WallTagsCountEndDiastolesNoiseOnce) {
  double error = 0.0, sd = 0.0, kept = 0.0;
  const int n = CalibrationSeeds();
  for (const auto& [noisy, free] : WallDraws()) {
    ASSERT_FALSE(noisy.fit.frames[kEs].covariance.depth_noise.size() == 0);
    const double e = noisy.analysis.clinical[kEs].volume_ml -
                     free.analysis.clinical[kEs].volume_ml;
    const double once =
        PropagateUncertainty(noisy.fit, noisy.analysis).clinical[kEs].volume_ml;
    SequenceFit twice = noisy.fit;
    twice.frames[kEs].covariance.depth_noise.resize(0, 0);
    const double none =
        PropagateUncertainty(twice, noisy.analysis).clinical[kEs].volume_ml;
    error += e * e;
    sd += once * once;
    kept += none * none;
  }
  std::printf("ESV: error %.3f, sd %.3f (%.3f with nothing taken off)\n",
              std::sqrt(error / n), std::sqrt(sd / n), std::sqrt(kept / n));
  EXPECT_LT(sd, 0.95 * 0.95 * kept);
  if (n >= 12) EXPECT_NEAR(std::sqrt(sd / error), 1.0, 0.25);
}

}  // namespace
}  // namespace pfdm
