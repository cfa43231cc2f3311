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
