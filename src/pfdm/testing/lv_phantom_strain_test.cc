// Lagrangian strain (report/surface_strain.h) of fits of the independent
// analytic LV phantom against the phantom's own strain, measured here on
// its mid-wall material points with the phantom's mapping alone (nothing
// of the model): the tangents of the ED mid-wall in nu and phi by central
// differences, moved by LvWorldPoint, through the same PlaneStrain.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <utility>

#include "gtest/gtest.h"
#include "pfdm/fit/fitter.h"
#include "pfdm/phantom/lv_phantom.h"
#include "pfdm/report/fit_analysis.h"
#include "pfdm/report/surface_strain.h"

namespace pfdm {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct PhantomStrain {
  double gcs_percent = 0.0;
  double gls_percent = 0.0;
  std::array<double, 16> ecc_percent{};
  std::array<double, 16> radial_contraction_percent{};  // From lv_truth.
};

// Segment of wall_motion's layout from ED height fraction h and body
// longitude phi (counter-clockwise about +z from -x at phi = -pi).
int SegmentOf(double h, double phi) {
  const int level = h >= 2.0 / 3.0 ? 0 : h >= 1.0 / 3.0 ? 1 : 2;
  const int sectors = level == 2 ? 4 : 6;
  const double turn = (phi + kPi) / (2 * kPi);
  return 6 * level +
         static_cast<int>(std::floor((turn - std::floor(turn)) * sectors)) %
             sectors;
}

// The phantom's strain at mid-wall material point (nu, phi) at `motion`.
SurfaceStrain TruthStrainAt(const LvShape& shape,
                            const LvDeformation& deformation,
                            const LvFrameMotion& motion, double nu,
                            double phi) {
  constexpr double kStep = 1e-6;
  auto body = [&](double n, double p) { return shape.Position(n, p, 0.0); };
  auto world = [&](double n, double p) {
    return LvWorldPoint(shape, deformation, motion, body(n, p));
  };
  const Eigen::Vector3d x_nu0 =
      (body(nu + kStep, phi) - body(nu - kStep, phi)) / (2 * kStep);
  const Eigen::Vector3d x_phi0 =
      (body(nu, phi + kStep) - body(nu, phi - kStep)) / (2 * kStep);
  const Eigen::Vector3d x_nu =
      (world(nu + kStep, phi) - world(nu - kStep, phi)) / (2 * kStep);
  const Eigen::Vector3d x_phi =
      (world(nu, phi + kStep) - world(nu, phi - kStep)) / (2 * kStep);
  return PlaneStrain(x_nu0, x_phi0, x_nu, x_phi, x_phi0, x_nu0);
}

// The mid-wall from its apex pole to the base plane on a grid of cells
// equal in nu and phi, each weighted by its ED area.
std::vector<PhantomStrain> PhantomTruthStrain(const LvPhantom& phantom) {
  const LvPhantomOptions& options = phantom.options;
  const LvShape shape(options.shape);
  const double nu_base = shape.BaseNu(0.0);
  constexpr int kRows = 90, kCols = 120;
  std::vector<PhantomStrain> frames;
  for (int t = 0; t < options.num_frames; ++t) {
    const LvFrameMotion motion = ScenarioMotion(
        options.kinematics, t, options.num_frames, options.breathing);
    PhantomStrain strain;
    std::array<double, 16> area{};
    double total = 0.0;
    for (int i = 0; i < kRows; ++i) {
      const double nu = nu_base * (i + 0.5) / kRows;
      for (int j = 0; j < kCols; ++j) {
        const double phi = -kPi + 2 * kPi * (j + 0.5) / kCols;
        const SurfaceStrain e =
            TruthStrainAt(shape, options.deformation, motion, nu, phi);
        constexpr double kStep = 1e-6;
        const Eigen::Vector3d x_nu0 = (shape.Position(nu + kStep, phi, 0.0) -
                                       shape.Position(nu - kStep, phi, 0.0)) /
                                      (2 * kStep);
        const double w =
            x_nu0.norm() * shape.Position(nu, phi, 0.0).head<2>().norm();
        const double h = shape.Position(nu, phi, 0.0).z() / shape.base_z();
        const int s = SegmentOf(h, phi);
        strain.gcs_percent += w * 100 * e.ecc;
        strain.gls_percent += w * 100 * e.ell;
        strain.ecc_percent[s] += w * 100 * e.ecc;
        area[s] += w;
        total += w;
      }
    }
    strain.gcs_percent /= total;
    strain.gls_percent /= total;
    for (int s = 0; s < 16; ++s) {
      strain.ecc_percent[s] /= area[s];
      strain.radial_contraction_percent[s] =
          phantom.truth[t].segments[s].radial_contraction_percent;
    }
    frames.push_back(strain);
  }
  return frames;
}

struct Fitted {
  LvPhantom phantom;
  FitAnalysis analysis;
  std::vector<PhantomStrain> truth;
};

Fitted FitPhantom(bool lesion,
                  LvKinematics kinematics = LvKinematics::kSystole) {
  LvPhantomOptions options;
  options.deformation.lesion = lesion;
  options.kinematics = kinematics;
  Fitted f{MakeLvPhantom(options), {}, {}};
  f.analysis = AnalyzeFit(
      FitSequence(f.phantom.points, ModelConfig::Paper(17), FitOptions()));
  f.truth = PhantomTruthStrain(f.phantom);
  return f;
}

StrainPeak PeakOf(const std::vector<PhantomStrain>& frames,
                  double PhantomStrain::*field) {
  StrainPeak peak;
  for (size_t t = 0; t < frames.size(); ++t) {
    if (frames[t].*field < peak.percent) {
      peak = {frames[t].*field, static_cast<int>(t)};
    }
  }
  return peak;
}

// The truth itself, against the design at mid-height (c = 0.22): Ecc of
// a circle shrunk by 1 - c is ((1 - c)^2 - 1) / 2 = -19.6 %.
TEST(LvPhantomStrainTest, TruthStrainFollowsTheDesign) {
  LvPhantomOptions options;
  options.noise_mm = 0.0;
  const std::vector<PhantomStrain> truth =
      PhantomTruthStrain(MakeLvPhantom(options));
  EXPECT_NEAR(truth.front().gcs_percent, 0.0, 1e-6);
  EXPECT_NEAR(truth.front().gls_percent, 0.0, 1e-6);
  const PhantomStrain& es = truth.back();
  for (int s = 6; s < 12; ++s) {
    EXPECT_NEAR(es.ecc_percent[s], 100 * (0.78 * 0.78 - 1) / 2, 0.3) << s;
  }
  std::printf("phantom truth at ES: GCS %.2f %%  GLS %.2f %%\n", es.gcs_percent,
              es.gls_percent);
  // Ecc runs with c from the apex (0.24) to the base (0.20).
  EXPECT_LT(es.ecc_percent[12], es.ecc_percent[6]);
  EXPECT_LT(es.ecc_percent[6], es.ecc_percent[0]);
  // Shortening by 17 % of a meridian that also contracts 20-24 %: GLS
  // between the Green-Lagrange strains of the two.
  EXPECT_LT(es.gls_percent, 100 * (0.83 * 0.83 - 1) / 2 + 1.0);
  EXPECT_GT(es.gls_percent, 100 * (0.76 * 0.76 - 1) / 2);
}

// Systole with breathing: peak GCS and GLS within 1.5 points of the
// phantom's; segments of a level uniform within 2 points of Ecc.
TEST(LvPhantomStrainTest, NormalSystolePeaksAndUniformSegments) {
  const Fitted f = FitPhantom(/*lesion=*/false);
  for (size_t t = 0; t < f.truth.size(); ++t) {
    std::printf("frame %zu  GCS %6.2f (truth %6.2f)  GLS %6.2f (truth %6.2f)\n",
                t, f.analysis.strain[t].gcs_percent, f.truth[t].gcs_percent,
                f.analysis.strain[t].gls_percent, f.truth[t].gls_percent);
  }
  const StrainPeak gcs = PeakGcs(f.analysis.strain);
  const StrainPeak gls = PeakGls(f.analysis.strain);
  const StrainPeak gcs_truth = PeakOf(f.truth, &PhantomStrain::gcs_percent);
  const StrainPeak gls_truth = PeakOf(f.truth, &PhantomStrain::gls_percent);
  std::printf("peak GCS %.2f %% (frame %d), truth %.2f %% (frame %d)\n",
              gcs.percent, gcs.frame, gcs_truth.percent, gcs_truth.frame);
  std::printf("peak GLS %.2f %% (frame %d), truth %.2f %% (frame %d)\n",
              gls.percent, gls.frame, gls_truth.percent, gls_truth.frame);
  EXPECT_NEAR(gcs.percent, gcs_truth.percent, 1.5);
  EXPECT_NEAR(gls.percent, gls_truth.percent, 1.5);
  EXPECT_EQ(gcs.frame, gcs_truth.frame);

  const std::vector<RegionMotion>& es = f.analysis.region_motion.back();
  const PhantomStrain& truth = f.truth.back();
  for (int s = 0; s < 16; ++s) {
    std::printf("segment %2d  Ecc %6.2f (truth %6.2f)  Ell %6.2f  Ecl %5.2f\n",
                s + 1, es[s].ecc_percent, truth.ecc_percent[s],
                es[s].ell_percent, es[s].ecl_percent);
  }
  const std::pair<int, int> levels[] = {{0, 6}, {6, 6}, {12, 4}};
  for (auto [first, count] : levels) {
    double low = 1e9, high = -1e9;
    for (int s = first; s < first + count; ++s) {
      low = std::min(low, es[s].ecc_percent);
      high = std::max(high, es[s].ecc_percent);
      EXPECT_NEAR(es[s].ecc_percent, truth.ecc_percent[s], 2.0) << s;
    }
    EXPECT_LT(high - low, 2.0) << "level from segment " << first + 1;
  }
}

// A full cycle (p = sin^2, 9 frames): every frame's GCS and GLS within 0.5
// point of the truth (0.2 measured), the peaks at mid-cycle (frame 4) and
// the strain back to 0 at the end.
TEST(LvPhantomStrainTest, CyclePeaksAtEndSystoleAndReturns) {
  const Fitted f = FitPhantom(/*lesion=*/false, LvKinematics::kCycle);
  for (size_t t = 0; t < f.truth.size(); ++t) {
    std::printf("frame %zu  GCS %6.2f (truth %6.2f)  GLS %6.2f (truth %6.2f)\n",
                t, f.analysis.strain[t].gcs_percent, f.truth[t].gcs_percent,
                f.analysis.strain[t].gls_percent, f.truth[t].gls_percent);
    EXPECT_NEAR(f.analysis.strain[t].gcs_percent, f.truth[t].gcs_percent, 0.5)
        << t;
    EXPECT_NEAR(f.analysis.strain[t].gls_percent, f.truth[t].gls_percent, 0.5)
        << t;
  }
  EXPECT_EQ(PeakGcs(f.analysis.strain).frame, 4);
  EXPECT_EQ(PeakGls(f.analysis.strain).frame, 4);
  EXPECT_NEAR(f.analysis.strain.back().gcs_percent, 0.0, 0.5);
  EXPECT_NEAR(f.analysis.strain.back().gls_percent, 0.0, 0.5);
}

// The lesion (mid 2, segment 8) with the global functions alone: a
// measured baseline for the local deformations, which should lift the
// mirror image.  Every ring is an ellipse, so mid 2 and its opposite mid 5
// read alike: the lesion is spread over both.  The truth of the segment's
// mean Ecc is dominated by the lesion's 5-degree edges, where the radius
// steps by 15 % and the circumference stretches: +18 %, against about
// -6.4 % inside the lesion ((1 - 0.3 c)^2 - 1) / 2, c = 0.22).
TEST(LvPhantomStrainTest, LesionBaselineOfTheGlobalModel) {
  const Fitted f = FitPhantom(/*lesion=*/true);
  const std::vector<RegionMotion>& es = f.analysis.region_motion.back();
  const PhantomStrain& truth = f.truth.back();
  for (int s = 6; s < 12; ++s) {
    std::printf(
        "segment %2d  Ecc %6.2f (truth %6.2f)  radial %6.2f (truth %6.2f)\n",
        s + 1, es[s].ecc_percent, truth.ecc_percent[s],
        es[s].radial_contraction_percent, truth.radial_contraction_percent[s]);
  }
  const LvShape shape(f.phantom.options.shape);
  const LvFrameMotion motion =
      ScenarioMotion(f.phantom.options.kinematics, 4, 5, true);
  const double centre_nu = shape.NuAtHeight(0.5 * shape.base_z(), 0.0);
  const double centre =
      100 * TruthStrainAt(shape, f.phantom.options.deformation, motion,
                          centre_nu, -kPi / 2)
                .ecc;
  std::printf("Ecc at the lesion's centre %.2f %%\n", centre);
  const double c = 0.22 * (1 - 0.7);
  EXPECT_NEAR(centre, 100 * ((1 - c) * (1 - c) - 1) / 2, 0.3);
  EXPECT_NEAR(truth.ecc_percent[7], 18.3, 1.0);
  // The global model: the mirror image, within 1 point.
  EXPECT_NEAR(es[7].ecc_percent, es[10].ecc_percent, 1.0);
  EXPECT_NEAR(es[7].radial_contraction_percent,
              es[10].radial_contraction_percent, 1.0);
}

}  // namespace
}  // namespace pfdm
