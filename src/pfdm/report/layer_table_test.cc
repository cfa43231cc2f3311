#include "pfdm/report/layer_table.h"

#include <cmath>
#include <string>

#include "gtest/gtest.h"

namespace pfdm {
namespace {

int Count(const std::string& text, const std::string& what) {
  int count = 0;
  for (size_t at = text.find(what); at != std::string::npos;
       at = text.find(what, at + 1)) {
    ++count;
  }
  return count;
}

// ES is frame 1: segment 8's numbers, n/a where not measured, a row per
// segment and nothing without a wall.
TEST(LayerTableTest, OneRowPerSegmentAtEsNotMeasuredIsNa) {
  FitAnalysis analysis;
  analysis.regions = Regions(RegionLayout());
  analysis.ejection_fraction.es_frame = 1;
  analysis.region_layers.assign(2, std::vector<RegionLayers>(17));
  RegionLayers& mid2 = analysis.region_layers[1][7];
  mid2.layers[0] = {-24.46, -16.04, std::nan("")};
  mid2.layers[2] = {-6.5, -13.0, 85.26};
  mid2.err_percent = 46.34;
  const std::string html = LayerTableHtml(analysis);
  EXPECT_NE(html.find("Strain per layer at ES (frame 1)"), std::string::npos);
  EXPECT_EQ(Count(html, "<tr><td>"), 17);
  const size_t row = html.find("<tr><td>8</td>");
  ASSERT_NE(row, std::string::npos);
  const std::string line = html.substr(row, html.find("</tr>", row) - row);
  EXPECT_NE(line.find("mid 2"), std::string::npos);
  EXPECT_NE(line.find(">-24.5<"), std::string::npos);
  EXPECT_NE(line.find(">-16.0<"), std::string::npos);
  EXPECT_NE(line.find(">n/a<"), std::string::npos);
  EXPECT_NE(line.find(">85.3<"), std::string::npos);
  EXPECT_NE(line.find(">46.3<"), std::string::npos);
  analysis.region_layers.clear();
  EXPECT_EQ(LayerTableHtml(analysis), "");
}

}  // namespace
}  // namespace pfdm
