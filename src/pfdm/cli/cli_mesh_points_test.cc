// pfdm mesh-points end to end: OBJ frames to tracked points and measures.
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "gtest/gtest.h"
#include "nlohmann/json.hpp"
#include "pfdm/testing/test_util.h"

namespace pfdm {
namespace {

// An open square pyramid (apex at z = 0, rim at z = h) as OBJ text.
std::string Pyramid(double half_width, double h) {
  std::string obj = "v 0 0 0\n";
  const int corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  for (const auto& c : corners) {
    obj += "v " + std::to_string(c[0] * half_width) + " " +
           std::to_string(c[1] * half_width) + " " + std::to_string(h) + "\n";
  }
  return obj + "f 1 3 2\nf 1 4 3\nf 1 5 4\nf 1 2 5\n";
}

TEST(CliMeshPointsTest, ObjFolderBecomesTrackedFramesWithMeasures) {
  const std::string dir = ScratchDirectory("mesh_points");
  std::filesystem::create_directories(dir + "/obj");
  WriteText(dir + "/obj/heart_LV_000.obj", Pyramid(10, 30));
  WriteText(dir + "/obj/heart_LV_001.obj", Pyramid(8, 27));
  WriteText(dir + "/obj/heart_RV_000.obj", Pyramid(1, 1));
  const CommandResult run =
      RunPfdm("mesh-points --mesh " + dir + "/obj --mesh_filter _LV_ --out " +
              dir + "/points.csv");
  ASSERT_EQ(run.exit_code, 0) << run.error;
  const std::string csv = ReadText(dir + "/points.csv");
  EXPECT_EQ(csv.rfind("frame,id,x,y,z\n0,0,0,0,0\n0,1,-10,-10,30\n", 0), 0u)
      << csv;
  EXPECT_NE(csv.find("\n1,4,-8,8,27\n"), std::string::npos);
  // Volume 20 x 20 x 30 / 3 = 4 ml, then 16 x 16 x 27 / 3 = 2.304 ml; the
  // length 30 then 27 (10 %); corners 20 % nearer the axis.
  EXPECT_NE(run.output.find("    0       4.00      30.00            0.00"),
            std::string::npos)
      << run.output;
  EXPECT_NE(run.output.find("    1       2.30      27.00           10.00"
                            "     20.00"),
            std::string::npos)
      << run.output;
}

TEST(CliMeshPointsTest, UnknownFormatIsOneLine) {
  const std::string dir = ScratchDirectory("mesh_points");
  WriteText(dir + "/m.ply", "ply\n");
  const CommandResult run = RunPfdm("mesh-points --mesh " + dir +
                                    "/m.ply --out " + dir + "/points.csv");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.error, "pfdm: error: " + dir +
                           "/m.ply: unknown mesh format (use --mesh_format)\n");
  EXPECT_FALSE(std::filesystem::exists(dir + "/points.csv"));
}

// Issue 14: with two scalar arrays --label silently used the alphabetically
// first.
TEST(CliMeshPointsTest, LabelNamesItsArrayWhenThereAreSeveral) {
  const std::string dir = ScratchDirectory("mesh_points");
  WriteText(dir + "/m.vtk",
            "# vtk DataFile Version 3.0\nm\nASCII\nDATASET POLYDATA\n"
            "POINTS 4 float\n0 0 0 1 0 0 0 1 0 0 0 1\n"
            "POLYGONS 2 8\n3 0 1 2\n3 0 2 3\n"
            "POINT_DATA 4\nSCALARS a float\nLOOKUP_TABLE default\n0 0 0 1\n"
            "SCALARS b float\nLOOKUP_TABLE default\n1 1 0 0\n");
  CommandResult run = RunPfdm("mesh-points --mesh " + dir +
                              "/m.vtk --label 0 --out " + dir + "/points.csv");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.error, "pfdm: error: " + dir +
                           "/m.vtk: --label 0 is ambiguous, the file has point "
                           "scalars a, b; give --label NAME=0\n");
  EXPECT_FALSE(std::filesystem::exists(dir + "/points.csv"));
  run = RunPfdm("mesh-points --mesh " + dir + "/m.vtk --label b=1 --out " +
                dir + "/points.csv");
  ASSERT_EQ(run.exit_code, 0) << run.error;
  EXPECT_EQ(ReadText(dir + "/points.csv"),
            "frame,id,x,y,z\n0,0,0,0,0\n0,1,1,0,0\n");
}

// The meshes `pfdm fit` writes (binary .vtp of float32 by default; legacy
// VTK as text on request) read back as frames of material points: the model's
// vertices (is_data = 0) keep their count over frames, and the volume the
// meshes enclose is the mid-wall volume fit.json reports, measured a second way
// (on the faceted surface: within 1 %).  Written as legacy text instead, the
// same volumes to 0.01 ml.
TEST(CliMeshPointsTest, FitMeshesReadBackAsFramesOfTheirVolume) {
  const std::string dir = ScratchDirectory("mesh_points_fit");
  ASSERT_EQ(
      RunPfdm("simulate --frames 3 --tags 400 --out " + dir + "/phantom.csv")
          .exit_code,
      0);
  std::vector<double> volumes[2];
  for (const std::string format : {"vtp", "vtk,ascii"}) {
    const std::string out = dir + "/fit_" + format.substr(0, 3);
    const CommandResult fit =
        RunPfdm("fit --points " + dir + "/phantom.csv --vtk_format " + format +
                " --out " + out);
    ASSERT_EQ(fit.exit_code, 0) << fit.error;
    const CommandResult run =
        RunPfdm("mesh-points --mesh " + out + " --label is_data=0 --out " +
                dir + "/points_" + format.substr(0, 3) + ".csv");
    ASSERT_EQ(run.exit_code, 0) << run.error;
    EXPECT_NE(run.output.find("(3 frames x "), std::string::npos) << run.output;
    const nlohmann::json json =
        nlohmann::json::parse(ReadText(out + "/fit.json"));
    std::istringstream lines(run.output);
    std::string line;
    std::vector<double>& measured = volumes[format != "vtp"];
    while (std::getline(lines, line)) {
      int frame;
      double volume;
      if (std::sscanf(line.c_str(), "%d %lf", &frame, &volume) == 2) {
        measured.push_back(volume);
        const double reported =
            json["frames"][frame]["midwall_volume_ml"].get<double>();
        EXPECT_NEAR(volume / reported, 1.0, 0.01) << format << " " << line;
      }
    }
    EXPECT_EQ(measured.size(), 3u) << run.output;
  }
  // Without the label the data points would join the vertices.
  const CommandResult unlabelled =
      RunPfdm("mesh-points --mesh " + dir + "/fit_vtp --out " + dir +
              "/unlabelled.csv");
  EXPECT_EQ(unlabelled.exit_code, 1);
  EXPECT_EQ(unlabelled.error,
            "pfdm: error: " + dir +
                "/fit_vtp/frame_000.vtp: a pfdm frame with its data points "
                "(is_data = 1); --label is_data=0 keeps the model's "
                "vertices\n");
  EXPECT_FALSE(std::filesystem::exists(dir + "/unlabelled.csv"));
  ASSERT_EQ(volumes[0].size(), volumes[1].size());
  for (size_t t = 0; t < volumes[0].size(); ++t) {
    EXPECT_NEAR(volumes[0][t], volumes[1][t], 0.01) << t;
  }
}

}  // namespace
}  // namespace pfdm
