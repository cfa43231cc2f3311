// The mesh voxelizer against an analytic solid, and pfdm fit --segmentation
// on biv-me patient 1's own meshes voxelized (../shared/data; skipped
// without it): real anatomy, which the model did not make.
#include "pfdm/testing/mesh_mask.h"

#include <cstdio>

#include "Eigen/Geometry"
#include "gtest/gtest.h"
#include "nlohmann/json.hpp"
#include "pfdm/fit/stages/fitter.h"
#include "pfdm/io/mesh_reader.h"
#include "pfdm/io/nifti_writer.h"
#include "pfdm/report/fit_analysis.h"
#include "pfdm/report/rv_insertion.h"
#include "pfdm/segmentation/mask_contours.h"
#include "pfdm/testing/test_util.h"

namespace pfdm {
namespace {

// A cube of side 2 h about c, turned by `rotation`.
TriangleMesh Cube(const Eigen::Vector3d& c, const Eigen::Matrix3d& rotation,
                  double h) {
  TriangleMesh mesh;
  for (int n = 0; n < 8; ++n) {
    const Eigen::Vector3d corner(n & 1 ? h : -h, n & 2 ? h : -h,
                                 n & 4 ? h : -h);
    mesh.points.push_back(c + rotation * corner);
  }
  mesh.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6},
                    {0, 1, 4}, {1, 5, 4}, {2, 6, 3}, {3, 6, 7},
                    {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return mesh;
}

// Every voxel centre of every slice of an oblique stack: inside the
// voxelized cube exactly where it lies inside the cube.
TEST(MeshMaskTest, InsideSliceIsTheSolidVoxelByVoxel) {
  const Eigen::Vector3d c(3.1, -2.2, 7.3);
  const Eigen::Matrix3d rotation =
      Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 3).normalized())
          .toRotationMatrix();
  const double h = 12.3;
  const TriangleMesh cube = Cube(c, rotation, h);
  StackGeometry stack;
  stack.origin = c + Eigen::Vector3d(0.3, 0.2, -0.1);
  stack.to_apex = Eigen::Vector3d(0.2, -0.3, 1.0).normalized();
  stack.first_slice_mm = -25.0;
  stack.in_plane_mm = 1.5;
  stack.slice_mm = 4.0;
  stack.size = 41;
  stack.slices = 13;
  const Eigen::Matrix4d world_from_voxel = WorldFromVoxel(stack);
  const Eigen::Matrix3d linear = world_from_voxel.topLeftCorner<3, 3>();
  EXPECT_NEAR(linear.determinant(), 1.5 * 1.5 * 4.0, 1e-9);  // Right-handed.
  int inside = 0, wrong = 0;
  for (int k = 0; k < stack.slices; ++k) {
    const std::vector<bool> slice =
        InsideSlice(cube, world_from_voxel, stack.size, k);
    for (int j = 0; j < stack.size; ++j) {
      for (int i = 0; i < stack.size; ++i) {
        const Eigen::Vector3d p =
            (world_from_voxel * Eigen::Vector4d(i, j, k, 1)).head<3>();
        const bool truth =
            (rotation.transpose() * (p - c)).cwiseAbs().maxCoeff() < h;
        inside += truth;
        wrong += truth != slice[j * stack.size + i];
      }
    }
  }
  EXPECT_GT(inside, 1000);
  EXPECT_EQ(wrong, 0);
}

MeshMaskFrame ReadFrame(const std::string& folder, int frame) {
  char suffix[16];
  std::snprintf(suffix, sizeof(suffix), "_%03d.obj", frame);
  return {ReadObj(folder + "/patient1_LV_ENDOCARDIAL" + suffix),
          ReadObj(folder + "/patient1_EPICARDIAL" + suffix)};
}

// biv-me patient 1's meshes at end-diastole (frame 0) and end-systole
// (frame 9), voxelized with ACDC's labels.
MeshMask BivMeMask() {
  const std::string obj = SharedDataDirectory() + "/biv-me-patient1/obj";
  return MakeMeshMask({ReadFrame(obj, 0), ReadFrame(obj, 9)}, LabelMap());
}

double Ef(double ed, double es) { return (ed - es) / ed; }

