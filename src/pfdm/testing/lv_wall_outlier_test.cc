// The wall choice (fit/stages/wall_stage.h) on the independent LV phantom
// with 5 % outliers: tags 5-10 mm off must not read as a wall, nor widen a
// wall the tags do fill.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>

#include "Eigen/Core"
#include "gtest/gtest.h"
#include "pfdm/fit/stages/fitter.h"
#include "pfdm/phantom/lv_phantom.h"
#include "pfdm/report/clinical_summary.h"

namespace pfdm {
namespace {

constexpr double kOutlierFraction = 0.05;

// Moves kOutlierFraction of every frame's points (exactly, by a draw
// without replacement) by 5-10 mm in a direction uniform on the sphere.
// Each frame draws its own points and offsets: a tracker fails frame by
// frame (a tag taken for its neighbour on the next stripe, found again
// later), which is also the harder case for the frames after the first,
// whose tags then keep a frame-0 material point that may be off while
// their own position is not.  The wall is decided on frame 0 alone, which
// has its 5 % either way.  (Until the LV phantom has an outlier option of
// its own.)
void AddOutliers(PointSequence* sequence, unsigned seed) {
  std::mt19937 random(seed);
  std::normal_distribution<double> direction(0.0, 1.0);
  std::uniform_real_distribution<double> length(5.0, 10.0);
  for (Frame& frame : sequence->frames) {
    std::vector<size_t> order(frame.points.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::shuffle(order.begin(), order.end(), random);
    const size_t count =
        static_cast<size_t>(std::lround(kOutlierFraction * order.size()));
    for (size_t k = 0; k < count; ++k) {
      Eigen::Vector3d offset(direction(random), direction(random),
                             direction(random));
      frame.points[order[k]].position += length(random) * offset.normalized();
    }
  }
}

struct OutlierFit {
  SequenceFit fit;
  std::vector<ClinicalSummary> clinical;
};

OutlierFit Fit(LvTagLayer tags, bool outliers) {
  LvPhantomOptions options;
  options.tags = tags;
  LvPhantom phantom = MakeLvPhantom(options);
  // Seed 6: outliers whose spread with the rest, 4.0 mm, made the fit a
  // solid before the spread left outliers out.
  if (outliers) AddOutliers(&phantom.points, 6);
  OutlierFit result;
  result.fit =
      FitSequence(phantom.points, ModelConfig::Paper(17), FitOptions());
  std::vector<Model> models;
  for (size_t t = 0; t < result.fit.frames.size(); ++t) {
    models.push_back(result.fit.ModelAt(t));
  }
  result.clinical = SummarizeSequence(models);
  std::printf("%s tags%s: %s\n", LvTagLayerName(tags).c_str(),
              outliers ? " with outliers" : "", result.fit.wall_reason.c_str());
  return result;
}

// How many tags wall_reason says it left out as outliers.
int OutliersLeftOut(const std::string& reason) {
  const size_t at = reason.find(" mm across the wall, ");
  return at == std::string::npos ? -1 : std::stoi(reason.substr(at + 21));
}

// The thickness the solid started from, as wall_reason says it.
double StartThickness(const std::string& reason) {
  const size_t end = reason.find(" mm thick to start");
  const size_t begin = reason.rfind(", ", end);
  if (end == std::string::npos || begin == std::string::npos) return -1.0;
  return std::stod(reason.substr(begin + 2, end - begin - 2));
}

// Mid-wall tags with 5 % outliers spread 4.0 mm measured on all of them
// (3.4-4.0 over the first eight seeds), and the fit chose a solid whose
// "cavity" read 128.5 / 63.2 ml.  Left out, the rest spread 1.8 mm, as
// without outliers (1.7): one surface, whose volumes stay within 8 % of the
// same fit without outliers (0.2 % here; the outliers' pull on the
// least-squares fit reaches 6.2 % with other seeds, which a robust loss,
// not the wall, is for).
TEST(LvWallOutlierTest, MidwallTagsWithOutliersKeepOneSurface) {
  const OutlierFit clean = Fit(LvTagLayer::kMidwall, false);
  const OutlierFit noisy = Fit(LvTagLayer::kMidwall, true);
  ASSERT_FALSE(noisy.fit.config.Solid()) << noisy.fit.wall_reason;
  EXPECT_FALSE(noisy.clinical.back().solid);
  EXPECT_NE(noisy.fit.wall_reason.find(": one surface (under 4.0 mm)"),
            std::string::npos);
  const double spread = std::stod(noisy.fit.wall_reason.substr(12));
  EXPECT_NEAR(spread, std::stod(clean.fit.wall_reason.substr(12)), 0.3);
  // 100 outliers, two-thirds of them more than 2.4 mm off the wall (an
  // offset of 5-10 mm in a random direction has a normal part uniform up
  // to its length): 66.
  EXPECT_GE(OutliersLeftOut(noisy.fit.wall_reason), 55);
  EXPECT_LE(OutliersLeftOut(noisy.fit.wall_reason), 100);
  EXPECT_EQ(OutliersLeftOut(clean.fit.wall_reason), 0);
  for (size_t t : {size_t{0}, clean.clinical.size() - 1}) {
    std::printf("frame %zu volume %.1f ml (without outliers %.1f)\n", t,
                noisy.clinical[t].volume_ml, clean.clinical[t].volume_ml);
    EXPECT_NEAR(noisy.clinical[t].volume_ml, clean.clinical[t].volume_ml,
                0.08 * clean.clinical[t].volume_ml);
  }
}

// Tags through the wall with 5 % outliers: still a solid, every frame's
// wall thickness within 10 % of the same fit without outliers.
TEST(LvWallOutlierTest, WallTagsWithOutliersStayASolidOfTheirThickness) {
  const OutlierFit clean = Fit(LvTagLayer::kWall, false);
  const OutlierFit noisy = Fit(LvTagLayer::kWall, true);
  ASSERT_TRUE(clean.fit.config.Solid()) << clean.fit.wall_reason;
  ASSERT_TRUE(noisy.fit.config.Solid()) << noisy.fit.wall_reason;
  // The fence for tags uniform through the wall lies far beyond them.
  EXPECT_EQ(OutliersLeftOut(clean.fit.wall_reason), 0);
  EXPECT_NE(clean.fit.wall_reason.find("(0 beyond the wall left out)"),
            std::string::npos);
  // The solid starts 9.1 mm thick against 8.8 without outliers, 8 tags
  // beyond the wall left out of it.
  EXPECT_NEAR(StartThickness(noisy.fit.wall_reason),
              StartThickness(clean.fit.wall_reason), 0.04 * 8.8);
  for (size_t t = 0; t < clean.clinical.size(); ++t) {
    const double h = clean.clinical[t].wall_thickness_mm;
    std::printf("frame %zu thickness %.2f mm (without outliers %.2f)\n", t,
                noisy.clinical[t].wall_thickness_mm, h);
    EXPECT_NEAR(noisy.clinical[t].wall_thickness_mm, h, 0.1 * h) << t;
  }
}

}  // namespace
}  // namespace pfdm
