#include "pfdm/phantom/lv_phantom.h"

#include <algorithm>
#include <cmath>

#include "gtest/gtest.h"
#include "pfdm/util/error.h"

namespace pfdm {
namespace {

constexpr double kPi = 3.14159265358979323846;

LvPhantom Make(LvKinematics kinematics, double noise_mm = 0.0,
               int num_tags = 400) {
  LvPhantomOptions options;
  options.kinematics = kinematics;
  options.noise_mm = noise_mm;
  options.num_tags = num_tags;
  return MakeLvPhantom(options);
}

// Volume of surface w at progress p by discs, from the design: heights
// scale by 1 - LS p, each disc's area by (1 - c(h, w) p)^2 (twist turns
// discs, leaving their area).
double DesignedVolumeMl(const LvShape& shape, const LvDeformation& design,
                        double w, double p) {
  constexpr int kSlices = 4000;
  const double apex = shape.ApexZ(w), dz = (shape.base_z() - apex) / kSlices;
  double volume = 0.0;
  for (int i = 0; i < kSlices; ++i) {
    const double z = apex + (i + 0.5) * dz;
    const double r =
        shape.Position(shape.NuAtHeight(z, w), 0.0, w).x() *
        (1.0 - DesignedRadialContraction(design, z / shape.base_z(), w) * p);
    volume += kPi * r * r * dz;
  }
  return (1.0 - design.longitudinal_shortening * p) * volume / 1000.0;
}

TEST(LvPhantomTest, SystoleTruthIsTheDesign) {
  const LvPhantom phantom = Make(LvKinematics::kSystole);
  ASSERT_EQ(phantom.truth.size(), 5u);
  const LvShape shape;
  const LvDeformation design;
  const std::vector<double> heights = LvRingHeights();
  for (const LvFrameTruth& truth : phantom.truth) {
    const double p = truth.progress;
    EXPECT_NEAR(p, truth.frame / 4.0, 1e-15);
    EXPECT_NEAR(truth.longitudinal_shortening_percent, 17.0 * p, 1e-9);
    for (size_t i = 0; i < heights.size(); ++i) {
      const double h = heights[i];
      // The 2 degrees of breathing tilt read as < 0.01 degree of rotation.
      EXPECT_NEAR(truth.midwall.rotation_deg[i],
                  DesignedRotationDeg(design, h) * p, 0.01);
      EXPECT_NEAR(truth.endo.rotation_deg[i], truth.midwall.rotation_deg[i],
                  1e-9);
      EXPECT_NEAR(truth.midwall.radial_contraction_percent[i],
                  100.0 * DesignedRadialContraction(design, h, 0.0) * p, 1e-9);
      EXPECT_NEAR(truth.endo.radial_contraction_percent[i],
                  100.0 * DesignedRadialContraction(design, h, -1.0) * p, 1e-9);
      EXPECT_NEAR(truth.epi.radial_contraction_percent[i],
                  100.0 * DesignedRadialContraction(design, h, 1.0) * p, 1e-9);
    }
    for (double w : {-1.0, 0.0, 1.0}) {
      const double volume = w < 0   ? truth.endo_volume_ml
                            : w > 0 ? truth.epi_volume_ml
                                    : truth.volume_ml;
      EXPECT_NEAR(volume, DesignedVolumeMl(shape, design, w, p), 1e-3 * volume)
          << w;
    }
  }
  const LvFrameTruth& es = phantom.truth.back();
  EXPECT_NEAR(es.apex_rotation_deg, -10.0, 0.01);
  EXPECT_NEAR(es.base_rotation_deg, 3.0, 0.01);
  EXPECT_NEAR(es.net_twist_deg, 13.0, 0.01);
  // c_mid(h) = 24 - 4 h % averaged over h = 0.05 ... 1.00.
  EXPECT_NEAR(es.mean_radial_contraction_percent, 24.0 - 4.0 * 0.525, 1e-9);
  EXPECT_NEAR(es.midwall.rotation_deg[3], -7.4, 0.01);                // h = 0.2
  EXPECT_NEAR(es.midwall.rotation_deg[17], 1.7, 0.01);                // h = 0.9
  EXPECT_NEAR(es.midwall.radial_contraction_percent[9], 22.0, 1e-9);  // 0.5
  // ED and ES cavity volumes and ejection fraction.
  EXPECT_NEAR(phantom.truth[0].endo_volume_ml, 106.9, 0.1);
  EXPECT_NEAR(es.endo_volume_ml, 43.9, 0.1);
  EXPECT_NEAR(1.0 - es.endo_volume_ml / phantom.truth[0].endo_volume_ml, 0.589,
              0.002);
}

TEST(LvPhantomTest, EndDiastoleHasTheAnalyticVolumes) {
  const LvPhantom phantom = Make(LvKinematics::kStatic);
  const LvShape shape;
  for (const LvFrameTruth& truth : phantom.truth) {
    EXPECT_NEAR(truth.volume_ml, shape.ClosedVolume(0.0) / 1000.0,
                1e-3 * truth.volume_ml);
    EXPECT_NEAR(truth.endo_volume_ml, shape.ClosedVolume(-1.0) / 1000.0,
                1e-3 * truth.endo_volume_ml);
    EXPECT_NEAR(truth.myocardial_volume_ml,
                (shape.ClosedVolume(1.0) - shape.ClosedVolume(-1.0)) / 1000.0,
                1e-3 * truth.myocardial_volume_ml);
    EXPECT_EQ(truth.longitudinal_shortening_percent, 0.0);
    EXPECT_TRUE(truth.world_from_body.isApprox(LvWorldPose(), 1e-15));
  }
  for (int t = 1; t < 5; ++t) {
    for (size_t i = 0; i < 400; ++i) {
      EXPECT_EQ(phantom.points.frames[t].points[i].position,
                phantom.points.frames[0].points[i].position);
    }
  }
}

TEST(LvPhantomTest, RigidMotionChangesOnlyThePose) {
  const LvShape shape;
  const Eigen::Matrix3d r0 = LvWorldPose().linear();
  const Eigen::Vector3d axis = r0 * Eigen::Vector3d::UnitZ();
  for (LvKinematics kinematics :
       {LvKinematics::kRigidAxial, LvKinematics::kRigidLateral,
        LvKinematics::kRigidTilt, LvKinematics::kRigidSpin}) {
    SCOPED_TRACE(LvKinematicsName(kinematics));
    const LvPhantom phantom = Make(kinematics);
    const LvFrameTruth& ed = phantom.truth.front();
    for (const LvFrameTruth& truth : phantom.truth) {
      EXPECT_EQ(truth.progress, 0.0);
      EXPECT_NEAR(truth.longitudinal_shortening_percent, 0.0, 1e-9);
      EXPECT_NEAR(truth.volume_ml, ed.volume_ml, 1e-9);
      EXPECT_NEAR(truth.endo_volume_ml, ed.endo_volume_ml, 1e-9);
      for (const LvLayerRings* rings :
           {&truth.midwall, &truth.endo, &truth.epi}) {
        for (double c : rings->radial_contraction_percent) {
          EXPECT_NEAR(c, 0.0, 1e-9);
        }
      }
    }
    const LvFrameTruth& last = phantom.truth.back();
    // The motion relative to frame 0, in the world.
    const Eigen::Isometry3d move =
        last.world_from_body * ed.world_from_body.inverse();
    const Eigen::Vector3d centre =
        ed.world_from_body * Eigen::Vector3d(0, 0, 0.5 * shape.base_z());
    const double turned_deg =
        Eigen::AngleAxisd(move.linear()).angle() * 180.0 / kPi;
    const Eigen::Vector3d shift = move * centre - centre;
    for (size_t i = 0; i < last.midwall.rotation_deg.size(); ++i) {
      const double rotation = last.midwall.rotation_deg[i];
      switch (kinematics) {
        case LvKinematics::kRigidAxial:
          EXPECT_NEAR((shift - 8.0 * axis).norm(), 0.0, 1e-12);
          EXPECT_NEAR(rotation, 0.0, 1e-9);
          break;
        case LvKinematics::kRigidLateral:
          EXPECT_NEAR(shift.norm(), 5.0, 1e-12);
          EXPECT_NEAR(shift.dot(axis), 0.0, 1e-12);
          EXPECT_NEAR(rotation, 0.0, 1e-9);
          break;
        case LvKinematics::kRigidTilt:
          EXPECT_NEAR(shift.norm(), 0.0, 1e-12);
          EXPECT_NEAR(turned_deg, 8.0, 1e-9);
          EXPECT_NEAR(std::acos((move.linear() * axis).dot(axis)) * 180.0 / kPi,
                      8.0, 1e-6);
          // A tilt reads a little as rotation about the old axis.
          EXPECT_NEAR(rotation, 0.0, 0.3);
          break;
        default:
          EXPECT_NEAR(shift.norm(), 0.0, 1e-12);
          EXPECT_NEAR(turned_deg, 10.0, 1e-9);
          EXPECT_NEAR(rotation, 10.0, 1e-9);
          EXPECT_NEAR(last.endo.rotation_deg[i], 10.0, 1e-9);
          break;
      }
    }
  }
}

TEST(LvPhantomTest, CycleReturnsToEndDiastole) {
  const LvPhantom phantom = Make(LvKinematics::kCycle);
  ASSERT_EQ(phantom.points.frames.size(), 9u);
  const LvFrameTruth& es = phantom.truth[4];
  EXPECT_NEAR(es.progress, 1.0, 1e-15);
  EXPECT_NEAR(es.longitudinal_shortening_percent, 17.0, 1e-9);
  const LvFrameTruth& last = phantom.truth.back();
  EXPECT_EQ(last.progress, 0.0);
  EXPECT_TRUE(
      last.world_from_body.isApprox(phantom.truth[0].world_from_body, 1e-15));
  EXPECT_NEAR(last.longitudinal_shortening_percent, 0.0, 1e-12);
  EXPECT_NEAR(last.volume_ml, phantom.truth[0].volume_ml, 1e-12);
  for (size_t i = 0; i < last.midwall.rotation_deg.size(); ++i) {
    EXPECT_NEAR(last.midwall.rotation_deg[i], 0.0, 1e-12);
    EXPECT_NEAR(last.endo.radial_contraction_percent[i], 0.0, 1e-12);
  }
  for (size_t i = 0; i < 400; ++i) {
    EXPECT_NEAR((phantom.points.frames.back().points[i].position -
                 phantom.points.frames[0].points[i].position)
                    .norm(),
                0.0, 1e-12);
  }
  // Frames 3 and 5 mirror each other about end-systole.
  EXPECT_NEAR(phantom.truth[3].endo_volume_ml, phantom.truth[5].endo_volume_ml,
              1e-9);
}

TEST(LvPhantomTest, TagsAreTrackedMaterialPoints) {
  LvPhantomOptions options;
  options.num_tags = 500;
  options.noise_mm = 0.0;
  const LvPhantom phantom = MakeLvPhantom(options);
  const LvShape shape;
  ASSERT_EQ(phantom.points.frames.size(), 5u);
  double closest_to_apex = 1e9;
  for (size_t t = 0; t < 5; ++t) {
    const Frame& frame = phantom.points.frames[t];
    EXPECT_EQ(frame.index, static_cast<int>(t));
    ASSERT_EQ(frame.points.size(), 500u);
    const LvFrameMotion motion =
        ScenarioMotion(LvKinematics::kSystole, t, 5, true);
    for (size_t i = 0; i < 500; ++i) {
      EXPECT_EQ(frame.points[i].id, static_cast<int>(i));
      EXPECT_NEAR((frame.points[i].position -
                   LvWorldPoint(shape, options.deformation, motion,
                                phantom.tag_material[i]))
                      .norm(),
                  0.0, 1e-9);
    }
  }
  int short_axis_basal = 0;
  for (size_t i = 0; i < 500; ++i) {
    const Eigen::Vector3d& x = phantom.tag_material[i];
    EXPECT_NEAR(shape.Transmural(x), 0.0, 1e-9);
    EXPECT_GE(x.z(), -1e-9);
    EXPECT_LE(x.z(), shape.base_z() + 1e-9);
    closest_to_apex = std::min(closest_to_apex, x.norm());
    if (i % 2 == 0 && x.z() > 2.0 / 3.0 * shape.base_z()) ++short_axis_basal;
  }
  // Long-axis tags reach the apex; short-axis ones are uniform in height.
  EXPECT_LT(closest_to_apex, 2.0);
  EXPECT_NEAR(short_axis_basal / 250.0, 1.0 / 3.0, 0.1);
}

TEST(LvPhantomTest, WallTagsSpanTheWall) {
  LvPhantomOptions options;
  options.tags = LvTagLayer::kWall;
  options.num_tags = 1000;
  options.noise_mm = 0.0;
  const LvPhantom phantom = MakeLvPhantom(options);
  const LvShape shape;
  double lowest = 1, highest = -1, sum = 0;
  for (const Eigen::Vector3d& x : phantom.tag_material) {
    const double w = shape.Transmural(x);
    lowest = std::min(lowest, w);
    highest = std::max(highest, w);
    sum += w;
    EXPECT_LE(x.z(), shape.base_z() + 1e-9);
  }
  EXPECT_GE(lowest, -1.0 - 1e-9);
  EXPECT_LE(highest, 1.0 + 1e-9);
  EXPECT_LT(lowest, -0.98);
  EXPECT_GT(highest, 0.98);
  EXPECT_NEAR(sum / 1000.0, 0.0, 0.1);  // Uniform: sd 0.58 / sqrt(1000).
}

TEST(LvPhantomTest, NoiseHasTheRequestedSpread) {
  const LvPhantom clean = Make(LvKinematics::kSystole, 0.0, 2000);
  const LvPhantom noisy = Make(LvKinematics::kSystole, 0.5, 2000);
  double sum = 0.0, squares = 0.0;
  int count = 0;
  for (size_t t = 0; t < 5; ++t) {
    for (size_t i = 0; i < 2000; ++i) {
      const Eigen::Vector3d e = noisy.points.frames[t].points[i].position -
                                clean.points.frames[t].points[i].position;
      for (int k = 0; k < 3; ++k) {
        sum += e[k];
        squares += e[k] * e[k];
        ++count;
      }
    }
  }
  // 30,000 draws: the mean within 4 standard errors (0.003 mm), the
  // standard deviation within 2 % (its standard error is 0.4 %).
  EXPECT_NEAR(sum / count, 0.0, 0.012);
  EXPECT_NEAR(std::sqrt(squares / count), 0.5, 0.01);
}

// 5 % outliers among 2,000 tags x 5 frames: the truth lists the points that
// moved, each 5-10 mm from its place without outliers (the same seed), in
// directions that average out; every other point is where it was.  A larger
// fraction moves a superset, each point by the same vector.
TEST(LvPhantomTest, OutliersMoveTheListedPointsOnly) {
  LvPhantomOptions options;
  const LvPhantom clean = MakeLvPhantom(options);
  options.outlier_fraction = 0.05;
  const LvPhantom dirty = MakeLvPhantom(options);
  options.outlier_fraction = 0.1;
  const LvPhantom dirtier = MakeLvPhantom(options);
  int count = 0;
  Eigen::Vector3d mean_direction = Eigen::Vector3d::Zero();
  double shortest = 1e9, longest = 0.0, sum = 0.0;
  for (size_t t = 0; t < 5; ++t) {
    const std::vector<int>& ids = dirty.truth[t].outlier_ids;
    EXPECT_TRUE(std::is_sorted(ids.begin(), ids.end()));
    const std::vector<int>& more = dirtier.truth[t].outlier_ids;
    EXPECT_TRUE(std::includes(more.begin(), more.end(), ids.begin(), ids.end()))
        << t;
    for (int i = 0; i < 2000; ++i) {
      const Eigen::Vector3d e = dirty.points.frames[t].points[i].position -
                                clean.points.frames[t].points[i].position;
      if (!std::binary_search(ids.begin(), ids.end(), i)) {
        EXPECT_EQ(e.norm(), 0.0) << t << " " << i;
        continue;
      }
      ++count;
      shortest = std::min(shortest, e.norm());
      longest = std::max(longest, e.norm());
      sum += e.norm();
      mean_direction += e.normalized();
      EXPECT_EQ((dirtier.points.frames[t].points[i].position -
                 dirty.points.frames[t].points[i].position)
                    .norm(),
                0.0);
    }
  }
  // 10,000 draws at 5 %: 500 expected, sd 22.
  EXPECT_NEAR(count, 500, 70);
  EXPECT_GE(shortest, 5.0);
  EXPECT_LE(longest, 10.0);
  EXPECT_LT(shortest, 5.1);
  EXPECT_GT(longest, 9.9);
  EXPECT_NEAR(sum / count, 7.5, 0.25);  // Uniform: sd 1.44 / sqrt(500).
  // Unit vectors uniform on the sphere: each coordinate's mean has sd
  // 0.58 / sqrt(500) = 0.026.
  EXPECT_LT((mean_direction / count).cwiseAbs().maxCoeff(), 0.1);
  EXPECT_TRUE(clean.truth[2].outlier_ids.empty());
}

// Area-weighted mean height fraction of the mid-wall between h0 and h1.
double MeanHeight(const LvShape& shape, double h0, double h1) {
  constexpr int kSlices = 3000;
  double area = 0.0, moment = 0.0;
  for (int i = 0; i < kSlices; ++i) {
    const double a = h0 + (h1 - h0) * i / kSlices;
    const double b = h0 + (h1 - h0) * (i + 1) / kSlices;
    const Eigen::Vector3d pa =
        shape.Position(shape.NuAtHeight(a * shape.base_z(), 0.0), 0.0, 0.0);
    const Eigen::Vector3d pb =
        shape.Position(shape.NuAtHeight(b * shape.base_z(), 0.0), 0.0, 0.0);
    const double band = (pa.x() + pb.x()) * (pb - pa).norm();  // / pi
    area += band;
    moment += band * 0.5 * (a + b);
  }
  return moment / area;
}

TEST(LvPhantomTest, SegmentsAverageTheDesignOverTheirArea) {
  const LvPhantom phantom = Make(LvKinematics::kSystole, 0.0, 10);
  const LvShape shape;
  const LvDeformation design;
  // c and theta are linear in h: a segment's mean is their value at its
  // area-weighted mean height.
  const double mean_h[3] = {MeanHeight(shape, 2.0 / 3.0, 1.0),
                            MeanHeight(shape, 1.0 / 3.0, 2.0 / 3.0),
                            MeanHeight(shape, 0.0, 1.0 / 3.0)};
  for (const LvSegmentTruth& segment : phantom.truth.back().segments) {
    const double h = mean_h[segment.segment <= 6    ? 0
                            : segment.segment <= 12 ? 1
                                                    : 2];
    EXPECT_NEAR(segment.radial_contraction_percent,
                100.0 * DesignedRadialContraction(design, h, 0.0), 0.01)
        << segment.name;
    // The breathing tilt reads as a few hundredths of a degree.
    EXPECT_NEAR(segment.rotation_deg, DesignedRotationDeg(design, h), 0.05)
        << segment.name;
  }
}

TEST(LvPhantomTest, LesionWeakensMidSegmentTwoOnly) {
  LvPhantomOptions options;
  options.num_tags = 10;
  options.noise_mm = 0.0;
  const LvPhantom normal = MakeLvPhantom(options);
  options.deformation.lesion = true;
  const LvPhantom lesion = MakeLvPhantom(options);
  const auto& before = normal.truth.back().segments;
  const auto& after = lesion.truth.back().segments;
  ASSERT_EQ(after.size(), 16u);
  EXPECT_EQ(after[7].name, "mid 2");
  // Normal mid segments: c_mid at their centre height, 22 %.
  EXPECT_NEAR(before[7].radial_contraction_percent, 22.0, 0.05);
  // The lesion keeps 30 % of the contraction where it is whole (6.6 %);
  // its edges (20 degrees, 0.1 of the height) and the centroids of its
  // rings, pulled toward the weak sector, bring the segment's mean,
  // measured, to 15.89 %.
  EXPECT_NEAR(after[7].radial_contraction_percent, 15.89, 0.05);
  for (int s : {0, 1, 2, 3, 4, 5, 12, 13, 14, 15}) {  // Basal and apical.
    EXPECT_NEAR(after[s].radial_contraction_percent,
                before[s].radial_contraction_percent, 1e-9)
        << after[s].name;
    EXPECT_NEAR(after[s].rotation_deg, before[s].rotation_deg, 1e-9);
  }
  // That pull moves the other mid segments' numbers too (by the
  // definition): contraction by up to 2 points, rotation by up to 1.3
  // degrees (design: 22 % and -3.5 degrees at mid-height).
  for (int s : {6, 8, 9, 10, 11}) {
    EXPECT_NEAR(after[s].radial_contraction_percent,
                before[s].radial_contraction_percent, 2.1)
        << after[s].name;
    EXPECT_NEAR(after[s].rotation_deg, before[s].rotation_deg, 1.4)
        << after[s].name;
  }
}

// A mid-ventricular segment: every tag between 30 and 72 % of the height,
// both halves (short- and long-axis planes) reaching both ends; a squat
// cloud, wider than long; the truth the whole LV's, as for full data.
TEST(LvPhantomTest, MidventricularTagsLieBetweenTheirHeights) {
  LvPhantomOptions options;
  options.region = LvRegion::kMidventricular;
  options.tags = LvTagLayer::kWall;
  options.num_tags = 1000;
  options.noise_mm = 0.0;
  const LvPhantom phantom = MakeLvPhantom(options);
  const LvShape shape;
  const LvPhantom full = Make(LvKinematics::kSystole);
  ASSERT_EQ(phantom.tag_material.size(), 1000u);
  double low[2] = {1, 1}, high[2] = {0, 0}, widest = 0;
  for (size_t i = 0; i < phantom.tag_material.size(); ++i) {
    const Eigen::Vector3d& x = phantom.tag_material[i];
    const double h = x.z() / shape.base_z();
    low[i % 2] = std::min(low[i % 2], h);
    high[i % 2] = std::max(high[i % 2], h);
    widest = std::max(widest, x.head<2>().norm());
  }
  for (int half : {0, 1}) {
    EXPECT_GE(low[half], 0.30 - 1e-12);
    EXPECT_LT(low[half], 0.31);
    EXPECT_LE(high[half], 0.72 + 1e-12);
    EXPECT_GT(high[half], 0.71);
  }
  // 40 mm long, 64 mm across the epicardium.
  EXPECT_NEAR((high[0] - low[0]) * shape.base_z(), 39.9, 0.5);
  EXPECT_NEAR(2 * widest, 64.0, 1.0);
  EXPECT_EQ(phantom.truth.back().net_twist_deg,
            full.truth.back().net_twist_deg);
  EXPECT_EQ(phantom.points.frames[3].points[17].id, 17);
}

TEST(LvPhantomTest, NamesItsRegionsAndSamplings) {
  LvRegion region;
  LvSampling sampling;
  EXPECT_TRUE(ParseLvRegion("midventricular", &region));
  EXPECT_EQ(LvRegionName(region), "midventricular");
  EXPECT_TRUE(ParseLvRegion("full", &region));
  EXPECT_EQ(region, LvRegion::kFull);
  EXPECT_FALSE(ParseLvRegion("apical", &region));
  EXPECT_TRUE(ParseLvSampling("sax-slices", &sampling));
  EXPECT_EQ(LvSamplingName(sampling), "sax-slices");
  EXPECT_TRUE(ParseLvSampling("tags", &sampling));
  EXPECT_EQ(sampling, LvSampling::kTags);
  EXPECT_FALSE(ParseLvSampling("lax", &sampling));
  LvPhantomOptions options;
  EXPECT_EQ(LvSliceHeights(options).size(), 9u);
  options.region = LvRegion::kMidventricular;
  EXPECT_EQ(LvSliceHeights(options), (std::vector<double>{0.30, 0.51, 0.72}));
  options.num_slices = 1;
  EXPECT_EQ(LvSliceHeights(options), std::vector<double>{0.51});
}

TEST(LvPhantomTest, RejectsBadOptions) {
  LvPhantomOptions options;
  options.num_tags = 0;
  EXPECT_THROW(MakeLvPhantom(options), InputError);
  options.num_tags = 10;
  options.noise_mm = -1;
  EXPECT_THROW(MakeLvPhantom(options), InputError);
  options.noise_mm = 0;
  options.outlier_fraction = 1.5;
  EXPECT_THROW(MakeLvPhantom(options), InputError);
  options.outlier_fraction = 0.1;
  options.outlier_min_mm = 10.0;
  options.outlier_max_mm = 5.0;
  EXPECT_THROW(MakeLvPhantom(options), InputError);
  options.outlier_max_mm = 20.0;
  EXPECT_NO_THROW(MakeLvPhantom(options));
  options.shape.wall_mm = 40.0;  // Thicker than the radius.
  EXPECT_THROW(MakeLvPhantom(options), InputError);
  options.shape.wall_mm = 10.0;
  options.shape.base_nu_deg = 80.0;  // Widest at the base.
  EXPECT_THROW(MakeLvPhantom(options), InputError);
  options.shape.base_nu_deg = 120.0;
  options.num_slices = -1;
  EXPECT_THROW(MakeLvPhantom(options), InputError);
  options.sampling = LvSampling::kSaxSlices;
  options.num_slices = 11;  // 10 points for 11 contours.
  EXPECT_THROW(MakeLvPhantom(options), InputError);
}

}  // namespace
}  // namespace pfdm