// biv-me's meshes at end-diastole (frame 0) and end-systole (frame 9), as
// ACDC gives a patient: 1.5 mm in-plane, 8 mm slices.  The fitted cavity's
// volumes and EF within 5 % of the voxels counted and of the meshes' own,
// the mass within 10 % of the voxels', the segments anchored by the RV, and
// no slice taken for misaligned.
TEST(MeshMaskTest, BivMeMeshesVoxelizedFitToTheirVolumes) {
  if (SharedDataDirectory().empty()) {
    GTEST_SKIP() << "../shared/data is absent";
  }
  const MeshMask mask = BivMeMask();
  const MaskContours contours = ExtractMaskContours(mask.volume, LabelMap());
  EXPECT_TRUE(contours.misaligned.empty());
  const SequenceFit fit =
      FitSequence(contours.points, ModelConfig::Paper(17), FitOptions());
  ASSERT_TRUE(fit.config.Solid());
  RvInsertion insertion;
  insertion.unlabelled = contours.rv_insertion;
  const FitAnalysis analysis =
      AnalyzeFit(fit, {}, AnatomicalLayout(fit.ModelAt(0), insertion));
  for (int t = 0; t < 2; ++t) {
    const ClinicalSummary& c = analysis.clinical[t];
    std::printf(
        "frame %d: %zu points, wall %.1f mm, rms %.2f mm, %s; cavity fit "
        "%.1f voxels %.1f mesh %.1f ml; mass fit %.1f voxels %.1f g\n",
        t, contours.points.frames[t].points.size(), mask.wall_mm[t],
        fit.frames[t].rms_mm, analysis.verdicts[t].Summary().c_str(),
        c.volume_ml, mask.cavity_ml[t], mask.mesh_cavity_ml[t], c.lv_mass_g,
        1.05 * mask.myocardium_ml[t]);
    EXPECT_NEAR(c.volume_ml, mask.cavity_ml[t], 0.05 * mask.cavity_ml[t]);
    EXPECT_NEAR(c.volume_ml, mask.mesh_cavity_ml[t],
                0.05 * mask.mesh_cavity_ml[t]);
    EXPECT_NEAR(c.lv_mass_g, 1.05 * mask.myocardium_ml[t],
                0.10 * 1.05 * mask.myocardium_ml[t]);
    EXPECT_LT(fit.frames[t].rms_mm, 1.5);
  }
  const double ef = analysis.ejection_fraction.ratio;
  const double voxel_ef = Ef(mask.cavity_ml[0], mask.cavity_ml[1]);
  const double mesh_ef = Ef(mask.mesh_cavity_ml[0], mask.mesh_cavity_ml[1]);
  std::printf("EF fit %.3f voxels %.3f meshes %.3f\n", ef, voxel_ef, mesh_ef);
  EXPECT_NEAR(ef, voxel_ef, 0.05 * voxel_ef);
  EXPECT_NEAR(ef, mesh_ef, 0.05 * mesh_ef);
  EXPECT_TRUE(analysis.layout.anatomical) << analysis.layout.anchor;
}

// The same mask as ACDC lays a patient out (one 3D file per frame,
// patientNNN_frameMM_gt.nii.gz, ED and ES) through `pfdm fit
// --segmentation DIR --labels acdc`: the fit, the labels in fit.json, the
// report with its 3D view and slices.
TEST(MeshMaskTest, CliFitsBivMeAsAnAcdcFolder) {
  if (SharedDataDirectory().empty()) {
    GTEST_SKIP() << "../shared/data is absent";
  }
  const MeshMask mask = BivMeMask();
  const std::string dir = ScratchDirectory("out");
  const std::string patient = ScratchDirectory("patient001");
  WriteLabelVolume(mask.volume, patient + "/patient001_frame01_gt.nii.gz", 0,
                   1);
  WriteLabelVolume(mask.volume, patient + "/patient001_frame10_gt.nii.gz", 1,
                   1);
  const CommandResult r = RunPfdm("fit --segmentation " + patient +
                                  " --labels acdc --out " + dir + "/fit");
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const nlohmann::json json =
      nlohmann::json::parse(ReadText(dir + "/fit/fit.json"));
  const double mesh_ef = Ef(mask.mesh_cavity_ml[0], mask.mesh_cavity_ml[1]);
  EXPECT_NEAR(json["ejection_fraction"]["ratio"].get<double>(), mesh_ef,
              0.05 * mesh_ef);
  EXPECT_EQ(json["segmentation"]["source"], patient);
  EXPECT_EQ(json["segmentation"]["labels"]["lv"], 3);
  EXPECT_EQ(json["segmentation"]["frames"], 2);
  EXPECT_TRUE(json["segmentation"]["misaligned"].empty());
  EXPECT_EQ(json["segments_anatomical"], true);
  const std::string report = ReadText(dir + "/fit/report.html");
  EXPECT_NE(report.find("<h2>The segmentation and the fit</h2>"),
            std::string::npos);
  EXPECT_NE(report.find("pfdm-view3d"), std::string::npos);
}

}  // namespace
}  // namespace pfdm
