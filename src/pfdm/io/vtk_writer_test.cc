#include "pfdm/io/vtk_writer.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

#include "gtest/gtest.h"
#include "pfdm/util/error.h"

namespace pfdm {
namespace {

// The output as whitespace-separated tokens after the two free-text lines.
struct ParsedVtk {
  std::string version, title;
  std::vector<std::string> words;

  // Index of the token after the first `key`.
  size_t After(const std::string& key) const {
    const auto it = std::find(words.begin(), words.end(), key);
    EXPECT_NE(it, words.end()) << key;
    return static_cast<size_t>(it - words.begin()) + 1;
  }
  bool Has(const std::string& key) const {
    return std::find(words.begin(), words.end(), key) != words.end();
  }
  std::vector<double> Numbers(const std::string& key, size_t skip,
                              size_t count) const {
    std::vector<double> values;
    for (size_t i = After(key) + skip; i < After(key) + skip + count; ++i) {
      values.push_back(std::stod(words.at(i)));
    }
    return values;
  }
};

ParsedVtk Parse(const std::string& text) {
  ParsedVtk parsed;
  std::istringstream in(text);
  std::getline(in, parsed.version);
  std::getline(in, parsed.title);
  std::string word;
  while (in >> word) parsed.words.push_back(word);
  return parsed;
}

VtkPolyData Sample() {
  VtkPolyData data;
  data.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.5, 0.25, -2}};
  data.triangles = {{0, 1, 2}, {1, 2, 3}};
  data.vertices = {3};
  data.point_scalars = {{"u", {0.1, 0.2, 0.3, 0.4}}, {"is_data", {0, 0, 0, 1}}};
  data.point_vectors = {
      {"residual", {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}, {1, -2, 3}}}};
  return data;
}

TEST(VtkWriterTest, WritesHeaderPointsCellsAndPointData) {
  const ParsedVtk vtk = Parse(ToLegacyVtk(Sample(), "pfdm frame_003"));
  EXPECT_EQ(vtk.version, "# vtk DataFile Version 3.0");
  EXPECT_EQ(vtk.title, "pfdm frame_003");
  EXPECT_EQ(vtk.words[0], "ASCII");
  EXPECT_EQ(vtk.words[vtk.After("DATASET")], "POLYDATA");
  EXPECT_EQ(vtk.words[vtk.After("POINTS")], "4");
  EXPECT_EQ(vtk.words[vtk.After("POINTS") + 1], "double");
  EXPECT_EQ(vtk.Numbers("POINTS", 2, 12),
            (std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0.5, 0.25, -2}));
  // VERTICES count, list size (1 + index per cell), then the cells.
  EXPECT_EQ(vtk.Numbers("VERTICES", 0, 4), (std::vector<double>{1, 2, 1, 3}));
  EXPECT_EQ(vtk.Numbers("POLYGONS", 0, 10),
            (std::vector<double>{2, 8, 3, 0, 1, 2, 3, 1, 2, 3}));
  EXPECT_EQ(vtk.words[vtk.After("POINT_DATA")], "4");
  EXPECT_EQ(vtk.words[vtk.After("SCALARS")], "u");
  EXPECT_EQ(vtk.words[vtk.After("u")], "double");
  EXPECT_EQ(vtk.words[vtk.After("u") + 1], "1");
  EXPECT_EQ(vtk.words[vtk.After("LOOKUP_TABLE")], "default");
  EXPECT_EQ(vtk.Numbers("u", 4, 4), (std::vector<double>{0.1, 0.2, 0.3, 0.4}));
  EXPECT_EQ(vtk.Numbers("is_data", 4, 4), (std::vector<double>{0, 0, 0, 1}));
  EXPECT_EQ(vtk.words[vtk.After("VECTORS")], "residual");
  EXPECT_EQ(vtk.words[vtk.After("residual")], "double");
  EXPECT_EQ(vtk.Numbers("residual", 1, 12),
            (std::vector<double>{0, 0, 0, 0, 0, 0, 0, 0, 0, 1, -2, 3}));
  EXPECT_EQ(vtk.words.size(), vtk.After("residual") + 13);
}

TEST(VtkWriterTest, WritesNineSignificantDigits) {
  VtkPolyData data;
  data.points = {{1.0 / 3.0, -123456.789012, 1e-20}};
  data.point_scalars = {{"s", {2.0 / 3.0}}};
  const ParsedVtk vtk = Parse(ToLegacyVtk(data, "t"));
  EXPECT_EQ(vtk.words[vtk.After("POINTS") + 2], "0.333333333");
  EXPECT_EQ(vtk.words[vtk.After("POINTS") + 3], "-123456.789");
  EXPECT_EQ(vtk.words[vtk.After("POINTS") + 4], "1e-20");
  EXPECT_EQ(vtk.words.back(), "0.666666667");
}

TEST(VtkWriterTest, NumbersAreFormattedAsPrintfWould) {
  // The files' text did not change when the writers left std::ostream:
  // every value as %.9g, every index as %d.
  const std::vector<double> values = {
      0.0,      -0.0, 1.0,       -2.5,         0.1,        1.0 / 3,      1e-5,
      -1.25e-7, 1e20, 123456789, 1234567890.5, M_PI * 100, -42.000000001};
  for (double value : values) {
    char expected[32];
    std::snprintf(expected, sizeof(expected), "%.9g", value);
    std::string text;
    AppendVtkNumber(value, &text);
    EXPECT_EQ(text, expected) << value;
  }
  for (int value : {0, 7, -3, 2147483647}) {
    std::string text;
    AppendVtkNumber(value, &text);
    EXPECT_EQ(text, std::to_string(value));
  }
}

