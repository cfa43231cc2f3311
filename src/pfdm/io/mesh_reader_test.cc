#include "pfdm/io/mesh_reader.h"

#include "gtest/gtest.h"
#include "pfdm/testing/test_util.h"

namespace pfdm {
namespace {

TEST(MeshReaderTest, ObjVerticesAndFacesInEveryForm) {
  const std::string path = ScratchDirectory("obj") + "/m.obj";
  WriteText(path,
            "# comment\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\n"
            "f 1/1/1 2/2/1 3/3/1 4/4/1\nf -4 -2 -1\ns off\n");
  const TriangleMesh mesh = ReadObj(path);
  ASSERT_EQ(mesh.points.size(), 4u);
  EXPECT_EQ(mesh.points[2], Eigen::Vector3d(1, 1, 0));
  ASSERT_EQ(mesh.triangles.size(), 3u);  // A quad fanned into two, then one.
  EXPECT_EQ(mesh.triangles[1], (std::array<int, 3>{0, 2, 3}));
  EXPECT_EQ(mesh.triangles[2], (std::array<int, 3>{0, 2, 3}));
}

TEST(MeshReaderTest, ObjErrorsNameFileAndLine) {
  const std::string dir = ScratchDirectory("obj");
  WriteText(dir + "/a.obj", "v 0 0 0\nv 1 x 0\n");
  EXPECT_EQ(InputErrorOf([&] { ReadObj(dir + "/a.obj"); }),
            dir + "/a.obj:2: 'x' is not a number");
  WriteText(dir + "/b.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n");
  EXPECT_EQ(InputErrorOf([&] { ReadObj(dir + "/b.obj"); }),
            dir + "/b.obj:4: vertex 8 out of range");
  EXPECT_EQ(InputErrorOf([&] { ReadObj(dir + "/none.obj"); }),
            dir + "/none.obj: cannot open the file");
}

// Issue 14: a NUL byte cut a line short.
TEST(MeshReaderTest, ObjWithANulByteIsNotText) {
  const std::string obj = ScratchDirectory("obj") + "/m.obj";
  WriteText(obj, std::string("v 0 0 0\nv 1 0 0\nv 0 1") + '\0' + "\n");
  EXPECT_EQ(InputErrorOf([&] { ReadObj(obj); }),
            obj + ":3: contains a NUL byte (not a text file?)");
}

TEST(MeshReaderTest, CapMeanShapeIsFourSurfacesOfXyzPoints) {
  const std::string dir = ScratchDirectory("cap");
  std::string values;
  for (int i = 0; i < 24; ++i) values += std::to_string(i) + "\n";
  WriteText(dir + "/mean_shape.csv", values);
  WriteText(dir + "/surface_face.csv", "1,2,1\n2,1,2\n");
  const auto surfaces = ReadCapMeanShape(dir + "/mean_shape.csv");
  ASSERT_EQ(surfaces.size(), 4u);
  ASSERT_EQ(surfaces[0].size(), 2u);
  EXPECT_EQ(surfaces[0][1], Eigen::Vector3d(3, 4, 5));
  EXPECT_EQ(surfaces[2][0], Eigen::Vector3d(12, 13, 14));
  const auto faces = ReadCapFaces(dir + "/surface_face.csv", 2);
  ASSERT_EQ(faces.size(), 2u);
  EXPECT_EQ(faces[1], (std::array<int, 3>{1, 0, 1}));
  EXPECT_EQ(InputErrorOf([&] { ReadCapFaces(dir + "/surface_face.csv", 1); }),
            dir + "/surface_face.csv:1: vertex 2 out of range 1..1");
  WriteText(dir + "/short.csv", "1\n2\n3\n");
  EXPECT_EQ(InputErrorOf([&] { ReadCapMeanShape(dir + "/short.csv"); }),
            dir + "/short.csv: 3 values, not 4 surfaces of x y z points");
}

TEST(MeshReaderTest, VerticesBecomeTrackedPoints) {
  const PointSequence sequence = MeshPointSequence(
      "meshes", {{{0, 0, 0}, {1, 0, 0}}, {{0, 0, 1}, {1, 0, 1}}});
  ASSERT_EQ(sequence.frames.size(), 2u);
  EXPECT_EQ(sequence.frames[1].index, 1);
  EXPECT_EQ(sequence.frames[1].points[1].id, 1);
  EXPECT_EQ(sequence.frames[1].points[1].position, Eigen::Vector3d(1, 0, 1));
  EXPECT_EQ(InputErrorOf([] {
              MeshPointSequence("m", {{{0, 0, 0}}, {}});
            }),
            "m: frame 1 has 0 vertices, frame 0 1");
}

}  // namespace
}  // namespace pfdm
