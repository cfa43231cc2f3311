#include "pfdm/io/legacy_vtk_reader.h"

#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "gtest/gtest.h"
#include "pfdm/io/vtk_writer.h"
#include "pfdm/testing/small_poly_data.h"
#include "pfdm/testing/test_util.h"

namespace pfdm {
namespace {

TEST(LegacyVtkReaderTest, AsciiPointsPolygonsAndLabels) {
  const std::string path = ScratchDirectory("vtk") + "/m.vtk";
  WriteText(path,
            "# vtk DataFile Version 3.0\nvtk output\nASCII\nDATASET POLYDATA\n"
            "POINTS 4 float\n0 0 0 1 0 0 0 1 0\n0 0 1\n"
            "POLYGONS 2 8\n3 0 1 2\n3 0 2 3\n\n"
            "POINT_DATA 4\nSCALARS scalars float\nLOOKUP_TABLE lookup_table\n"
            "0 0 1\n1\nLOOKUP_TABLE lookup_table 2\n0.7 0.01 0.1 1\n"
            "0.9 0.6 0.5 1\n");
  const VtkMesh vtk = ReadLegacyVtkPolyData(path);
  ASSERT_EQ(vtk.mesh.points.size(), 4u);
  EXPECT_EQ(vtk.mesh.points[3], Eigen::Vector3d(0, 0, 1));
  ASSERT_EQ(vtk.mesh.triangles.size(), 2u);
  EXPECT_EQ(vtk.point_scalars.at("scalars"), (std::vector<double>{0, 0, 1, 1}));
  WriteText(path,
            "# vtk DataFile Version 3.0\nt\nASCII\nDATASET POLYDATA\n"
            "POINTS 2 float\n0 0 0\n1 zz 0\n");
  EXPECT_EQ(InputErrorOf([&] { ReadLegacyVtkPolyData(path); }),
            path + ":7: 'zz' is not a number");
}

// Issue 14: scalars of another count than the points were paired with the
// wrong points, and coordinates past 1e155 overflowed the fit.
TEST(LegacyVtkReaderTest, PointDataMustMatchThePointsAndCoordinatesBeBounded) {
  const std::string path = ScratchDirectory("vtk") + "/m.vtk";
  WriteText(path,
            "# vtk DataFile Version 3.0\nvtk output\nASCII\nDATASET POLYDATA\n"
            "POINTS 3 float\n0 0 0 1 0 0 0 1 0\n"
            "POINT_DATA 2\nSCALARS s float\nLOOKUP_TABLE default\n0 1\n");
  EXPECT_EQ(InputErrorOf([&] { ReadLegacyVtkPolyData(path); }),
            path + ":7: POINT_DATA 2 does not match POINTS 3");
  WriteText(path,
            "# vtk DataFile Version 3.0\nvtk output\nASCII\nDATASET POLYDATA\n"
            "POINTS 2 float\n0 0 0 1e200 0 0\n");
  EXPECT_EQ(InputErrorOf([&] { ReadLegacyVtkPolyData(path); }),
            path +
                ":6: coordinate '1e200' is out of range (more than 1e6 mm "
                "from the origin)");
  // Text with a NUL is not text (binary numbers belong in a BINARY file).
  WriteText(path, std::string("# vtk DataFile Version 3.0\nt\nASCII\n"
                              "DATASET POLYDATA\nPOINTS 1 float\n0 0") +
                      '\0' + "\n");
  EXPECT_EQ(InputErrorOf([&] { ReadLegacyVtkPolyData(path); }),
            path + ":6: contains a NUL byte (not a text file?)");
}

// Big-endian bytes, as binary legacy VTK stores numbers.
std::string BigEndian(std::uint64_t bits, int size) {
  std::string bytes;
  for (int i = size - 1; i >= 0; --i) {
    bytes += static_cast<char>(bits >> (8 * i));
  }
  return bytes;
}
// IEEE floats or doubles as their bit patterns.
template <typename Real, typename Bits>
std::string Reals(const std::vector<Real>& values) {
  static_assert(sizeof(Real) == sizeof(Bits));
  std::string bytes;
  for (Real value : values) {
    Bits bits;
    std::memcpy(&bits, &value, sizeof(bits));
    bytes += BigEndian(bits, sizeof(bits));
  }
  return bytes;
}
std::string Floats(const std::vector<float>& values) {
  return Reals<float, std::uint32_t>(values);
}
std::string Doubles(const std::vector<double>& values) {
  return Reals<double, std::uint64_t>(values);
}
std::string Integers(const std::vector<std::int64_t>& values, int size) {
  std::string bytes;
  for (std::int64_t value : values) {
    bytes += BigEndian(static_cast<std::uint64_t>(value), size);
  }
  return bytes;
}

// pfdm's own frames are binary legacy VTK (the fit's default): every double
// comes back exactly, the VERTICES of the data points are passed over and
// the scalars are found by name; the same file as text gives the same mesh
// to its nine digits.
TEST(LegacyVtkReaderTest, BinaryGivesBackWhatPfdmWrote) {
  const VtkPolyData data = SmallPolyData();
  const std::string path = ScratchDirectory("vtk_binary") + "/m.vtk";
  WriteText(path, ToLegacyVtk(data, "pfdm frame 0", VtkFormat::kBinary));
  const VtkMesh vtk = ReadLegacyVtkPolyData(path);
  EXPECT_EQ(vtk.mesh.points, data.points);
  EXPECT_EQ(vtk.mesh.triangles, data.triangles);
  ASSERT_EQ(vtk.point_scalars.size(), 2u);
  EXPECT_EQ(vtk.point_scalars.at("u"), data.point_scalars[0].second);
  EXPECT_EQ(vtk.point_scalars.at("is_data"), data.point_scalars[1].second);
  WriteText(path, ToLegacyVtk(data, "pfdm frame 0", VtkFormat::kAscii));
  const VtkMesh text = ReadLegacyVtkPolyData(path);
  ASSERT_EQ(text.mesh.points.size(), data.points.size());
  for (size_t i = 0; i < data.points.size(); ++i) {
    EXPECT_NEAR((text.mesh.points[i] - data.points[i]).norm(), 0.0, 2e-8) << i;
  }
  EXPECT_EQ(text.mesh.triangles, data.triangles);
}

// pfdm's float precision, binary and text: each point the float nearest the
// double written, is_data (float32 at any precision) exact.
TEST(LegacyVtkReaderTest, FloatPrecisionGivesBackTheNearestFloats) {
  VtkPolyData data;
  data.points = {{0.1, -2.5, 3e-7}, {1.0 / 3, 4, 5}, {-6, 7.25, 8}};
  data.triangles = {{0, 1, 2}};
  data.point_scalars = {{"u", {0.5, -1, 1.0 / 7}}, {"is_data", {0, 0, 1}}};
  data.float32_scalars = {"is_data"};
  const std::string path = ScratchDirectory("vtk_float") + "/m.vtk";
  for (VtkFormat format : {VtkFormat::kBinary, VtkFormat::kAscii}) {
    const std::string text =
        ToLegacyVtk(data, "pfdm frame 0", format, VtkPrecision::kFloat);
    EXPECT_NE(text.find("POINTS 3 float\n"), std::string::npos);
    EXPECT_NE(text.find("SCALARS is_data float 1"), std::string::npos);
    WriteText(path, text);
    const VtkMesh vtk = ReadLegacyVtkPolyData(path);
    ASSERT_EQ(vtk.mesh.points.size(), 3u);
    // Binary: the float itself; text: its shortest decimal, a double that
    // rounds to the same float.
    const auto as_written = [format](double value) {
      return format == VtkFormat::kBinary ? value
                                          : double{static_cast<float>(value)};
    };
    for (size_t i = 0; i < 3; ++i) {
      for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(as_written(vtk.mesh.points[i][k]),
                  static_cast<float>(data.points[i][k]));
      }
    }
    EXPECT_EQ(as_written(vtk.point_scalars.at("u")[2]),
              static_cast<float>(1.0 / 7));
    EXPECT_EQ(vtk.point_scalars.at("is_data"), (std::vector<double>{0, 0, 1}));
  }
  EXPECT_NE(ToLegacyVtk(data, "t", VtkFormat::kAscii, VtkPrecision::kDouble)
                .find("SCALARS u double 1"),
            std::string::npos);
}

// Other writers' binary files: float points, the classic int cell list,
// unsigned char labels, a colour table; a title naming ASCII, and a binary
// byte that is a line break (10) in the data, change nothing.
TEST(LegacyVtkReaderTest, BinaryOfOtherTypes) {
  const std::string path = ScratchDirectory("vtk_binary") + "/m.vtk";
  WriteText(path,
            "# vtk DataFile Version 3.0\nnot ASCII\nBINARY\n"
            "DATASET POLYDATA\nPOINTS 3 float\n" +
                Floats({0, 0.5f, -1.25f, 10, 0, 0, 0, 10, 2.5f}) +
                "\nPOLYGONS 1 4\n" + Integers({3, 0, 1, 2}, 4) +
                "\nPOINT_DATA 3\nSCALARS label unsigned_char 1\n"
                "LOOKUP_TABLE labels\n" +
                Integers({0, 1, 10}, 1) + "\nLOOKUP_TABLE labels 1\n" +
                Integers({255, 0, 0, 255}, 1) + "\n");
  const VtkMesh vtk = ReadLegacyVtkPolyData(path);
  ASSERT_EQ(vtk.mesh.points.size(), 3u);
  EXPECT_EQ(vtk.mesh.points[0], Eigen::Vector3d(0, 0.5, -1.25));
  EXPECT_EQ(vtk.mesh.points[2], Eigen::Vector3d(0, 10, 2.5));
  EXPECT_EQ(vtk.mesh.triangles, (std::vector<std::array<int, 3>>{{0, 1, 2}}));
  EXPECT_EQ(vtk.point_scalars.at("label"), (std::vector<double>{0, 1, 10}));
}

// VTK 9 writes legacy files as version 5.1: cells as OFFSETS and
// CONNECTIVITY arrays, and METADATA blocks after arrays; as text and as
// binary (vtktypeint64).
TEST(LegacyVtkReaderTest, Version51OffsetsConnectivityAndMetadata) {
  const std::string path = ScratchDirectory("vtk51") + "/m.vtk";
  const std::string metadata =
      "METADATA\nINFORMATION 2\nNAME L2_NORM_RANGE LOCATION vtkDataArray\n"
      "DATA 2 0 1.41421\nNAME L2_NORM_FINITE_RANGE LOCATION vtkDataArray\n"
      "DATA 2 0 1.41421\n\n";
  WriteText(path,
            "# vtk DataFile Version 5.1\nvtk output\nASCII\nDATASET POLYDATA\n"
            "POINTS 4 float\n0 0 0 1 0 0 0 1 0 \n0 0 1 \n" +
                metadata +
                "POLYGONS 3 7\nOFFSETS vtktypeint64\n0 3 7 \n"
                "CONNECTIVITY vtktypeint64\n0 1 2 0 2 3 1 \n"
                "POINT_DATA 4\nSCALARS s float 1\nLOOKUP_TABLE default\n"
                "0 0 1 1 \n");
  VtkMesh vtk = ReadLegacyVtkPolyData(path);
  ASSERT_EQ(vtk.mesh.points.size(), 4u);
  // A triangle and a quad, fanned.
  EXPECT_EQ(vtk.mesh.triangles,
            (std::vector<std::array<int, 3>>{{0, 1, 2}, {0, 2, 3}, {0, 3, 1}}));
  EXPECT_EQ(vtk.point_scalars.at("s"), (std::vector<double>{0, 0, 1, 1}));
  WriteText(path,
            "# vtk DataFile Version 5.1\nvtk output\nBINARY\n"
            "DATASET POLYDATA\nPOINTS 4 double\n" +
                Doubles({0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1}) + "\n" +
                metadata + "POLYGONS 3 7\nOFFSETS vtktypeint64\n" +
                Integers({0, 3, 7}, 8) + "\nCONNECTIVITY vtktypeint64\n" +
                Integers({0, 1, 2, 0, 2, 3, 1}, 8) + "\n");
  vtk = ReadLegacyVtkPolyData(path);
  EXPECT_EQ(vtk.mesh.points[3], Eigen::Vector3d(0, 0, 1));
  EXPECT_EQ(vtk.mesh.triangles,
            (std::vector<std::array<int, 3>>{{0, 1, 2}, {0, 2, 3}, {0, 3, 1}}));
}

// ParaView saves point arrays as FIELD data (each array followed by its
// METADATA), after CELL_DATA; vectors, colours and many-component arrays
// are read past; a one-component array of a value per point is a scalar.
TEST(LegacyVtkReaderTest, FieldArraysAndCellDataBeforePointData) {
  const std::string path = ScratchDirectory("vtk_field") + "/m.vtk";
  const std::string head = "# vtk DataFile Version 5.1\nvtk output\n";
  const std::string cells =
      "POLYGONS 2 3\nOFFSETS vtktypeint64\n0 3\n"
      "CONNECTIVITY vtktypeint64\n0 1 2\n";
  WriteText(path, head +
                      "ASCII\nDATASET POLYDATA\nPOINTS 3 double\n"
                      "0 0 0 1 0 0 0 1 0\n" +
                      cells +
                      "CELL_DATA 1\nSCALARS area double 1\n"
                      "LOOKUP_TABLE default\n0.5\n"
                      "POINT_DATA 3\nVECTORS residual double\n"
                      "1 2 3 4 5 6 7 8 9\nCOLOR_SCALARS c 3\n"
                      "1 0 0 0 1 0 0 0 1\nSCALARS rgb float 3\n"
                      "LOOKUP_TABLE default\n0 0 0 1 1 1 0 1 0\n"
                      "FIELD FieldData 2\nis_data 1 3 double\n0 0 1\n"
                      "METADATA\nINFORMATION 0\n\n"
                      "normal 3 3 float\n0 0 1 0 0 1 0 0 1\n");
  VtkMesh vtk = ReadLegacyVtkPolyData(path);
  ASSERT_EQ(vtk.point_scalars.size(), 1u);
  EXPECT_EQ(vtk.point_scalars.at("is_data"), (std::vector<double>{0, 0, 1}));
  EXPECT_EQ(vtk.mesh.triangles.size(), 1u);
  WriteText(path,
            head + "BINARY\nDATASET POLYDATA\nPOINTS 3 double\n" +
                Doubles({0, 0, 0, 1, 0, 0, 0, 1, 0}) +
                "\nPOLYGONS 2 3\nOFFSETS vtktypeint64\n" + Integers({0, 3}, 8) +
                "\nCONNECTIVITY vtktypeint64\n" + Integers({0, 1, 2}, 8) +
                "\nPOINT_DATA 3\nCOLOR_SCALARS c 4\n" +
                Integers({255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255}, 1) +
                "\nFIELD FieldData 2\nu 1 3 double\n" +
                Doubles({-1.5, 0.25, 1}) +
                "\nMETADATA\nINFORMATION 0\n\nlabel 1 3 int\n" +
                Integers({7, 8, 10}, 4) + "\n");
  vtk = ReadLegacyVtkPolyData(path);
  EXPECT_EQ(vtk.point_scalars.at("u"), (std::vector<double>{-1.5, 0.25, 1}));
  EXPECT_EQ(vtk.point_scalars.at("label"), (std::vector<double>{7, 8, 10}));
}

// Past binary data an error names the byte, where a line number would count
// line breaks that are data.
TEST(LegacyVtkReaderTest, BinaryErrorsNameTheByte) {
  const std::string path = ScratchDirectory("vtk_binary_bad") + "/m.vtk";
  const std::string head =
      "# vtk DataFile Version 3.0\nt\nBINARY\nDATASET POLYDATA\n";
  const std::string points = "POINTS 2 double\n";
  const size_t data = head.size() + points.size();
  WriteText(path, head + points + Doubles({1, 2, 3, 4, 5}));
  EXPECT_EQ(InputErrorOf([&] { ReadLegacyVtkPolyData(path); }),
            path + ": byte " + std::to_string(data) +
                ": the file ends inside the points");
  WriteText(path, head + points +
                      Doubles({1, 2, 3, 4,
                               std::numeric_limits<double>::quiet_NaN(), 6}));
  EXPECT_EQ(
      InputErrorOf([&] { ReadLegacyVtkPolyData(path); }),
      path + ": byte " + std::to_string(data + 32) + ": not a finite number");
  WriteText(path, head + points + Doubles({1, 2, 3, 4, -2e6, 6}));
  EXPECT_EQ(InputErrorOf([&] { ReadLegacyVtkPolyData(path); }),
            path + ": byte " + std::to_string(data + 32) +
                ": coordinate '-2000000' is out of range (more than 1e6 mm "
                "from the origin)");
  WriteText(path, head + points + Doubles({1, 2, 3, 4, 5, 6}) +
                      "\nPOINT_DATA 2\nSCALARS s long 1\nLOOKUP_TABLE t\n" +
                      Integers({1, 2}, 8));
  EXPECT_EQ(InputErrorOf([&] { ReadLegacyVtkPolyData(path); }),
            path + ": byte " + std::to_string(data + 72) +
                ": binary 'long' has the size of the writer's platform; "
                "write the file as ASCII or with vtktypeint64");
  // An index past 2^53 (fuzzing: its conversion was undefined).
  const std::string polygons = "\nPOLYGONS 2 3\nOFFSETS vtktypeint64\n";
  WriteText(path,
            head + points + Doubles({1, 2, 3, 4, 5, 6}) + polygons +
                Integers({0, 3}, 8) + "\nCONNECTIVITY vtktypeint64\n" +
                Integers({0, 1, std::numeric_limits<std::int64_t>::max()}, 8));
  EXPECT_EQ(InputErrorOf([&] { ReadLegacyVtkPolyData(path); }),
            path + ": byte " +
                std::to_string(data + 48 + polygons.size() + 16 + 27 + 16) +
                ": integer 9223372036854775808.000000 is out of range");
  WriteText(path, "# vtk DataFile Version 3.0\nt\nXML\n");
  EXPECT_EQ(InputErrorOf([&] { ReadLegacyVtkPolyData(path); }),
            path + ":3: 'XML' where ASCII or BINARY belongs");
  WriteText(path, head + "POINTS 99999 float\n" + Floats({1, 2, 3}));
  EXPECT_EQ(InputErrorOf([&] { ReadLegacyVtkPolyData(path); }),
            path + ":5: 99999 is not the point count of a file of " +
                std::to_string(head.size() + 19 + 12) + " bytes");
}

}  // namespace
}  // namespace pfdm
