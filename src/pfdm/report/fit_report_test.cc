#include "pfdm/report/fit_report.h"

#include <cstdio>

#include "gtest/gtest.h"
#include "pfdm/phantom/phantom.h"
#include "pfdm/testing/test_util.h"
#include "pfdm/testing/truth_as_fit.h"

namespace pfdm {
namespace {

TEST(FitReportTest, InlinesSvg) {
  EXPECT_EQ(InlineSvg("<?xml version=\"1.0\"?>\n<!DOCTYPE svg>\n<svg a='1'/>"),
            "<svg a='1'/>");
  EXPECT_EQ(InlineSvg("not a plot"), "");
}

// Without tracked points at ES the cards read n/a for twist, torsion and
// shear, the rotation cells of the tables too, and the bull's-eye's
// caption says rotation has no map; contraction and strain are numbers.
TEST(FitReportTest, WhatIsNotMeasuredReadsNA) {
  PhantomOptions options;
  options.num_points = 50;
  const Phantom phantom = MakePhantom(options);
  SequenceFit fit = TruthAsFit(phantom);
  for (FrameFit& frame : fit.frames) frame.tracked = false;
  const FitAnalysis analysis = AnalyzeFit(fit);
  const std::string html = WithoutScripts(
      FitReportHtml(phantom.points, fit, analysis, "", "<svg id='b'></svg>"));
  EXPECT_NE(html.find("net twist at ES<b>n/a</b>no tracked points at ES"),
            std::string::npos);
  EXPECT_NE(html.find("torsion at ES<b>n/a</b>shear angle n/a</div>"),
            std::string::npos);
  EXPECT_NE(html.find("No tracked points:</b>"), std::string::npos);
  EXPECT_NE(html.find("rotation is n/a there"), std::string::npos);
  EXPECT_EQ(html.find("nan"), std::string::npos);
  char radial[64];
  std::snprintf(radial, sizeof(radial), "radial contraction at ES<b>%.1f %%",
                analysis.clinical[4].radial_contraction_percent);
  EXPECT_NE(html.find(radial), std::string::npos) << radial;
  // Per frame: net twist, apex, base, torsion; per segment: rotation, Ecl.
  EXPECT_EQ(CountOf(html, "<td>n/a</td>"), 5 * 4 + 17 * 2);

  // Frame 2 alone without tracked points: ES has numbers, frame 2 n/a.
  fit = TruthAsFit(phantom);
  fit.frames[2].tracked = false;
  const std::string mixed =
      WithoutScripts(FitReportHtml(phantom.points, fit, AnalyzeFit(fit), ""));
  EXPECT_EQ(mixed.find("No tracked points:"), std::string::npos);
  EXPECT_NE(mixed.find("Frames without tracked points:</b> frame 2, where"),
            std::string::npos);
  EXPECT_EQ(mixed.find("net twist at ES<b>n/a"), std::string::npos);
  EXPECT_EQ(CountOf(mixed, "<td>n/a</td>"), 4);
}

// A solid whose field moves every layer alike says under its segments'
// table what they cannot show (regional_limit.h): tags, that a segment
// reads as its ring; contours, that its thickening is its ring's.  With
// the field through the wall, that a third of the wall's thickening is
// its bend; on a surface nothing is said.
TEST(FitReportTest, SaysWhatTheSegmentsCannotShowThroughTheWall) {
  PhantomOptions options;
  options.num_points = 50;
  const Phantom phantom = MakePhantom(options);
  SequenceFit fit = TruthAsFit(phantom);
  const auto page = [&phantom](const SequenceFit& f) {
    return WithoutScripts(FitReportHtml(phantom.points, f, AnalyzeFit(f), ""));
  };
  const std::string ring = "a segment that moves unlike its ring reads as";
  const std::string thickening = "A segment's thickening here is its ring";
  EXPECT_EQ(page(fit).find("Through the wall:"), std::string::npos);
  fit.config.MakeSolid();
  LocalGrid grid;
  grid.rows = 5;
  grid.cols = 8;
  grid.u_min = fit.config.u_min;
  grid.u_max = fit.config.u_max;
  for (FrameFit& frame : fit.frames) {
    frame.state.globals[kH] = 8.0;
    for (FunctionValues& knot : frame.state.knots) knot[kH] = 8.0;
    frame.state.local = LocalField::Zero(grid);
  }
  EXPECT_NE(page(fit).find(ring), std::string::npos);
  SequenceFit transmural = fit;
  for (FrameFit& frame : transmural.frames) {
    frame.state.local = LocalField::Zero(grid, /*transmural=*/true);
  }
  const std::string thirds = page(transmural);
  EXPECT_NE(thirds.find("Through the wall:"), std::string::npos);
  EXPECT_NE(thirds.find("each third of the wall"), std::string::npos);
  EXPECT_EQ(thirds.find(ring), std::string::npos);
  for (FrameFit& frame : fit.frames) frame.tracked = false;
  const std::string contours = page(fit);
  EXPECT_EQ(contours.find(ring), std::string::npos);
  EXPECT_NE(contours.find(thickening), std::string::npos);
}

// Contours the reader left out (io/partial_rings.h) are named on the page;
// without any, nothing is said.
TEST(FitReportTest, NamesTheContoursLeftOut) {
  PhantomOptions options;
  options.num_points = 50;
  const Phantom phantom = MakePhantom(options);
  SequenceFit fit = TruthAsFit(phantom);
  const std::string none =
      WithoutScripts(FitReportHtml(phantom.points, fit, AnalyzeFit(fit), ""));
  EXPECT_EQ(none.find("Left out of the fit"), std::string::npos);
  fit.left_out.push_back({3, "SAX_LV_ENDOCARDIAL 2", 31, 149.0});
  const std::string html =
      WithoutScripts(FitReportHtml(phantom.points, fit, AnalyzeFit(fit), ""));
  EXPECT_NE(html.find("frame 3 SAX_LV_ENDOCARDIAL 2 (31 points);"),
            std::string::npos);
}

// How end-systole was found: the least volume, or, where frames have no
// walls (walls_unseen), the least volume inside the mid-wall, which names
// them and says when ES is one of them.
TEST(FitReportTest, SaysHowEndSystoleWasFound) {
  PhantomOptions options;
  options.num_points = 50;
  const Phantom phantom = MakePhantom(options);
  const SequenceFit fit = TruthAsFit(phantom);
  FitAnalysis analysis = AnalyzeFit(fit);
  const std::string plain =
      WithoutScripts(FitReportHtml(phantom.points, fit, analysis, ""));
  EXPECT_NE(plain.find("(ES) the frame of least"), std::string::npos);
  EXPECT_EQ(plain.find("inside the mid-wall"), std::string::npos);
  analysis.walls_measured.assign(fit.frames.size(), true);
  analysis.walls_measured[1] = analysis.walls_measured[2] = false;
  analysis.ejection_fraction.es_by_midwall = true;
  const std::string measured =
      WithoutScripts(FitReportHtml(phantom.points, fit, analysis, ""));
  EXPECT_NE(measured.find("the frame of least volume inside the mid-wall, "
                          "which the tags place in every frame, frame " +
                          std::to_string(analysis.ejection_fraction.es_frame) +
                          " (frames 1, 2 with nothing that places the walls "
                          "have no cavity)."),
            std::string::npos);
  analysis.ejection_fraction.es_frame = 2;
  analysis.ejection_fraction.ratio = kNotMeasured;
  const std::string unseen =
      WithoutScripts(FitReportHtml(phantom.points, fit, analysis, ""));
  EXPECT_NE(unseen.find("frame 2 (frames 1, 2 with nothing that places the "
                        "walls have no cavity; ES is one of them, so ESV and "
                        "the ejection fraction are n/a)."),
            std::string::npos);
  // ED without walls (--ed_frame on such a frame), ES with them.
  analysis.ejection_fraction.es_frame = 3;
  const std::string ed_unseen =
      WithoutScripts(FitReportHtml(phantom.points, fit, analysis, ""));
  EXPECT_NE(ed_unseen.find("have no cavity; ED is one of them, so EDV and "
                           "the ejection fraction are n/a)."),
            std::string::npos);
}

// Frames whose data span too little of the axis are named for that, apart
// from those with nothing that places the walls (each used to be listed
// under the other's reason), and one frame takes the singular.
TEST(FitReportTest, NamesEachFrameWithoutAVolumeForItsOwnReason) {
  PhantomOptions options;
  options.num_points = 50;
  const Phantom phantom = MakePhantom(options);
  const SequenceFit fit = TruthAsFit(phantom);
  ASSERT_GE(fit.frames.size(), 4u);
  FitAnalysis analysis = AnalyzeFit(fit);
  const std::string es =
      "frame " + std::to_string(analysis.ejection_fraction.es_frame);
  // Whether the report names ES and goes on with `phrase`.
  const auto reads = [&](const std::string& phrase) {
    return WithoutScripts(FitReportHtml(phantom.points, fit, analysis, ""))
               .find(es + phrase) != std::string::npos;
  };
  analysis.volume_measured.assign(fit.frames.size(), true);
  analysis.volume_measured[3] = false;
  EXPECT_TRUE(
      reads(" of those with one (frame 3 spans too little of the axis "
            "for a volume, so ESV and the ejection fraction are "
            "n/a)."));
  analysis.walls_measured.assign(fit.frames.size(), true);
  analysis.walls_measured[1] = analysis.walls_measured[2] = false;
  analysis.ejection_fraction.es_by_midwall = true;
  EXPECT_TRUE(
      reads(" (frame 3 spans too little of the axis for a volume; "
            "frames 1, 2 with nothing that places the walls have no "
            "cavity)."));
  analysis.volume_measured[3] = true;
  analysis.walls_measured[2] = true;
  EXPECT_TRUE(
      reads(" (frame 1 with nothing that places the walls has no cavity)."));
}

TEST(FitReportTest, OnePageWithKeyNumbersTablesAndNoExternalResources) {
  PhantomOptions options;
  options.num_points = 50;
  const Phantom phantom = MakePhantom(options);
  SequenceFit fit = TruthAsFit(phantom);
  for (size_t t = 0; t < fit.frames.size(); ++t) fit.frames[t].rms_mm = 0.5 + t;
  fit.frames[3].unsettled_mm = 0.94;
  PointSequence points = phantom.points;
  points.source = "tags<1>.csv";
  const FitAnalysis analysis = AnalyzeFit(fit);
  const std::string page =
      FitReportHtml(points, fit, analysis, "<?xml?><svg id='p'></svg>");
  const std::string html = WithoutScripts(page);
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(html.find("tags&lt;1&gt;.csv"), std::string::npos);
  EXPECT_NE(html.find("<svg id='p'></svg>"), std::string::npos);
  // The curves over the cycle: volume, dV/dt, rotation, torsion,
  // contraction, Ecc and Ell; the segments' three levels.
  EXPECT_EQ(CountOf(html,
                    "<svg xmlns='http://www.w3.org/2000/svg' "
                    "class='chart'"),
            7 + 3);
  EXPECT_EQ(html.find("<?xml"), std::string::npos);
  // Tags on a mid-wall: its volume is named as such, with no ejection
  // fraction; a surface fitted to endocardial contours encloses the cavity.
  EXPECT_NE(html.find("mid-wall enclosed volume"), std::string::npos);
  EXPECT_NE(html.find("no ejection fraction"), std::string::npos);
  EXPECT_EQ(html.find("ejection fraction<b>"), std::string::npos);
  SequenceFit endocardium = fit;
  endocardium.surface = WallLayer::kEndocardium;
  const FitAnalysis cavity = AnalyzeFit(endocardium);
  const std::string cavity_html =
      FitReportHtml(points, endocardium, cavity, "");
  char ef[64];
  std::snprintf(ef, sizeof(ef), "ejection fraction<b>%.1f %%",
                100 * cavity.ejection_fraction.ratio);
  EXPECT_NE(cavity_html.find(ef), std::string::npos) << ef;
  EXPECT_NE(html.find("4 ES"), std::string::npos);
  EXPECT_NE(html.find("<td>4.50</td>"), std::string::npos);  // RMS frame 4.
  // Frame 3's correspondences had not settled; the others' had.
  EXPECT_NE(html.find("CONVERGENCE; closest points unsettled (0.94 mm in the "
                      "last search)"),
            std::string::npos);
  EXPECT_EQ(CountOf(html, "unsettled"), 1);
  // 5 frame rows and 17 segment rows in the table at ES and in the
  // segments' timing, each a <tr> after its table's head.
  EXPECT_EQ(CountOf(html, "<tr>"), 3 + 5 + 17 + 17);
  EXPECT_NE(html.find("apical 4"), std::string::npos);
  EXPECT_EQ(html.find("No tracked points"), std::string::npos);  // Tags.
  EXPECT_EQ(html.find("n/a"), std::string::npos);
  for (const char* external : {"src=", "href=", "<link", "@import"}) {
    EXPECT_EQ(page.find(external), std::string::npos) << external;
  }
  // Without strain plots no caption of theirs; with them, inlined and
  // captioned; peak GCS among the key numbers, frame 0's strain unsigned.
  EXPECT_EQ(html.find("Bull's-eye"), std::string::npos);
  const std::string with_maps =
      WithoutScripts(FitReportHtml(points, fit, analysis, "<svg id='p'></svg>",
                                   "<?xml?><svg id='b'></svg>"));
  EXPECT_NE(with_maps.find("<svg id='b'></svg>"), std::string::npos);
  EXPECT_NE(with_maps.find("model's &minus;x axis"), std::string::npos);
  EXPECT_NE(with_maps.find("The segments are not anatomical</b> (no RV "
                           "insertion given)"),
            std::string::npos);
  const StrainPeak gcs = PeakGcs(analysis.strain);
  EXPECT_LT(gcs.percent, -3.0);
  char peak[64];
  std::snprintf(peak, sizeof(peak), "peak GCS<b>%.1f %%", gcs.percent);
  EXPECT_NE(with_maps.find(peak), std::string::npos) << peak;
  EXPECT_EQ(with_maps.find(">-0.0<"), std::string::npos);
}

}  // namespace
}  // namespace pfdm
