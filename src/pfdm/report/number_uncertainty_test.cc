#include "pfdm/report/number_uncertainty.h"

#include <cmath>
#include <cstdio>
#include <ctime>
#include <random>
#include <string>

#include "Eigen/Eigenvalues"
#include "gtest/gtest.h"
#include "pfdm/fit/stages/fitter.h"
#include "pfdm/fit/stages/frame_verdict.h"
#include "pfdm/phantom/lv_phantom.h"
#include "pfdm/report/tracked_response.h"
#include "pfdm/testing/test_util.h"

namespace pfdm {
namespace {

// Two frames (ED, ES) of the LV phantom's 400 mid-wall tags, fitted with
// the covariances.
struct Fitted {
  SequenceFit fit;
  FitAnalysis analysis;
};

// `frames` frames of the LV phantom's 400 tags (9 knots; mid-wall unless
// `layer` says), fitted with the covariances.
SequenceFit FitLvTags(int frames, int seed,
                      LvTagLayer layer = LvTagLayer::kMidwall) {
  LvPhantomOptions options;
  options.num_frames = frames;
  options.num_tags = 400;
  options.tags = layer;
  options.seed = seed;
  FitOptions fit_options;
  fit_options.uncertainty = true;
  return FitSequence(MakeLvPhantom(options).points, ModelConfig::Paper(9),
                     fit_options);
}

const Fitted& LvFit() {
  static const Fitted* fitted = [] {
    auto* f = new Fitted;
    f->fit = FitLvTags(2, 7);
    f->analysis = AnalyzeFit(f->fit);
    return f;
  }();
  return *fitted;
}

TEST(NumberUncertaintyTest, NudgedTurnsOnTheLeftAndMovesKnots) {
  const Fitted& f = LvFit();
  const Model model = f.analysis.models[1];
  const std::vector<CovarianceEntry> entries = {
      {CovarianceEntry::Kind::kRotation, -1, 2},
      {CovarianceEntry::Kind::kKnot, 3, kA1}};
  Eigen::Vector2d delta(0.01, 0.5);
  const Model nudged = Nudged(model, entries, delta);
  // The rotation about world z by 0.01 rad: R' = Rz R.
  const Eigen::Matrix3d turn =
      Eigen::AngleAxisd(0.01, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  EXPECT_LT((nudged.Rotation() - turn * model.Rotation()).norm(), 1e-12);
  EXPECT_NEAR(nudged.state.knots[3][kA1] - model.state.knots[3][kA1], 0.5,
              1e-15);
}

TEST(NumberUncertaintyTest, MeasureFrameGivesTheAnalysisNumbers) {
  const Fitted& f = LvFit();
  const FitAnalysis& a = f.analysis;
  const ReferenceSamples samples = SampleReference(a.models[0], a.layout);
  const std::vector<double> measured = Flatten(
      MeasureFrame(a.models[0], samples, a.regions, a.models[1], nullptr));
  const std::vector<double> analysis =
      Flatten({a.clinical[1], a.region_motion[1], a.strain[1]});
  ASSERT_EQ(measured.size(), analysis.size());
  for (size_t i = 0; i < measured.size(); ++i) {
    if (!Measured(analysis[i])) continue;  // Left out by the analysis.
    EXPECT_NEAR(measured[i], analysis[i], 1e-9 * (1.0 + std::abs(analysis[i])))
        << i;
  }
}

// Draws from N(0, C): V sqrt(lambda) z, C's negative eigenvalues (none
// but round-off's in a covariance) taken as 0.
class GaussianDraws {
 public:
  explicit GaussianDraws(const Eigen::MatrixXd& covariance) {
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(covariance);
    root_ = eigen.eigenvectors() *
            eigen.eigenvalues().cwiseMax(0.0).cwiseSqrt().asDiagonal();
  }
  Eigen::VectorXd Delta(std::mt19937* random) const {
    std::normal_distribution<double> normal;
    Eigen::VectorXd z(root_.cols());
    for (int i = 0; i < z.size(); ++i) z[i] = normal(*random);
    return root_ * z;
  }

 private:
  Eigen::MatrixXd root_;
};

// Draws of a frame's parameters from N(x, C).
class ParameterSampler {
 public:
  ParameterSampler(const Model& model, const FrameCovariance& covariance)
      : model_(model), covariance_(covariance), draws_(covariance.covariance) {}
  Eigen::VectorXd Delta(std::mt19937* random) const {
    return draws_.Delta(random);
  }
  Model At(const Eigen::VectorXd& delta) const {
    return Nudged(model_, covariance_.entries, delta);
  }

 private:
  const Model& model_;
  const FrameCovariance& covariance_;
  GaussianDraws draws_;
};

double Sd(const std::vector<double>& values) {
  double mean = 0.0, square = 0.0;
  for (double v : values) mean += v / values.size();
  for (double v : values) square += (v - mean) * (v - mean);
  return std::sqrt(square / (values.size() - 1));
}

// The three numbers at ES: the ejection fraction, a mid segment's Ecc and
// the radial contraction.
struct Sds {
  double ratio = 0.0, ecc = 0.0, radial = 0.0;
};

Eigen::Vector3d EsNumbers(const FitAnalysis& a, const Model& ed_model,
                          const Model& es_model, int segment) {
  const ReferenceSamples samples = SampleReference(ed_model, a.layout);
  const double edv =
      MeasureFrame(ed_model, samples, a.regions, ed_model, VolumePlaneOf(a, 0))
          .clinical.volume_ml;
  const FrameNumbers at_es =
      MeasureFrame(ed_model, samples, a.regions, es_model, VolumePlaneOf(a, 1));
  return {(edv - at_es.clinical.volume_ml) / edv,
          at_es.regions[segment].ecc_percent,
          at_es.clinical.radial_contraction_percent};
}

// Through held depths the delta method counts ED's noise in ES's depth
// noise E less what ED's model took up of it, the response through the
// depths M_w (tracked_response.h): per number g E g' - min(g M_w C_ED
// M_w' g', g E g'), which no Gaussian of ES's parameters need reproduce
// (E - M_w C_ED M_w' is not a covariance).  So it is added to the sampled
// rest's variance, g from ES's numbers measured here from scratch.
Eigen::Vector3d DepthVariances(const SequenceFit& fit, const FitAnalysis& a,
                               const TrackedResponse& response, int segment) {
  const FrameCovariance& es = fit.frames[1].covariance;
  if (response.through_wall.size() == 0 || es.depth_noise.size() == 0) {
    return Eigen::Vector3d::Zero();
  }
  const NumbersOf numbers = [&](const Model& moved) {
    const Eigen::Vector3d y = EsNumbers(a, a.models[0], moved, segment);
    return std::vector<double>{y[0], y[1], y[2]};
  };
  const Eigen::MatrixXd g = NumberJacobian(a.models[1], es, numbers);
  const Eigen::Vector3d own = Variances(g, es.depth_noise);
  return own - Variances(g * response.through_wall,
                         fit.frames[0].covariance.covariance)
                   .cwiseMin(own);
}

// The numbers' sds over 400 draws of both frames' parameters: ED's from
// its covariance, ES's from its own (less held depths' noise, added after)
// plus its response to ED's draw along the surface (tracked_response.h),
// ES turned with ED's spin, as the delta method does.
Sds SampledSds(const SequenceFit& fit, const FitAnalysis& a, int segment) {
  const TrackedResponse response = MeasureTrackedResponse(fit, 1);
  EXPECT_FALSE(response.Empty());
  const FrameCovariance& c1 = fit.frames[1].covariance;
  const bool depths = response.through_wall.size() > 0;
  EXPECT_EQ(depths, c1.depth_noise.size() > 0);
  const ParameterSampler ed(a.models[0], fit.frames[0].covariance);
  const GaussianDraws es(depths ? c1.covariance - c1.depth_noise
                                : c1.covariance);
  std::mt19937 random(11);
  std::vector<double> ratio, ecc, radial;
  for (int draw = 0; draw < 400; ++draw) {
    const Eigen::VectorXd ed_delta = ed.Delta(&random);
    const Model ed_model = ed.At(ed_delta);
    const Eigen::VectorXd es_delta =
        es.Delta(&random) + response.along_surface * ed_delta;
    const Model es_model = SpunWith(a.models[0], ed_model,
                                    Nudged(a.models[1], c1.entries, es_delta));
    const Eigen::Vector3d y = EsNumbers(a, ed_model, es_model, segment);
    ratio.push_back(y[0]);
    ecc.push_back(y[1]);
    radial.push_back(y[2]);
  }
  const Eigen::Vector3d depth = DepthVariances(fit, a, response, segment);
  const auto with = [](double sd, double variance) {
    return std::sqrt(sd * sd + variance);
  };
  return {with(Sd(ratio), depth[0]), with(Sd(ecc), depth[1]),
          with(Sd(radial), depth[2])};
}

// The delta method's sds against the sampled ones.  400 draws give a
// sample sd within about 3.5 % (1 / sqrt(2 x 400)) of the true one; the
// delta method's linearization adds a little: 12 % allowed.
void ExpectSampledSds(const SequenceFit& fit, const FitAnalysis& a) {
  ASSERT_TRUE(a.sd.computed);
  ASSERT_EQ(a.ejection_fraction.es_frame, 1);
  const int segment = 9;  // Mid 4 (0-based 9).
  const Sds sampled = SampledSds(fit, a, segment);
  // The delta method's own sds: the analysis's add the local field's
  // spread (local_field_noise.h), which these draws do not vary.
  const NumberSd delta = PropagateUncertainty(fit, a);
  const Sds sds{delta.ejection_fraction.ratio,
                delta.region_motion[1][segment].ecc_percent,
                delta.clinical[1].radial_contraction_percent};
  std::printf(
      "sd delta / sampled: EF %.5f / %.5f, Ecc %.4f / %.4f, radial "
      "contraction %.4f / %.4f\n",
      sds.ratio, sampled.ratio, sds.ecc, sampled.ecc, sds.radial,
      sampled.radial);
  EXPECT_GT(sds.ratio, 0.0);
  EXPECT_GT(sds.ecc, 0.0);
  EXPECT_NEAR(sds.ratio / sampled.ratio, 1.0, 0.12);
  EXPECT_NEAR(sds.ecc / sampled.ecc, 1.0, 0.12);
  EXPECT_NEAR(sds.radial / sampled.radial, 1.0, 0.12);
}

// Mid-wall tags.
TEST(NumberUncertaintyTest, DeltaMethodMatchesSampling) {
  ExpectSampledSds(LvFit().fit, LvFit().analysis);
}

// Tags through the wall (held depths), where ES follows ED's radii most
// (TrackedResponseTest): the ejection fraction's volumes share ED's
// parameters, which EjectionRatioSd takes in.
TEST(NumberUncertaintyTest, DeltaMethodMatchesSamplingThroughTheWall) {
  const SequenceFit fit = FitLvTags(2, 7, LvTagLayer::kWall);
  ASSERT_TRUE(fit.config.Solid());
  ExpectSampledSds(fit, AnalyzeFit(fit));
}

// ED turned about its axis by 0.1 rad and ES with it: every number of ES
// stays, to the sampling's round-off.
TEST(NumberUncertaintyTest, SpinOfEdTurnsEveryFrameAlike) {
  const FitAnalysis& a = LvFit().analysis;
  const Model& ed = a.models[0];
  Model turned = ed;
  const Eigen::Vector3d axis = ed.Rotation().col(2);
  const Eigen::Quaterniond q =
      Eigen::Quaterniond(Eigen::AngleAxisd(0.1, axis)) *
      Eigen::Quaterniond(ed.state.quaternion[0], ed.state.quaternion[1],
                         ed.state.quaternion[2], ed.state.quaternion[3]);
  turned.state.quaternion = {q.w(), q.x(), q.y(), q.z()};
  const Model es = SpunWith(ed, turned, a.models[1]);
  const Eigen::Vector3d moved =
      es.WorldPoint(0.1, 0.2) - turned.WorldPoint(0.1, 0.2);
  const Eigen::Vector3d before =
      Eigen::AngleAxisd(0.1, axis) *
      (a.models[1].WorldPoint(0.1, 0.2) - ed.WorldPoint(0.1, 0.2));
  EXPECT_LT((moved - before).norm(), 1e-9);
  const std::vector<double> original =
      Flatten({a.clinical[1], a.region_motion[1], a.strain[1]});
  const std::vector<double> spun = Flatten(MeasureFrame(
      turned, SampleReference(turned, a.layout), a.regions, es, nullptr));
  for (size_t i = 0; i < spun.size(); ++i) {
    if (!Measured(original[i])) continue;
    EXPECT_NEAR(spun[i], original[i], 1e-6 * (1.0 + std::abs(original[i])))
        << i;
  }
}

// The sds as first written (before FrameMeasurer): every step measures
// every number of every frame again from scratch; ES's numbers move with
// ED's parameters through ES's response too (tracked_response.h).
std::vector<Eigen::VectorXd> StraightforwardVariances(const SequenceFit& fit,
                                                      const FitAnalysis& a) {
  const Model& ed = a.models[0];
  const ReferenceSamples samples = SampleReference(ed, a.layout);
  std::vector<Eigen::VectorXd> variance(fit.frames.size());
  const NumbersOf own = [&](const Model& model) {
    return Flatten(MeasureFrame(ed, samples, a.regions, model, nullptr));
  };
  const FrameCovariance& c1 = fit.frames[1].covariance;
  const Eigen::MatrixXd own_jacobian = NumberJacobian(a.models[1], c1, own);
  variance[1] = Variances(own_jacobian, c1.covariance);
  const NumbersOf of_ed = [&](const Model& moved) {
    const ReferenceSamples moved_samples = SampleReference(moved, a.layout);
    std::vector<double> all =
        Flatten(MeasureFrame(moved, moved_samples, a.regions, moved, nullptr));
    const std::vector<double> es =
        Flatten(MeasureFrame(moved, moved_samples, a.regions,
                             SpunWith(ed, moved, a.models[1]), nullptr));
    all.insert(all.end(), es.begin(), es.end());
    return all;
  };
  const FrameCovariance& c0 = fit.frames[0].covariance;
  const Eigen::MatrixXd from_ed = NumberJacobian(ed, c0, of_ed);
  const Eigen::Index size = from_ed.rows() / 2;
  // Mid-wall tags: their depth is the surface's, held by nothing.
  const TrackedResponse tracked = MeasureTrackedResponse(fit, 1);
  EXPECT_EQ(tracked.through_wall.size(), 0);
  const Eigen::MatrixXd& response = tracked.along_surface;
  EXPECT_EQ(response.rows(), own_jacobian.cols());
  variance[0] = Variances(from_ed.topRows(size), c0.covariance);
  variance[1] += Variances(from_ed.bottomRows(size) + own_jacobian * response,
                           c0.covariance);
  return variance;
}

// PropagateUncertainty measures again only what each step moves
// (FrameMeasurer); its sds are those of measuring everything again, to
// the round-off of the volumes' batched trigonometry (1e-9 allowed).
TEST(NumberUncertaintyTest, SdsAreTheStraightforwardOnes) {
  const Fitted& f = LvFit();
  const std::clock_t start = std::clock();
  const std::vector<Eigen::VectorXd> variance =
      StraightforwardVariances(f.fit, f.analysis);
  const std::clock_t middle = std::clock();
  const NumberSd again = PropagateUncertainty(f.fit, f.analysis);
  std::printf("CPU s: from scratch %.2f, PropagateUncertainty %.2f\n",
              double(middle - start) / CLOCKS_PER_SEC,
              double(std::clock() - middle) / CLOCKS_PER_SEC);
  ASSERT_TRUE(again.computed);
  int compared = 0;
  for (size_t t = 0; t < 2; ++t) {
    // PropagateUncertainty's own: the analysis's add the local field's
    // spread (local_field_noise.h).
    FrameNumbers sds{again.clinical[t], again.region_motion[t],
                     again.strain[t]};
    const std::vector<double> kept = Flatten(sds);
    ASSERT_EQ(kept.size(), static_cast<size_t>(variance[t].size()));
    for (size_t i = 0; i < kept.size(); ++i) {
      if (!Measured(kept[i])) continue;  // Left out by the analysis.
      const double straightforward = std::sqrt(std::max(0.0, variance[t][i]));
      EXPECT_NEAR(kept[i], straightforward, 1e-9 * (1.0 + straightforward))
          << t << " " << i;
      compared += straightforward > 0.0;
    }
  }
  EXPECT_GT(compared, 100);
}

// The steps spread over threads (the fit's --threads) give one thread's
// sds to the bit: a step's measurement depends on no step before it, and
// each thread measures with FrameMeasurers of its own.  Three frames: on
// two threads each thread takes whole frames, on three the two frames'
// steps are shared out.
TEST(NumberUncertaintyTest, ThreadsGiveTheSameSdsToTheBit) {
  SequenceFit fit = FitLvTags(3, 8);
  ASSERT_EQ(fit.threads, 1);
  const FitAnalysis analysis = AnalyzeFit(fit);
  const NumberSd one = PropagateUncertainty(fit, analysis);
  ASSERT_TRUE(one.computed);
  const std::vector<double> sds = Flatten(one);
  int measured = 0;
  for (double sd : sds) measured += sd > 0.0;
  EXPECT_GT(measured, 200);
  for (int threads : {2, 3}) {
    fit.threads = threads;
    ExpectSameBits(sds, Flatten(PropagateUncertainty(fit, analysis)),
                   std::to_string(threads) + " threads");
  }
}

TEST(NumberUncertaintyTest, NotMeasuredNumbersHaveNoSd) {
  const Fitted& f = LvFit();
  const NumberSd& sd = f.analysis.sd;
  ASSERT_TRUE(sd.computed);
  for (size_t t = 0; t < sd.clinical.size(); ++t) {
    ClinicalSummary values = f.analysis.clinical[t];
    ClinicalSummary sds = sd.clinical[t];
    const std::vector<double*> v = ClinicalFields(&values);
    const std::vector<double*> s = ClinicalFields(&sds);
    for (size_t i = 0; i < v.size(); ++i) {
      EXPECT_EQ(Measured(*v[i]), Measured(*s[i])) << t << " " << i;
    }
  }
  // At ED, against itself: no strain, so no spread.
  EXPECT_NEAR(sd.strain[0].gcs_percent, 0.0, 1e-9);
  // ES's GCS spreads.
  EXPECT_GT(sd.strain[1].gcs_percent, 0.0);
}

// Data that do not reach the apex: the volumes, the mass and the ejection
// fraction, which take in the apex cap, keep their values and lose their
// intervals; the numbers measured from the data's own rings keep both.
TEST(NumberUncertaintyTest, NumbersWithTheUnseenApexCapHaveNoSd) {
  SequenceFit fit = LvFit().fit;
  fit.apex_in_data = false;
  const FitAnalysis unseen = AnalyzeFit(fit);
  const FitAnalysis& seen = LvFit().analysis;
  ASSERT_TRUE(unseen.sd.computed);
  for (size_t t = 0; t < 2; ++t) {
    EXPECT_EQ(unseen.clinical[t].volume_ml, seen.clinical[t].volume_ml);
    EXPECT_EQ(unseen.clinical[t].lv_mass_g, seen.clinical[t].lv_mass_g);
    for (double sd : {unseen.sd.clinical[t].volume_ml,
                      unseen.sd.clinical[t].myocardial_volume_ml,
                      unseen.sd.clinical[t].lv_mass_g}) {
      EXPECT_FALSE(Measured(sd)) << t;
    }
    EXPECT_TRUE(Measured(seen.sd.clinical[t].volume_ml)) << t;
  }
  EXPECT_EQ(unseen.ejection_fraction.ratio, seen.ejection_fraction.ratio);
  for (double sd :
       {unseen.sd.ejection_fraction.ratio, unseen.sd.ejection_fraction.edv_ml,
        unseen.sd.ejection_fraction.esv_ml}) {
    EXPECT_FALSE(Measured(sd));
  }
  EXPECT_GT(seen.sd.ejection_fraction.ratio, 0.0);
  EXPECT_GT(unseen.sd.clinical[1].radial_contraction_percent, 0.0);
  EXPECT_GT(unseen.sd.strain[1].gcs_percent, 0.0);
}

// A frame without a volume (short_span): its volume, the ESV and the
// ratio have no sd; ED's volume keeps its own, and the other numbers of the
// frame theirs.
TEST(NumberUncertaintyTest, AFrameWithoutAVolumeHasNoVolumeSd) {
  SequenceFit fit = LvFit().fit;
  fit.frames[1].verdict.Warn(kShortSpanCode, "the data span 53 %");
  const FitAnalysis analysis = AnalyzeFit(fit);
  ASSERT_TRUE(analysis.sd.computed);
  EXPECT_FALSE(Measured(analysis.sd.clinical[1].volume_ml));
  EXPECT_TRUE(Measured(analysis.sd.clinical[0].volume_ml));
  EXPECT_GT(analysis.sd.clinical[1].radial_contraction_percent, 0.0);
  const EjectionFraction& sd = analysis.sd.ejection_fraction;
  EXPECT_FALSE(Measured(sd.esv_ml));
  EXPECT_FALSE(Measured(sd.ratio));
  EXPECT_EQ(sd.edv_ml, analysis.sd.clinical[0].volume_ml);
}

TEST(NumberUncertaintyTest, WithoutCovariancesNothingIsComputed) {
  SequenceFit fit = LvFit().fit;
  fit.frames[1].covariance.computed = false;
  EXPECT_FALSE(AnalyzeFit(fit).sd.computed);
}

}  // namespace
}  // namespace pfdm