TEST(VtkWriterTest, LeavesOutEmptySections) {
  VtkPolyData data;
  data.points = {{1, 2, 3}};
  const ParsedVtk vtk = Parse(ToLegacyVtk(data, "points only"));
  EXPECT_FALSE(vtk.Has("VERTICES"));
  EXPECT_FALSE(vtk.Has("POLYGONS"));
  EXPECT_FALSE(vtk.Has("POINT_DATA"));
  EXPECT_EQ(vtk.words,
            (std::vector<std::string>{"ASCII", "DATASET", "POLYDATA", "POINTS",
                                      "1", "double", "1", "2", "3"}));
}

// The legacy BINARY form: each section's header line, then its numbers
// big-endian (doubles, int32 cells), then a newline.
class BigEndianReader {
 public:
  BigEndianReader(const std::string& text, size_t at) : text_(text), at_(at) {}
  double Double() {
    std::uint64_t bits = 0;
    for (int i = 0; i < 8; ++i) {
      bits = (bits << 8) | static_cast<unsigned char>(text_.at(at_++));
    }
    double value;
    std::memcpy(&value, &bits, sizeof(value));
    return value;
  }
  int Int() {
    std::uint32_t bits = 0;
    for (int i = 0; i < 4; ++i) {
      bits = (bits << 8) | static_cast<unsigned char>(text_.at(at_++));
    }
    return static_cast<int>(bits);
  }
  size_t at() const { return at_; }
  void Skip(size_t count) { at_ += count; }

 private:
  const std::string& text_;
  size_t at_;
};

TEST(VtkWriterTest, BinaryReadsBackExactly) {
  VtkPolyData data = Sample();
  data.points[1] = {1.0 / 3.0, -0.0, 1e-300};
  const std::string vtk =
      ToLegacyVtk(data, "pfdm frame_003", VtkFormat::kBinary);
  const std::string head =
      "# vtk DataFile Version 3.0\npfdm frame_003\nBINARY\nDATASET "
      "POLYDATA\nPOINTS 4 double\n";
  ASSERT_EQ(vtk.substr(0, head.size()), head);
  BigEndianReader in(vtk, head.size());
  for (const Eigen::Vector3d& p : data.points) {
    for (int k = 0; k < 3; ++k) EXPECT_EQ(in.Double(), p[k]);
  }
  auto expect_line = [&](const std::string& line) {
    ASSERT_EQ(vtk.substr(in.at(), line.size()), line);
    in.Skip(line.size());
  };
  expect_line("\nVERTICES 1 2\n");
  EXPECT_EQ(in.Int(), 1);
  EXPECT_EQ(in.Int(), 3);
  expect_line("\nPOLYGONS 2 8\n");
  for (int expected : {3, 0, 1, 2, 3, 1, 2, 3}) EXPECT_EQ(in.Int(), expected);
  expect_line("\nPOINT_DATA 4\nSCALARS u double 1\nLOOKUP_TABLE default\n");
  for (double expected : {0.1, 0.2, 0.3, 0.4}) EXPECT_EQ(in.Double(), expected);
  expect_line("\nSCALARS is_data double 1\nLOOKUP_TABLE default\n");
  for (double expected : {0, 0, 0, 1}) EXPECT_EQ(in.Double(), expected);
  expect_line("\nVECTORS residual double\n");
  for (double expected : {0, 0, 0, 0, 0, 0, 0, 0, 0, 1, -2, 3}) {
    EXPECT_EQ(in.Double(), expected);
  }
  EXPECT_EQ(in.at() + 1, vtk.size());
  EXPECT_EQ(vtk.back(), '\n');
}

TEST(VtkWriterTest, FormatsByName) {
  EXPECT_EQ(VtkFormatFromName("ascii"), VtkFormat::kAscii);
  EXPECT_EQ(VtkFormatFromName("binary"), VtkFormat::kBinary);
  try {
    VtkFormatFromName("base64");
    ADD_FAILURE() << "no error";
  } catch (const InputError& error) {
    EXPECT_STREQ(error.what(),
                 "unknown --vtk_format 'base64' (expected ascii or binary)");
  }
}

TEST(VtkWriterDeathTest, MismatchedArraysAndBadIndicesAreProgrammingErrors) {
  VtkPolyData data = Sample();
  data.point_scalars[0].second.pop_back();
  EXPECT_DEATH(ToLegacyVtk(data, "t"), "u");
  data = Sample();
  data.point_vectors[0].second.push_back(Eigen::Vector3d::Zero());
  EXPECT_DEATH(ToLegacyVtk(data, "t"), "residual");
  data = Sample();
  data.triangles.push_back({0, 1, 4});
  EXPECT_DEATH(ToLegacyVtk(data, "t"), "Check failed");
  data = Sample();
  data.vertices.push_back(-1);
  EXPECT_DEATH(ToLegacyVtk(data, "t"), "Check failed");
  data = Sample();
  data.point_scalars[0].first = "two words";
  EXPECT_DEATH(ToLegacyVtk(data, "t"), "two words");
  EXPECT_DEATH(ToLegacyVtk(Sample(), "two\nlines"), "Check failed");
}

}  // namespace
}  // namespace pfdm
