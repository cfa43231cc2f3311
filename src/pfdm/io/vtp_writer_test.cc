#include "pfdm/io/vtp_writer.h"

#include "gtest/gtest.h"
#include "pfdm/testing/test_util.h"

namespace pfdm {
namespace {

TEST(VtpWriterTest, PolyDataHasPointsCellsAndNamedArrays) {
  VtkPolyData data;
  data.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 5, 5}};
  data.triangles = {{0, 1, 2}};
  data.vertices = {3};
  data.point_scalars = {{"twist_deg", {0, 1, 2, 3.5}}};
  data.point_vectors = {
      {"residual", {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}, {1, 2, 3}}}};
  const std::string xml = ToVtkXmlPolyData(data);
  EXPECT_EQ(xml.rfind("<?xml", 0), 0u);
  EXPECT_NE(xml.find("NumberOfPoints=\"4\" NumberOfVerts=\"1\""),
            std::string::npos);
  EXPECT_NE(xml.find("NumberOfPolys=\"1\""), std::string::npos);
  EXPECT_NE(xml.find("Name=\"twist_deg\" format=\"ascii\">\n 0 1 2 3.5\n"),
            std::string::npos);
  EXPECT_NE(xml.find("Name=\"residual\" NumberOfComponents=\"3\""),
            std::string::npos);
  // Verts: connectivity 3, offsets 1; Polys: connectivity 0 1 2, offsets 3.
  EXPECT_NE(xml.find("<Verts>\n        <DataArray type=\"Int64\" "
                     "Name=\"connectivity\" format=\"ascii\">\n 3\n"),
            std::string::npos);
  EXPECT_NE(xml.find("Name=\"offsets\" format=\"ascii\">\n 3\n"),
            std::string::npos);
  EXPECT_NE(xml.find(" 5 5 5\n"), std::string::npos);
  EXPECT_EQ(CountOf(xml, "<DataArray"), 7);
  EXPECT_EQ(CountOf(xml, "</DataArray>"), 7);
}

TEST(VtpWriterTest, CollectionListsEveryTimestep) {
  const std::string pvd = PvdCollection(
      {{0, "frame_000.vtp"}, {1, "frame_001.vtp"}, {2, "a&b.vtp"}});
  EXPECT_NE(pvd.find("type=\"Collection\""), std::string::npos);
  EXPECT_EQ(CountOf(pvd, "<DataSet "), 3);
  EXPECT_NE(
      pvd.find("timestep=\"1\" group=\"\" part=\"0\" file=\"frame_001.vtp\""),
      std::string::npos);
  EXPECT_NE(pvd.find("file=\"a&amp;b.vtp\""), std::string::npos);
}

}  // namespace
}  // namespace pfdm
