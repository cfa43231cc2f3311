#include "pfdm/vtk_writer.h"

#include <sstream>

#include "gtest/gtest.h"

namespace pfdm {
namespace {

TEST(VtkWriterTest, WritesPointsCellsAndPointData) {
  VtkPolyData data;
  data.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.5, 0.25, 2}};
  data.triangles = {{0, 1, 2}};
  data.vertices = {3};
  data.point_scalars = {{"u", {0.1, 0.2, 0.3, 0.4}}};
  data.point_vectors = {{"residual", {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}, {1, 2, 3}}}};
  std::istringstream in(ToLegacyVtk(data, "title"));
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "# vtk DataFile Version 3.0");
  std::getline(in, line);
  EXPECT_EQ(line, "title");
  std::string word;
  std::vector<std::string> words;
  while (in >> word) words.push_back(word);
  auto at = [&](const std::string& key) {
    return std::find(words.begin(), words.end(), key) - words.begin();
  };
  EXPECT_EQ(words[at("POINTS") + 1], "4");
  EXPECT_EQ(words[at("POINTS") + 13], "0.25");
  EXPECT_EQ(words[at("VERTICES") + 1], "1");
  EXPECT_EQ(words[at("VERTICES") + 2], "2");
  EXPECT_EQ(words[at("VERTICES") + 4], "3");
  EXPECT_EQ(words[at("POLYGONS") + 1], "1");
  EXPECT_EQ(words[at("POLYGONS") + 2], "4");
  EXPECT_EQ(words[at("POINT_DATA") + 1], "4");
  EXPECT_EQ(words[at("u") + 5], "0.1");
  EXPECT_EQ(words[at("residual") + 11], "1");
  EXPECT_EQ(words.back(), "3");
}

}  // namespace
}  // namespace pfdm
