// Volumes, twist and contraction from fits to the real LV data in
// ../shared/data, against what the data's own meshes measure; skipped
// without that folder.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "gtest/gtest.h"
#include "pfdm/fit/correspondence/correspondence.h"
#include "pfdm/fit/stages/fitter.h"
#include "pfdm/fit/stages/temporal_prior.h"
#include "pfdm/io/landmark_axis.h"
#include "pfdm/io/legacy_vtk_reader.h"
#include "pfdm/io/mesh_reader.h"
#include "pfdm/io/mitral_valve_planes.h"
#include "pfdm/io/point_reader.h"
#include "pfdm/model/base_plane.h"
#include "pfdm/report/fit_analysis.h"
#include "pfdm/report/mesh_motion.h"
#include "pfdm/report/strain_spike.h"
#include "pfdm/testing/biv_me_meshes.h"
#include "pfdm/testing/test_util.h"

namespace pfdm {
namespace {

// biv-me patient 1's LV endocardial contours with the aortic valve points
// (lv-cavity): no correspondence over time, so no twist; the cavity closed
// at each frame's mitral valve plane should follow biv-me's own meshes
// (about 170 ml at ED, 71 ml at frame 9) within 10 % at every frame but
// frames 10 and 11, where biv-me's mesh lies 0.5-0.6 mm outside these
// contours (below): the global functions alone read 9.3 and 7.7 % low
// there, a surface 0.21 mm outside the points on average; with the local
// field, which follows the contours (0.12 mm inside), 11.4 and 10.7 %.
// With the contours alone, end-systole's outflow tract is extrapolated and
// frames 10 and 11 come out lower still.  With the pull toward frame 0's
// radii eased where the contours cover a ring (0.3, FitOptions::
// untracked_prior_covered_radii_scale) they read 9.4 and 9.2 % low (8.0
// and 8.3 at full pull); the points' mean signed distance from the surface
// there, -0.08 mm against -0.01, cannot tell the two apart.
TEST(RealDataReportTest, BivMeContourVolumesFollowItsMeshes) {
  const std::string shared = SharedDataDirectory();
  if (shared.empty()) GTEST_SKIP() << "../shared/data is absent";
  const std::string gp = shared + "/biv-me-patient1/guidepoints";
  const std::vector<BasePlane> planes = MitralValvePlanes(gp);
  ASSERT_EQ(planes.size(), 25u);
  const std::vector<TriangleMesh> meshes = BivMeLvMeshes(shared);
  const std::vector<double> mesh = MeshVolumes(meshes);
  EXPECT_NEAR(mesh[0], 174.5, 1.0);  // The reference itself.
  EXPECT_NEAR(mesh[9], 72.0, 1.0);
  const SequenceFit fit =
      FitSequence(ReadGpFiles(gp, ExpandContourAlias("lv-cavity")),
                  ModelConfig::Paper(17), FitOptions());
  const FitAnalysis analysis = AnalyzeFit(fit, planes);
  double sum_deviation = 0.0;
  for (int t = 0; t < 25; ++t) {
    const double deviation = analysis.clinical[t].volume_ml / mesh[t] - 1.0;
    sum_deviation += std::abs(deviation);
    std::printf("frame %2d  fit %6.1f ml  biv-me mesh %6.1f ml  %+5.1f %%\n", t,
                analysis.clinical[t].volume_ml, mesh[t], 100 * deviation);
    EXPECT_LT(std::abs(deviation), t == 10 || t == 11 ? 0.12 : 0.10)
        << "frame " << t;
    // Over all points, the two valve points of each frame included.  The
    // pull toward frame 0 of frames without tracked points costs up to
    // 0.35 mm here (frames 6 and 13) against a free drift.
    EXPECT_LT(fit.frames[t].rms_mm, 2.5) << "frame " << t;
  }
  // 0.023; 0.018 with the covered radii pulled as hard as the rest.
  EXPECT_LT(sum_deviation / 25, 0.035);
  // Frame 24 is end-diastole again (the meshes: +2.6 % volume): the cycle
  // closes, with no drift of the functions or of what they say.
  const ClinicalSummary& last = analysis.clinical[24];
  std::printf("frame 24: shortening %.2f %%, radial contraction %.2f %%\n",
              last.longitudinal_shortening_percent,
              last.radial_contraction_percent);
  // The meshes' own frame 24 is as long as frame 0 (MeasureMeshMotion:
  // -0.02 %); the fit's, 2.6 % longer (1.3 % while untracked frames'
  // length was held at frame 0's).
  EXPECT_NEAR(last.longitudinal_shortening_percent, 0.0, 3.5);
  EXPECT_NEAR(last.radial_contraction_percent, 0.0, 3.0);
  // The shortening, measured a second way: on the meshes' own vertices,
  // apex to rim centroid (MeasureMeshMotion), as the fit's apex pole to
  // base rim centroid; it follows them within 2.7 points rms over the cycle
  // (end-systole, frame 10: 16.6 % against 19.4; 2.5 points and 17.5 %
  // with the covered radii pulled toward frame 0's as hard as the rest).
  // With the length of untracked frames held at frame 0's, 4.9 points
  // (11.1 % at frame 10).
  const std::vector<MeshFrameMotion> motion = MeasureMeshMotion(meshes);
  double square_sum = 0.0;
  for (int t = 0; t < 25; ++t) {
    const double mesh_shortening = motion[t].longitudinal_shortening_percent;
    const double fit_shortening =
        analysis.clinical[t].longitudinal_shortening_percent;
    std::printf("frame %2d  shortening fit %5.2f %%  meshes %5.2f %%\n", t,
                fit_shortening, mesh_shortening);
    square_sum += std::pow(fit_shortening - mesh_shortening, 2);
  }
  EXPECT_LT(std::sqrt(square_sum / 25), 3.0);
  // The top two knots, above the basal short-axis contours, are seen by
  // three long-axis contours and two aortic valve points: with the pull
  // toward the previous frame (the default) their cross-section closes
  // within 11-14 % (0.885 and 1.144 at knot 16; 5-7 % without the pull),
  // the bending b2 within 3.8.
  for (size_t k = 1; k < last.radial_ratio_x.size(); ++k) {
    const bool top = k + 2 >= last.radial_ratio_x.size();
    EXPECT_NEAR(last.radial_ratio_x[k], 1.0, top ? 0.15 : 0.1) << "knot " << k;
    EXPECT_NEAR(last.radial_ratio_y[k], 1.0, top ? 0.15 : 0.1) << "knot " << k;
    EXPECT_NEAR(last.longitudinal_ratio[k], 1.0, 0.05) << "knot " << k;
    EXPECT_LT(std::abs(fit.frames[24].state.knots[k][kB0]), 3.0) << k;
    EXPECT_LT(std::abs(fit.frames[24].state.knots[k][kB2]), top ? 4.0 : 3.0)
        << k;
  }
  // The surface is nearly unbiased against the points: the mean signed
  // distance of the data along the surface normal is within 0.25 mm on
  // every frame (0.02 mm before frames without tracked points were pulled
  // toward frame 0; the pull costs up to 0.23 mm), so where the volumes
  // part most (frames 6-11, up to 9 % low) it is not a fit pulled inward by
  // its regularizer.  At frames 10 and 11 biv-me's
  // mesh lies 0.5-0.6 mm outside these contours, 1.6-2.1 mm in the basal
  // 20 mm.
  for (int t = 0; t < 25; ++t) {
    const Model model = fit.ModelAt(t);
    const FrameFit& frame = fit.frames[t];
    double sum = 0.0;
    for (size_t i = 0; i < frame.residuals.size(); ++i) {
      sum += frame.residuals[i].dot(
          SurfaceNormal(model, frame.material[i].u, frame.material[i].v));
    }
    const double bias = sum / frame.residuals.size();
    if (t >= 9 && t <= 11) std::printf("frame %d bias %+.3f mm\n", t, bias);
    EXPECT_LT(std::abs(bias), 0.25) << "frame " << t;
  }
  const double mesh_ef = 1.0 - mesh[9] / mesh[0];
  EXPECT_NEAR(analysis.ejection_fraction.ratio, mesh_ef, 0.05);
  EXPECT_NEAR(analysis.ejection_fraction.es_frame, 9, 1);
}

// Issue 31: biv-me's contours as `pfdm fit --contours lv-cavity` fits them
// (the landmarks' axis).  Plain correspondence rounds ran out on 15 of 25
// frames, points still moving 0.06-5.31 mm: two poses about 1.3 degrees
// and 1.7 mm apart swapped round after round (frame 11).  Rounds past the
// tenth now mix the last rounds' solutions (round_acceleration.h), and the
// local field's rounds are mixed.  The rounds alone (no pull toward the
// previous frame) leave 4 frames of the outflow tract's end-systole (8,
// 10-12) out of rounds, by 0.10-0.14 mm, and the fit is no worse (pooled
// RMS 0.764 mm against 0.791).  Since the local field's nodes move along
// the surface's normal only (node_normals.h; sliding along the wall had
// fitted some of the data) the pooled RMS reads 0.856 mm.
TEST(RealDataReportTest, BivMeContourRoundsSettle) {
  const std::string shared = SharedDataDirectory();
  if (shared.empty()) GTEST_SKIP() << "../shared/data is absent";
  const std::string gp = shared + "/biv-me-patient1/guidepoints";
  FitOptions options;
  AddLandmarkAxis(gp, &options);
  options.temporal_prior_weight = 0.0;
  const SequenceFit fit =
      FitSequence(ReadGpFiles(gp, ExpandContourAlias("lv-cavity")),
                  ModelConfig::Paper(17), options);
  const FitAnalysis analysis = AnalyzeFit(fit, MitralValvePlanes(gp));
  const std::vector<TriangleMesh> meshes = BivMeLvMeshes(shared);
  const std::vector<double> mesh = MeshVolumes(meshes);
  double squares = 0.0;
  int points = 0;
  for (int t = 0; t < 25; ++t) {
    const FrameFit& frame = fit.frames[t];
    const double deviation = analysis.clinical[t].volume_ml / mesh[t] - 1.0;
    std::printf(
        "frame %2d  rounds %2d  unsettled %.2f mm  rms %.3f  %+5.1f %%\n", t,
        frame.correspondence_rounds, frame.unsettled_mm, frame.rms_mm,
        100 * deviation);
    if (t < 8 || t > 12) EXPECT_EQ(frame.unsettled_mm, 0.0) << "frame " << t;
    EXPECT_LT(frame.unsettled_mm, 0.5) << "frame " << t;
    squares += frame.rms_mm * frame.rms_mm * frame.residuals.size();
    points += static_cast<int>(frame.residuals.size());
  }
  EXPECT_LT(std::sqrt(squares / points), 0.86);
}

// The same fit as `pfdm fit` makes it by default (issue 31): the pull
// toward the previous frame (fit/stages/temporal_prior.h) and the two
// outflow-tract rings left out (io/partial_rings.h: slice 2 at frames 6
// and 13, which had collapsed frame 13's base into a slit and made basal
// Ell jump by 14 points).  Every frame settles, in 166 rounds (228 before
// the rounds were mixed), pooled RMS 0.769 mm, and no level's Ecc or Ell
// departs from its neighbours' mean by 3 points (the largest: 2.6, apical
// Ecc at frame 14).  With the local field's nodes held to the surface's
// normal (node_normals.h): 163 rounds, pooled RMS 0.860 mm, the largest
// spike 2.78 points (apical Ecc at frame 14), and the cavity closer to
// biv-me's meshes (mean deviation 1.8 % against 2.6 %).  With the pull on
// the radii at 0.3 where the contours cover a ring (FitOptions::
// untracked_prior_covered_radii_scale): 167 rounds, 0.856 mm, the largest
// spike 2.87 points (the same); with no pull there, 3.47 (apical Ecc at
// frame 8).
TEST(RealDataReportTest, BivMeTemporalPriorSettlesEveryFrame) {
  const std::string shared = SharedDataDirectory();
  if (shared.empty()) GTEST_SKIP() << "../shared/data is absent";
  const std::string gp = shared + "/biv-me-patient1/guidepoints";
  FitOptions options;
  AddLandmarkAxis(gp, &options);
  const PointSequence contours =
      ReadGpFiles(gp, ExpandContourAlias("lv-cavity"));
  ASSERT_EQ(contours.left_out.size(), 2u);
  EXPECT_EQ(contours.left_out[0].frame, 6);
  EXPECT_EQ(contours.left_out[1].frame, 13);
  EXPECT_EQ(contours.left_out[1].contour, "SAX_LV_ENDOCARDIAL 2");
  EXPECT_EQ(contours.left_out[1].points, 31);
  const SequenceFit fit =
      FitSequence(contours, ModelConfig::Paper(17), options);
  EXPECT_DOUBLE_EQ(fit.temporal_prior_weight, kSuggestedTemporalPriorWeight);
  const FitAnalysis analysis = AnalyzeFit(fit, MitralValvePlanes(gp));
  double squares = 0.0;
  int points = 0, rounds = 0;
  for (const FrameFit& frame : fit.frames) {
    EXPECT_EQ(frame.unsettled_mm, 0.0) << "frame " << frame.frame;
    squares += frame.rms_mm * frame.rms_mm * frame.residuals.size();
    points += static_cast<int>(frame.residuals.size());
    rounds += frame.correspondence_rounds;
  }
  const StrainSpike spike = LargestStrainSpike(analysis.strain);
  std::printf(
      "rounds %d, pooled rms %.4f mm, largest strain spike %+.2f "
      "points (frame %d, level %d, %s)\n",
      rounds, std::sqrt(squares / points), spike.points, spike.frame,
      spike.level, spike.longitudinal ? "Ell" : "Ecc");
  EXPECT_LT(rounds, 190);
  EXPECT_LT(std::sqrt(squares / points), 0.865);
  EXPECT_LT(std::abs(spike.points), 3.0);
}

// The same contours of both walls (lv-cavity,lv-epi: lv-endo with the
// aortic valve points) make a solid: its endocardium follows biv-me's
// endocardial meshes as the cavity-only fit does, and the myocardium
// between the walls gives the LV mass.  Adult
// CMR (SSFP) reference ranges of LV mass are about 85-180 g for men and
// 65-140 g for women (Kawel-Boehm et al., JCMR 2020, pooled studies).
TEST(RealDataReportTest, BivMeBothWallsGiveTheCavityAndTheMass) {
  const std::string shared = SharedDataDirectory();
  if (shared.empty()) GTEST_SKIP() << "../shared/data is absent";
  const std::string gp = shared + "/biv-me-patient1/guidepoints";
  const std::vector<BasePlane> planes = MitralValvePlanes(gp);
  const std::vector<TriangleMesh> meshes = BivMeLvMeshes(shared);
  const std::vector<double> mesh = MeshVolumes(meshes);
  const SequenceFit fit =
      FitSequence(ReadGpFiles(gp, ExpandContourAlias("lv-cavity,lv-epi")),
                  ModelConfig::Paper(17), FitOptions());
  ASSERT_TRUE(fit.config.Solid()) << fit.wall_reason;
  EXPECT_EQ(fit.wall_reason, "endocardial and epicardial contours");
  // h rests at its floor 0 at the top knot in frames 2-12 (down to -5 mm
  // before it) and nowhere below (walls_meet): every verdict is ok.
  int top_at_floor = 0;
  for (const FrameFit& frame : fit.frames) {
    top_at_floor += frame.state.knots.back()[kH] == 0.0 ? 1 : 0;
    EXPECT_TRUE(frame.verdict.reasons().empty())
        << "frame " << frame.frame << ": " << frame.verdict.reasons()[0].code;
  }
  EXPECT_EQ(top_at_floor, 11);
  const FitAnalysis analysis = AnalyzeFit(fit, planes);
  EXPECT_EQ(analysis.volume_surface, "cavity");
  double worst = 0.0, sum_deviation = 0.0;
  for (int t = 0; t < 25; ++t) {
    const ClinicalSummary& c = analysis.clinical[t];
    const double deviation = c.volume_ml / mesh[t] - 1.0;
    worst = std::max(worst, std::abs(deviation));
    sum_deviation += std::abs(deviation);
    std::printf(
        "frame %2d  rms %.2f  cavity %6.1f (mesh %6.1f, %+5.1f %%)  "
        "myocardium %6.1f ml (%+5.1f %%, material %+5.1f %%)  mass %6.1f g  "
        "wall %4.1f mm\n",
        t, fit.frames[t].rms_mm, c.volume_ml, mesh[t], 100 * deviation,
        c.myocardial_volume_ml,
        100.0 * (c.myocardial_volume_ml /
                     analysis.clinical[0].myocardial_volume_ml -
                 1.0),
        c.myocardial_volume_change_percent, c.lv_mass_g, c.wall_thickness_mm);
    // End-systole's outflow tract is where the contours say least: frames
    // 10 and 11 read 9.8 and 9.5 % below the meshes, which lie 0.5 mm
    // outside the contours (11.5 and 10.3 % when the local field slid
    // along the wall; the cavity-only fit then: 11.4 and 10.7 %); 12.4
    // and 11.3 % since h's floor at 0 keeps the endocardium's top ring
    // (the aortic valve's points) from reaching outside the epicardium.
    EXPECT_LT(std::abs(deviation), 0.13) << "frame " << t;
    EXPECT_LT(fit.frames[t].rms_mm, 2.5) << "frame " << t;
    // The myocardium keeps its volume within 10 % over the cycle.
    EXPECT_NEAR(c.myocardial_volume_ml,
                analysis.clinical[0].myocardial_volume_ml,
                0.10 * analysis.clinical[0].myocardial_volume_ml)
        << "frame " << t;
    // The material myocardium (material_myocardium.h) drifts beyond issue
    // 32's 5 %: +7.7 % at ES (frame 9), +9.7 % at frame 10, where the
    // cavity reads 12 % under the meshes (docs/accuracy.md; +11.1 % at
    // frame 13 before its outflow-tract slice was left out).  It read 1-2
    // points less while the walls crossed at the top knot, whose negative
    // thickness took volume off.  The bound is the measured worst, so that
    // it cannot grow unseen.
    EXPECT_NEAR(c.myocardial_volume_change_percent, 0.0, 10.0) << "frame " << t;
  }
  const double mass = analysis.clinical[0].lv_mass_g;
  std::printf(
      "LV mass at ED %.0f g (adult CMR reference: men about 85-180 g, "
      "women 65-140 g); worst cavity deviation %.1f %%\n",
      mass, 100 * worst);
  EXPECT_LT(sum_deviation / 25, 0.04);
  EXPECT_GT(mass, 65.0);
  EXPECT_LT(mass, 250.0);
  EXPECT_GT(analysis.clinical[0].wall_thickness_mm, 5.0);
  EXPECT_LT(analysis.clinical[0].wall_thickness_mm, 15.0);
  // Issue 31 with both walls: the outflow-tract slices left out with their
  // epicardial arcs (io/partial_rings.h), no level's Ecc or Ell departs
  // from its neighbours' mean by 3 points (2.7, apical Ecc at frame 14).
  EXPECT_LT(std::abs(LargestStrainSpike(analysis.strain).points), 3.0);
}

// --incompressible 1 on the same contours: the material myocardium within
// 3.5 % of ED at every frame (+3.0 at frame 10; without: +9.7 %, the test
// above; within 2 % while the walls could cross at the top knot),
// at the same fit (pooled RMS 0.937 mm against 0.938), the cavity no
// further from biv-me's meshes on average (ES 69.9 ml against 68.4; mesh
// 72.0).  With the local field's nodes held to the surface's normal
// (node_normals.h): pooled RMS 1.045 mm against 1.043.
TEST(RealDataReportTest, BivMeIncompressibleWallKeepsItsVolume) {
  const std::string shared = SharedDataDirectory();
  if (shared.empty()) GTEST_SKIP() << "../shared/data is absent";
  const std::string gp = shared + "/biv-me-patient1/guidepoints";
  const std::vector<TriangleMesh> meshes = BivMeLvMeshes(shared);
  const std::vector<double> mesh = MeshVolumes(meshes);
  FitOptions options;
  options.incompressible_weight = 1.0;
  const SequenceFit fit =
      FitSequence(ReadGpFiles(gp, ExpandContourAlias("lv-cavity,lv-epi")),
                  ModelConfig::Paper(17), options);
  const FitAnalysis analysis = AnalyzeFit(fit, MitralValvePlanes(gp));
  double squares = 0.0, sum_deviation = 0.0;
  size_t points = 0;
  for (int t = 0; t < 25; ++t) {
    const ClinicalSummary& c = analysis.clinical[t];
    std::printf(
        "frame %2d  material myocardium %+5.2f %%  cavity %6.1f ml "
        "(mesh %6.1f)\n",
        t, c.myocardial_volume_change_percent, c.volume_ml, mesh[t]);
    EXPECT_NEAR(c.myocardial_volume_change_percent, 0.0, 3.5) << "frame " << t;
    // The term is in every frame's problem but frame 0's, its reference.
    if (t > 0) EXPECT_GT(fit.frames[t].costs.incompressibility, 0.0) << t;
    sum_deviation += std::abs(c.volume_ml / mesh[t] - 1.0);
    const FrameFit& frame = fit.frames[t];
    squares += frame.rms_mm * frame.rms_mm * frame.residuals.size();
    points += frame.residuals.size();
  }
  const double rms = std::sqrt(squares / points);
  std::printf("pooled rms %.4f mm, mean cavity deviation %.2f %%\n", rms,
              100.0 * sum_deviation / 25);
  EXPECT_LT(rms, 1.05);
  EXPECT_LT(sum_deviation / 25, 0.04);
}

// The same patient's meshes as tracked material points (vertex index = id).
TEST(RealDataReportTest, BivMeMeshVerticesGiveTwistAndContraction) {
  const std::string shared = SharedDataDirectory();
  if (shared.empty()) GTEST_SKIP() << "../shared/data is absent";
  const std::vector<TriangleMesh> meshes = BivMeLvMeshes(shared);
  std::vector<std::vector<Eigen::Vector3d>> vertices;
  for (const auto& mesh : meshes) vertices.push_back(mesh.points);
  const SequenceFit fit = FitSequence(MeshPointSequence("biv-me obj", vertices),
                                      ModelConfig::Paper(17), FitOptions());
  const FitAnalysis analysis = AnalyzeFit(fit);
  const std::vector<MeshFrameMotion> direct = MeasureMeshMotion(meshes);
  for (int t = 0; t < 25; ++t) {
    const ClinicalSummary& c = analysis.clinical[t];
    std::printf(
        "frame %2d  rms %.2f  volume %6.1f (mesh %6.1f)  twist %5.1f (apex "
        "%5.1f base %5.1f)  longitudinal %5.1f (mesh %5.1f)  radial %5.1f "
        "(mesh %5.1f)\n",
        t, fit.frames[t].rms_mm, c.volume_ml, direct[t].volume_ml,
        c.net_twist_deg, c.apex_rotation_deg, c.base_rotation_deg,
        c.longitudinal_shortening_percent,
        direct[t].longitudinal_shortening_percent, c.radial_contraction_percent,
        direct[t].radial_contraction_percent);
    EXPECT_LT(fit.frames[t].rms_mm, 3.0) << t;
    EXPECT_NEAR(c.volume_ml, direct[t].volume_ml, 0.06 * direct[t].volume_ml)
        << t;
  }
  const int es = analysis.ejection_fraction.es_frame;
  EXPECT_EQ(es, 9);
  const ClinicalSummary& at_es = analysis.clinical[es];
  EXPECT_NEAR(at_es.longitudinal_shortening_percent,
              direct[es].longitudinal_shortening_percent, 3.0);
  EXPECT_NEAR(at_es.radial_contraction_percent,
              direct[es].radial_contraction_percent, 3.0);
  // The base turns and the apex barely: net twist of a few degrees, of the
  // normal sign (base minus apex > 0).
  EXPECT_GT(at_es.net_twist_deg, 2.0);
  EXPECT_LT(at_es.net_twist_deg, 15.0);

  // Strain: GCS and GLS of the fitted surface against the meshes' own
  // triangles (MeshFrameMotion), both endocardial, Green-Lagrange: peaks
  // -21.9 and -20.3 % at frame 9 (meshes -21.9 at 9 and -20.3 at 10).
  // Endocardial strain exceeds the mid-wall strain that tagging reports.
  double gcs_mesh = 0.0, gls_mesh = 0.0;
  for (int t = 0; t < 25; ++t) {
    std::printf("frame %2d  GCS %6.2f (mesh %6.2f)  GLS %6.2f (mesh %6.2f)\n",
                t, analysis.strain[t].gcs_percent, direct[t].gcs_percent,
                analysis.strain[t].gls_percent, direct[t].gls_percent);
    // Largest difference 1.4 points (GLS, frame 7).
    EXPECT_NEAR(analysis.strain[t].gcs_percent, direct[t].gcs_percent, 2.0)
        << t;
    EXPECT_NEAR(analysis.strain[t].gls_percent, direct[t].gls_percent, 2.0)
        << t;
    gcs_mesh = std::min(gcs_mesh, direct[t].gcs_percent);
    gls_mesh = std::min(gls_mesh, direct[t].gls_percent);
  }
  const StrainPeak gcs = PeakGcs(analysis.strain);
  const StrainPeak gls = PeakGls(analysis.strain);
  std::printf(
      "peak GCS %.1f %% (frame %d), mesh %.1f %%; peak GLS %.1f %% (frame "
      "%d), mesh %.1f %%; published normal ranges for tagged MRI (mid-wall): "
      "peak Ecc about -13 to -21 %%, GLS about -15 to -20 %%\n",
      gcs.percent, gcs.frame, gcs_mesh, gls.percent, gls.frame, gls_mesh);
  EXPECT_NEAR(gcs.percent, gcs_mesh, 2.0);
  EXPECT_NEAR(gls.percent, gls_mesh, 2.0);
  EXPECT_EQ(gcs.frame, es);
}

// The CAP mean shape's ED and ES endocardium as two tracked frames.
TEST(RealDataReportTest, CapMeanShapeContractionAgainstTheMeshes) {
  const std::string shared = SharedDataDirectory();
  if (shared.empty()) GTEST_SKIP() << "../shared/data is absent";
  const auto surfaces =
      ReadCapMeanShape(shared + "/cap-lv-mean/mean_shape.csv");
  const auto faces = ReadCapFaces(shared + "/cap-lv-mean/surface_face.csv",
                                  static_cast<int>(surfaces[0].size()));
  const SequenceFit fit =
      FitSequence(MeshPointSequence("cap", {surfaces[0], surfaces[2]}),
                  ModelConfig::Paper(17), FitOptions());
  const FitAnalysis analysis = AnalyzeFit(fit);
  const std::vector<TriangleMesh> meshes = {{surfaces[0], faces},
                                            {surfaces[2], faces}};
  const std::vector<MeshFrameMotion> direct = MeasureMeshMotion(meshes);
  // The fitted model measured like the meshes: at each vertex's material
  // point, the same apex vertex and rim.
  std::vector<TriangleMesh> modelled = meshes;
  for (int t = 0; t < 2; ++t) {
    const Model model = fit.ModelAt(t);
    for (size_t i = 0; i < modelled[t].points.size(); ++i) {
      modelled[t].points[i] = model.WorldPoint(fit.frames[t].material[i].u,
                                               fit.frames[t].material[i].v);
    }
  }
  const std::vector<MeshFrameMotion> fitted = MeasureMeshMotion(modelled);
  const ClinicalSummary& es = analysis.clinical[1];
  std::printf(
      "CAP mean: rms %.2f / %.2f mm; volumes %.1f -> %.1f ml (mesh %.1f -> "
      "%.1f); EF %.3f (mesh %.3f)\n  longitudinal: model %.1f %%, model at "
      "the vertices %.1f %%, mesh %.1f %%\n  radial: model %.1f %%, "
      "model at the vertices %.1f %%, mesh %.1f %%; net twist %.1f deg\n",
      fit.frames[0].rms_mm, fit.frames[1].rms_mm,
      analysis.clinical[0].volume_ml, es.volume_ml, direct[0].volume_ml,
      direct[1].volume_ml, analysis.ejection_fraction.ratio,
      1.0 - direct[1].volume_ml / direct[0].volume_ml,
      es.longitudinal_shortening_percent,
      fitted[1].longitudinal_shortening_percent,
      direct[1].longitudinal_shortening_percent, es.radial_contraction_percent,
      fitted[1].radial_contraction_percent,
      direct[1].radial_contraction_percent, es.net_twist_deg);
  EXPECT_LT(fit.frames[0].rms_mm, 1.0);
  EXPECT_LT(fit.frames[1].rms_mm, 3.5);
  EXPECT_NEAR(analysis.ejection_fraction.ratio,
              1.0 - direct[1].volume_ml / direct[0].volume_ml, 0.05);
  EXPECT_NEAR(fitted[1].longitudinal_shortening_percent,
              direct[1].longitudinal_shortening_percent, 3.0);
  EXPECT_NEAR(fitted[1].radial_contraction_percent,
              direct[1].radial_contraction_percent, 3.0);
}

// The UK Digital Heart mean ED mesh: label 1 is the endocardium (it
// encloses 151 ml, label 0 252 ml).  A static fit.
TEST(RealDataReportTest, UkDigitalHeartEndocardiumStaticFit) {
  const std::string shared = SharedDataDirectory();
  if (shared.empty()) GTEST_SKIP() << "../shared/data is absent";
  const VtkMesh vtk =
      ReadLegacyVtkPolyData(shared + "/ukdhp-lv-ed/LV_ED_mean.vtk");
  const std::vector<double>& label = vtk.point_scalars.at("scalars");
  std::vector<Eigen::Vector3d> endo;
  for (size_t i = 0; i < label.size(); ++i) {
    if (label[i] == 1.0) endo.push_back(vtk.mesh.points[i]);
  }
  ASSERT_EQ(endo.size(), 9207u);
  const SequenceFit fit = FitSequence(MeshPointSequence("ukdhp", {endo}),
                                      ModelConfig::Paper(17), FitOptions());
  const FitAnalysis analysis = AnalyzeFit(fit);
  std::printf(
      "UK Digital Heart ED endocardium: %zu points, rms %.2f mm, "
      "max %.2f mm, volume %.1f ml\n",
      endo.size(), fit.frames[0].rms_mm, fit.frames[0].max_distance_mm,
      analysis.clinical[0].volume_ml);
  EXPECT_LT(fit.frames[0].rms_mm, 1.0);
  EXPECT_GT(fit.frames[0].rms_mm, 0.1);
  EXPECT_NEAR(analysis.clinical[0].volume_ml, 151.0, 0.06 * 151.0);
}

}  // namespace
}  // namespace pfdm
