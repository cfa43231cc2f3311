#include "pfdm/io/mesh_source.h"

#include <filesystem>
#include <string>

#include "gtest/gtest.h"
#include "pfdm/testing/test_util.h"

namespace pfdm {
namespace {

// A triangle at height z, with point scalars `is_data` as given.
std::string Triangle(double z, const std::string& is_data = "") {
  const std::string h = std::to_string(z);
  std::string vtk =
      "# vtk DataFile Version 3.0\nt\nASCII\nDATASET POLYDATA\nPOINTS 3 "
      "double\n0 0 " +
      h + " 1 0 " + h + " 0 1 " + h + "\nPOLYGONS 1 4\n3 0 1 2\n";
  if (!is_data.empty()) {
    vtk += "POINT_DATA 3\nSCALARS is_data double 1\nLOOKUP_TABLE default\n" +
           is_data + "\n";
  }
  return vtk;
}

// A folder reads as its .obj files or, without any, its .vtk files: each
// one frame, in name order, the filter keeping names that contain it.
TEST(MeshSourceTest, FolderFramesInNameOrderByExtension) {
  const std::string dir = ScratchDirectory("mesh_source") + "/frames";
  std::filesystem::create_directories(dir);
  WriteText(dir + "/b_001.vtk", Triangle(2));
  WriteText(dir + "/b_000.vtk", Triangle(1));
  WriteText(dir + "/other.vtk", Triangle(9));
  WriteText(dir + "/notes.txt", "not a mesh\n");
  MeshSettings settings;
  settings.mesh_filter = "b_";
  std::vector<TriangleMesh> frames = ReadMeshFrames(dir, settings);
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_EQ(frames[0].points[0].z(), 1.0);
  EXPECT_EQ(frames[1].points[0].z(), 2.0);
  WriteText(dir + "/m.obj", "v 0 0 5\nv 1 0 5\nv 0 1 5\nf 1 2 3\n");
  settings.mesh_filter = "";
  frames = ReadMeshFrames(dir, settings);
  ASSERT_EQ(frames.size(), 1u);  // The .obj, where there is one.
  EXPECT_EQ(frames[0].points[0].z(), 5.0);
  settings.mesh_format = "vtk";
  EXPECT_EQ(ReadMeshFrames(dir, settings).size(), 3u);
  settings.mesh_filter = "zz";
  EXPECT_EQ(InputErrorOf([&] { ReadMeshFrames(dir, settings); }),
            dir + ": no .vtk file matching 'zz'");
}

// The wall a mesh is of, by name: biv-me's LV_ENDOCARDIAL files, the CAP
// surfaces; nothing for mixed names, other names or a VTK label.
TEST(MeshSourceTest, SurfaceFromTheNames) {
  const std::string dir = ScratchDirectory("mesh_surface") + "/obj";
  std::filesystem::create_directories(dir);
  const std::string tri = "v 0 0 5\nv 1 0 5\nv 0 1 5\nf 1 2 3\n";
  for (const char* name :
       {"patient1_LV_ENDOCARDIAL_000.obj", "patient1_LV_ENDOCARDIAL_001.obj",
        "patient1_EPICARDIAL_000.obj"}) {
    WriteText(dir + "/" + name, tri);
  }
  MeshSettings settings;
  settings.mesh_filter = "LV_ENDO";
  EXPECT_EQ(MeshSurface(dir, settings), WallLayer::kEndocardium);
  const PointSequence points = ReadMeshPoints(dir, settings);
  EXPECT_EQ(points.frames[1].points[2].layer, WallLayer::kEndocardium);
  settings.mesh_filter = "EPI";
  EXPECT_EQ(MeshSurface(dir, settings), WallLayer::kEpicardium);
  settings.mesh_filter = "";
  EXPECT_EQ(MeshSurface(dir, settings), WallLayer::kAnywhere);
  EXPECT_EQ(MeshSurface(dir + "/patient1_EPICARDIAL_000.obj", settings),
            WallLayer::kEpicardium);
  MeshSettings cap;
  cap.cap_surfaces = "ED-endo,ES-endo";
  EXPECT_EQ(MeshSurface("mean_shape.csv", cap), WallLayer::kEndocardium);
  cap.cap_surfaces = "ED-epi,ES-epi";
  EXPECT_EQ(MeshSurface("mean_shape.csv", cap), WallLayer::kEpicardium);
  cap.cap_surfaces = "ED-endo,ED-epi";
  EXPECT_EQ(MeshSurface("mean_shape.csv", cap), WallLayer::kAnywhere);
  MeshSettings labelled;
  labelled.label = "1";
  EXPECT_EQ(MeshSurface(dir + "/patient1_LV_ENDOCARDIAL_000.obj", labelled),
            WallLayer::kAnywhere);
}

// pfdm's own frames carry is_data: their data points would pair by their
// place in each file, so they are refused without a label.
TEST(MeshSourceTest, PfdmFramesNeedTheirLabel) {
  const std::string path = ScratchDirectory("mesh_source") + "/frame_000.vtk";
  WriteText(path, Triangle(0, "0 0 1"));
  MeshSettings settings;
  EXPECT_EQ(InputErrorOf([&] { ReadMeshFrames(path, settings); }),
            path +
                ": a pfdm frame with its data points (is_data = 1); "
                "--label is_data=0 keeps the model's vertices");
  settings.label = "is_data=0";
  EXPECT_EQ(ReadMeshFrames(path, settings)[0].points.size(), 2u);
  WriteText(path, Triangle(0, "0 0 0"));  // No data points: nothing to mix.
  EXPECT_EQ(ReadMeshFrames(path, MeshSettings())[0].points.size(), 3u);
}

}  // namespace
}  // namespace pfdm
