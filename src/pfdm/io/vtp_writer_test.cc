#include "pfdm/io/vtp_writer.h"

#include <cmath>
#include <cstdint>
#include <vector>

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
  EXPECT_NE(xml.find("<Verts>\n        <DataArray type=\"Int32\" "
                     "Name=\"connectivity\" format=\"ascii\">\n 3\n"),
            std::string::npos);
  EXPECT_NE(xml.find("Name=\"offsets\" format=\"ascii\">\n 3\n"),
            std::string::npos);
  EXPECT_NE(xml.find(" 5 5 5\n"), std::string::npos);
  EXPECT_EQ(CountOf(xml, "<DataArray"), 7);
  EXPECT_EQ(CountOf(xml, "</DataArray>"), 7);
}

// Appended raw: the XML names each array, its bytes follow; read back by an
// independent reader they are the doubles and indices given, bit for bit.
TEST(VtpWriterTest, BinaryPolyDataReadsBackExactly) {
  VtkPolyData data;
  data.points = {{1.0 / 3.0, -0.0, 1e-300}, {1, 0, 0}, {0, 1, 0}, {5, 5, 5}};
  data.triangles = {{0, 1, 2}, {1, 2, 3}};
  data.vertices = {3};
  data.point_scalars = {{"twist_deg", {0, M_PI, -2e9, 3.5}},
                        {"a<b", {1, 2, 3, 4}}};
  data.point_vectors = {
      {"residual", {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}, {1, -2, 1.0 / 7.0}}}};
  const std::string xml = ToVtkXmlPolyData(data, VtkFormat::kBinary);
  EXPECT_EQ(xml.rfind("<?xml", 0), 0u);
  EXPECT_NE(xml.find("NumberOfPoints=\"4\" NumberOfVerts=\"1\""),
            std::string::npos);
  EXPECT_NE(xml.find("Name=\"a&lt;b\""), std::string::npos);
  EXPECT_EQ(CountOf(xml, "<DataArray"), 8);
  EXPECT_EQ(CountOf(xml, "format=\"appended\""), 8);
  const std::string end = "\n  </AppendedData>\n</VTKFile>\n";
  EXPECT_EQ(xml.substr(xml.size() - end.size()), end);

  const VtkXmlArrays arrays = ReadAppendedRawVtkXml(xml);
  const std::vector<double> points = arrays.float64.at("Points");
  ASSERT_EQ(points.size(), 12u);
  for (size_t i = 0; i < 4; ++i) {
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(points[3 * i + k], data.points[i][k]) << i;
    }
  }
  EXPECT_TRUE(std::signbit(points[1]));
  EXPECT_EQ(arrays.float64.at("PointData/twist_deg"),
            data.point_scalars[0].second);
  // The reader does not unescape names.
  EXPECT_EQ(arrays.float64.at("PointData/a&lt;b"),
            data.point_scalars[1].second);
  EXPECT_EQ(arrays.float64.at("PointData/residual"),
            (std::vector<double>{0, 0, 0, 0, 0, 0, 0, 0, 0, 1, -2, 1.0 / 7.0}));
  EXPECT_EQ(arrays.types.at("Points"), "Float64");
  EXPECT_EQ(arrays.types.at("PointData/twist_deg"), "Float64");
  EXPECT_EQ(arrays.types.at("Polys/connectivity"), "Int32");
  EXPECT_EQ(arrays.types.at("Verts/offsets"), "Int32");
  EXPECT_EQ(arrays.int64.at("Verts/connectivity"),
            (std::vector<std::int64_t>{3}));
  EXPECT_EQ(arrays.int64.at("Verts/offsets"), (std::vector<std::int64_t>{1}));
  EXPECT_EQ(arrays.int64.at("Polys/connectivity"),
            (std::vector<std::int64_t>{0, 1, 2, 1, 2, 3}));
  EXPECT_EQ(arrays.int64.at("Polys/offsets"),
            (std::vector<std::int64_t>{3, 6}));
}

// Float precision: every real array Float32, each value the nearest float
// to the double given (a relative 6e-8); float32_scalars are Float32 even
// in double precision, the rest Float64 there.
TEST(VtpWriterTest, FloatPrecisionHalvesTheRealsAndKeepsFlagsNarrow) {
  VtkPolyData data;
  data.points = {{1.0 / 3.0, 40.123456789, -55.5}, {1, 0, 0}, {0, 1, 0}};
  data.triangles = {{0, 1, 2}};
  data.point_scalars = {{"u", {0.1, 0.2, 1.0 / 7.0}}, {"is_data", {0, 0, 1}}};
  data.point_vectors = {{"residual", {{0, 0, 0}, {0, 0, 0}, {0.5, -1e-3, 2}}}};
  data.float32_scalars = {"is_data"};
  const VtkXmlArrays single = ReadAppendedRawVtkXml(
      ToVtkXmlPolyData(data, VtkFormat::kBinary, VtkPrecision::kFloat));
  for (const char* key :
       {"Points", "PointData/u", "PointData/is_data", "PointData/residual"}) {
    EXPECT_EQ(single.types.at(key), "Float32") << key;
  }
  const std::vector<double>& points = single.float64.at("Points");
  ASSERT_EQ(points.size(), 9u);
  for (size_t i = 0; i < 3; ++i) {
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(points[3 * i + k], static_cast<float>(data.points[i][k]));
      EXPECT_NEAR(points[3 * i + k], data.points[i][k],
                  6e-8 * std::abs(data.points[i][k]));
    }
  }
  EXPECT_EQ(single.float64.at("PointData/is_data"),
            (std::vector<double>{0, 0, 1}));
  const VtkXmlArrays exact = ReadAppendedRawVtkXml(
      ToVtkXmlPolyData(data, VtkFormat::kBinary, VtkPrecision::kDouble));
  EXPECT_EQ(exact.types.at("Points"), "Float64");
  EXPECT_EQ(exact.types.at("PointData/u"), "Float64");
  EXPECT_EQ(exact.types.at("PointData/residual"), "Float64");
  EXPECT_EQ(exact.types.at("PointData/is_data"), "Float32");
  EXPECT_EQ(exact.float64.at("PointData/u"), data.point_scalars[0].second);
  // In text, floats as their shortest decimal.
  const std::string ascii =
      ToVtkXmlPolyData(data, VtkFormat::kAscii, VtkPrecision::kFloat);
  EXPECT_NE(ascii.find("type=\"Float32\" Name=\"u\" format=\"ascii\">\n "
                       "0.1 0.2 0.14285715\n"),
            std::string::npos)
      << ascii;
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
