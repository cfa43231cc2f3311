#include "pfdm/io/vtk_xml_reader.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "gtest/gtest.h"
#include "pfdm/io/vtp_writer.h"
#include "pfdm/testing/small_poly_data.h"
#include "pfdm/testing/test_util.h"
#include "pfdm/util/error.h"

namespace pfdm {
namespace {

// pfdm's own .vtp in each encoding and precision: binary doubles back
// exactly, floats as the nearest float (in text, a decimal that rounds to
// it), text doubles to their nine digits; the vertices' cells and the
// vectors passed over.
TEST(VtkXmlReaderTest, ReadsWhatPfdmWritesInEveryForm) {
  const VtkPolyData data = SmallPolyData();
  const std::string path = ScratchDirectory("vtk_xml") + "/m.vtp";
  for (VtkFormat format : {VtkFormat::kBinary, VtkFormat::kAscii}) {
    for (VtkPrecision precision :
         {VtkPrecision::kDouble, VtkPrecision::kFloat}) {
      WriteText(path, ToVtkXmlPolyData(data, format, precision));
      const VtkMesh vtk = ReadVtkXmlPolyData(path);
      const bool single = precision == VtkPrecision::kFloat;
      const bool text = format == VtkFormat::kAscii;
      ASSERT_EQ(vtk.mesh.points.size(), 4u);
      for (size_t i = 0; i < 4; ++i) {
        for (int k = 0; k < 3; ++k) {
          const double want = data.points[i][k];
          // In text a float is its shortest decimal, read as a double
          // that rounds to the same float.
          if (single && text) {
            EXPECT_EQ(static_cast<float>(vtk.mesh.points[i][k]),
                      static_cast<float>(want));
          } else if (single) {
            EXPECT_EQ(vtk.mesh.points[i][k], static_cast<float>(want));
          } else if (text) {
            EXPECT_NEAR(vtk.mesh.points[i][k], want, 1e-8 * std::abs(want));
          } else {
            EXPECT_EQ(vtk.mesh.points[i][k], want);
          }
        }
      }
      EXPECT_EQ(vtk.mesh.triangles, data.triangles);
      ASSERT_EQ(vtk.point_scalars.size(), 2u);
      EXPECT_EQ(vtk.point_scalars.at("is_data"),
                (std::vector<double>{0, 0, 0, 1}));
      EXPECT_NEAR(vtk.point_scalars.at("u")[2], 1.0 / 7, single ? 1e-8 : 1e-9);
    }
  }
}

// Another writer's file: big-endian, UInt32 headers, Int64 cells, a quad
// fanned into two triangles, UInt8 labels.
TEST(VtkXmlReaderTest, ReadsOtherByteOrdersHeadersAndTypes) {
  std::string appended;
  const auto big = [&appended](std::uint64_t value, int bytes) {
    for (int i = bytes - 1; i >= 0; --i) {
      appended += static_cast<char>(value >> (8 * i));
    }
  };
  const auto big_float = [&big](float value) {
    std::uint32_t bits;
    std::memcpy(&bits, &value, 4);
    big(bits, 4);
  };
  big(4 * 12, 4);  // Points: 4 x 3 Float32.
  for (float v : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 1.f, 1.f, 0.f, 0.f, 1.f, 0.f}) {
    big_float(v);
  }
  const size_t connectivity = appended.size();
  big(4 * 8, 4);
  for (int v : {0, 1, 2, 3}) big(v, 8);
  const size_t offsets = appended.size();
  big(8, 4);
  big(4, 8);
  const size_t labels = appended.size();
  big(4, 4);
  for (int v : {7, 7, 8, 255}) big(v, 1);
  const std::string xml =
      "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\" "
      "byte_order=\"BigEndian\">\n<PolyData>\n<Piece NumberOfPoints=\"4\" "
      "NumberOfPolys=\"1\">\n<PointData Scalars=\"label\">\n"
      "<DataArray type=\"UInt8\" Name=\"label\" format=\"appended\" "
      "offset=\"" +
      std::to_string(labels) +
      "\"/>\n</PointData>\n<Points>\n<DataArray type=\"Float32\" "
      "NumberOfComponents=\"3\" format=\"appended\" offset=\"0\"/>\n"
      "</Points>\n<Polys>\n<DataArray type=\"Int64\" Name=\"connectivity\" "
      "format=\"appended\" offset=\"" +
      std::to_string(connectivity) +
      "\"/>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"appended\" "
      "offset=\"" +
      std::to_string(offsets) +
      "\"/>\n</Polys>\n</Piece>\n</PolyData>\n<AppendedData "
      "encoding=\"raw\">\n_" +
      appended + "\n</AppendedData>\n</VTKFile>\n";
  const std::string path = ScratchDirectory("vtk_xml") + "/other.vtp";
  WriteText(path, xml);
  const VtkMesh vtk = ReadVtkXmlPolyData(path);
  ASSERT_EQ(vtk.mesh.points.size(), 4u);
  EXPECT_EQ(vtk.mesh.points[2], Eigen::Vector3d(1, 1, 0));
  EXPECT_EQ(vtk.mesh.triangles,
            (std::vector<std::array<int, 3>>{{0, 1, 2}, {0, 2, 3}}));
  EXPECT_EQ(vtk.point_scalars.at("label"), (std::vector<double>{7, 7, 8, 255}));
}

TEST(VtkXmlReaderTest, RefusesWhatItCannotReadNamingTheFile) {
  const std::string dir = ScratchDirectory("vtk_xml_bad");
  const auto message = [&dir](const std::string& text) {
    WriteText(dir + "/m.vtp", text);
    try {
      ReadVtkXmlPolyData(dir + "/m.vtp");
    } catch (const InputError& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  const std::string at = dir + "/m.vtp: ";
  EXPECT_EQ(message("hello"), at + "not a VTK XML file (no <VTKFile>)");
  EXPECT_EQ(message("<VTKFile type=\"UnstructuredGrid\">"),
            at + "a VTK XML 'UnstructuredGrid' file, not PolyData");
  EXPECT_EQ(message("<VTKFile type=\"PolyData\" "
                    "compressor=\"vtkZLibDataCompressor\">"),
            at + "compressed arrays (vtkZLibDataCompressor); save without "
                 "compression");
  EXPECT_EQ(message("<VTKFile type=\"PolyData\"><Points><DataArray "
                    "type=\"Float64\" format=\"binary\">AAAA</DataArray>"),
            at + "DataArray format 'binary' (pfdm reads ascii and appended "
                 "raw)");
  const std::string truncated =
      ToVtkXmlPolyData(SmallPolyData(), VtkFormat::kBinary);
  EXPECT_EQ(message(truncated.substr(0, truncated.size() - 200)),
            at + "DataArray offset past the end");
}

}  // namespace
}  // namespace pfdm
