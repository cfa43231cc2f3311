#include "pfdm/report/bullseye_plot.h"

#include <cmath>

#include "gtest/gtest.h"
#include "pfdm/phantom/phantom.h"
#include "pfdm/testing/test_util.h"
#include "pfdm/testing/truth_as_fit.h"

namespace pfdm {
namespace {

// The AHA's page layout: segment 1 (and 7) centred at the top, 2 upper
// left, 4 at the bottom; the apical 13 at the top, 14 left, 16 right.
TEST(BullseyePlotTest, SegmentsSitWhereTheAhaDrawsThem) {
  const std::vector<WallRegion> regions = Regions(RegionLayout());
  auto centre = [&](int segment) {
    const auto [begin, end] = BullseyeSpanDeg(regions[segment - 1]);
    EXPECT_GT(end, begin) << segment;
    return (begin + end) / 2;
  };
  EXPECT_NEAR(centre(1), 90.0, 1e-9);
  EXPECT_NEAR(centre(2), 150.0, 1e-9);
  EXPECT_NEAR(centre(4), 270.0, 1e-9);
  EXPECT_NEAR(centre(7), 90.0, 1e-9);
  EXPECT_NEAR(centre(13), 90.0, 1e-9);
  EXPECT_NEAR(centre(14), 180.0, 1e-9);
  EXPECT_NEAR(centre(16), 360.0, 1e-9);
  EXPECT_NEAR(BullseyeSpanDeg(regions[0]).first, 60.0, 1e-9);
  EXPECT_NEAR(BullseyeSpanDeg(regions[12]).first, 45.0, 1e-9);
  EXPECT_NEAR(BullseyeSpanDeg(regions[16]).first, 0.0, 1e-9);  // The cap.
  EXPECT_NEAR(BullseyeSpanDeg(regions[16]).second, 360.0, 1e-9);
}

// Anatomical segments in the standard orientation: anterior at the top,
// the septum on the left (page angles 90-270), lateral on the right.
TEST(BullseyePlotTest, AnatomicalMapHasTheSeptumOnTheLeft) {
  RegionLayout layout;
  layout.anatomical = true;
  layout.anchor_v = 0.4;
  layout.direction = -1.0;
  const std::vector<WallRegion> regions = Regions(layout);
  auto centre = [&](const std::string& name) {
    for (const WallRegion& region : regions) {
      if (region.Name() != name) continue;
      const auto [begin, end] = BullseyeSpanDeg(region);
      return (begin + end) / 2;
    }
    ADD_FAILURE() << name;
    return 0.0;
  };
  EXPECT_NEAR(centre("basal anterior"), 90.0, 1e-9);
  EXPECT_NEAR(centre("mid anteroseptal"), 150.0, 1e-9);
  EXPECT_NEAR(centre("basal inferoseptal"), 210.0, 1e-9);
  EXPECT_NEAR(centre("mid inferior"), 270.0, 1e-9);
  EXPECT_NEAR(centre("basal anterolateral"), 390.0, 1e-9);  // 30.
  EXPECT_NEAR(centre("apical anterior"), 90.0, 1e-9);
  EXPECT_NEAR(centre("apical septal"), 180.0, 1e-9);
  EXPECT_NEAR(centre("apical lateral"), 360.0, 1e-9);
}

// Every segment drawn with its number and value, in each panel, with a
// colour box; the most negative value of a shortening map takes the scale's
// red, rgb(214, 96, 77).
TEST(BullseyePlotTest, PanelsLabelEverySegment) {
  const std::vector<WallRegion> regions = Regions(RegionLayout());
  BullseyeMap ecc{"peak Ecc, %", {}, BullseyePalette::kShorteningRed};
  BullseyeMap rotation{"rotation, degrees", {}, BullseyePalette::kPurpleGreen};
  for (size_t r = 0; r < regions.size(); ++r) {
    ecc.values.push_back(-20.0 + 0.25 * r);
    rotation.values.push_back(-7.0 + r);
  }
  const std::string svg = BullseyeSvg(regions, {ecc, rotation});
  EXPECT_NE(svg.find("peak Ecc, %"), std::string::npos);
  EXPECT_NE(svg.find("rotation, degrees"), std::string::npos);
  EXPECT_EQ(CountOf(svg, ">-20.0<"), 1);
  EXPECT_EQ(CountOf(svg, ">-16.2<"), 1);  // Segment 16, -16.25.
  EXPECT_EQ(CountOf(svg, ">8.0<"), 1);    // Rotation of segment 16.
  EXPECT_EQ(CountOf(svg, ">16<"), 2);     // Its number, once per panel.
  EXPECT_EQ(CountOf(svg, ">17<"), 2);     // The apex cap's.
  EXPECT_EQ(CountOf(svg, ">9.0<"), 1);    // Its rotation.
  // Segment borders: one path per panel, a closed outline (a move, M,
  // then lines) for each of its 17 segments.
  const std::string border = "stroke='rgb( 64,  64,  64)'";
  EXPECT_EQ(CountOf(svg, border), 2);
  int outlines = 0;
  for (size_t at = svg.find(border); at != std::string::npos;
       at = svg.find(border, at + 1)) {
    outlines += CountOf(svg.substr(at, svg.find("/>", at) - at), "M");
  }
  EXPECT_EQ(outlines, 34);
  EXPECT_NE(svg.find("rgb(214,  96,  77)"), std::string::npos);
}

// Rotation has a map at an ES with tracked points, none without (contours).
TEST(BullseyePlotTest, NoRotationMapWhereRotationIsNotMeasured) {
  PhantomOptions options;
  options.num_points = 1;
  const Phantom phantom = MakePhantom(options);
  SequenceFit fit = TruthAsFit(phantom);
  const std::vector<BullseyeMap> tags = ClinicalBullseyeMaps(AnalyzeFit(fit));
  ASSERT_EQ(tags.size(), 3u);
  EXPECT_EQ(tags[2].title, "rotation at ES, degrees");
  EXPECT_LT(tags[2].values[15], -1.0);  // An apical segment at ES.
  fit.frames[4].tracked = false;        // ES.
  const FitAnalysis analysis = AnalyzeFit(fit);
  ASSERT_EQ(analysis.ejection_fraction.es_frame, 4);
  const std::vector<BullseyeMap> contours = ClinicalBullseyeMaps(analysis);
  ASSERT_EQ(contours.size(), 2u);
  EXPECT_EQ(contours[0].title, tags[0].title);
  EXPECT_EQ(contours[1].title, tags[1].title);
  const std::string svg = BullseyeSvg(analysis.regions, contours);
  EXPECT_EQ(svg.find("rotation"), std::string::npos);
  EXPECT_EQ(svg.find("nan"), std::string::npos);
  EXPECT_EQ(CountOf(svg, ">17<"), 2);
  // Without data near the apex the cap is n/a, and the rotation map stays.
  fit.frames[4].tracked = true;
  fit.apex_in_data = false;
  const FitAnalysis no_apex = AnalyzeFit(fit);
  const std::vector<BullseyeMap> maps = ClinicalBullseyeMaps(no_apex);
  ASSERT_EQ(maps.size(), 3u);
  EXPECT_TRUE(std::isnan(maps[2].values[16]));
  const std::string cap_svg = BullseyeSvg(no_apex.regions, maps);
  EXPECT_EQ(CountOf(cap_svg, ">n/a<"), 3);
  EXPECT_EQ(cap_svg.find("nan"), std::string::npos);
}

TEST(BullseyePlotTest, StrainCurvesHaveGlobalAndLevels) {
  std::vector<GlobalStrain> strain(3);
  strain[1].gcs_percent = -10.0;
  strain[2].gcs_percent = -18.0;
  strain[2].level_ecc_percent = {-15.0, -18.0, -21.0};
  const std::string svg = StrainCurvesSvg(strain);
  for (const char* text : {"circumferential Ecc", "longitudinal Ell",
                           "GCS (global)", "GLS (global)", "basal", "apical"}) {
    EXPECT_NE(svg.find(text), std::string::npos) << text;
  }
}

}  // namespace
}  // namespace pfdm
