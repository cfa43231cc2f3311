#include "pfdm/io/not_measured_json.h"

#include "gtest/gtest.h"

namespace pfdm {
namespace {

// Every number measured: no section.  Contour frames list themselves; data
// that stop above the apex list the levels they leave out, and whether
// they are shown anyway.
TEST(NotMeasuredJsonTest, ListsWhatIsNullAndWhy) {
  FitAnalysis analysis;
  analysis.rotation_measured = {true, true, true};
  EXPECT_TRUE(NotMeasured(analysis).is_null());

  analysis.rotation_measured = {true, false, true};
  nlohmann::ordered_json section = NotMeasured(analysis);
  EXPECT_EQ(section["frames"], nlohmann::ordered_json({1}));
  EXPECT_FALSE(section.contains("extrapolated"));

  analysis.rotation_measured = {true, true, true};
  analysis.level_extrapolated = {false, false, true, true};
  analysis.apex_ring_extrapolated = true;
  section = NotMeasured(analysis);
  EXPECT_FALSE(section.contains("frames"));
  EXPECT_EQ(section["extrapolated"]["levels"],
            nlohmann::ordered_json({"apical", "apex cap"}));
  EXPECT_TRUE(section["extrapolated"]["apex_ring"].get<bool>());
  EXPECT_FALSE(section["extrapolated"]["shown"].get<bool>());
  EXPECT_NE(section["extrapolated"]["definition"].get<std::string>().find(
                "--extrapolated"),
            std::string::npos);
}

// Frames without a volume (FitAnalysis::volume_measured) are listed under
// short_span, beside the rest.
TEST(NotMeasuredJsonTest, ListsTheFramesWithoutAVolume) {
  FitAnalysis analysis;
  analysis.rotation_measured = {true, true, true};
  analysis.volume_measured = {true, true, true};
  EXPECT_TRUE(NotMeasured(analysis).is_null());

  analysis.volume_measured = {true, true, false};
  nlohmann::ordered_json section = NotMeasured(analysis);
  EXPECT_FALSE(section.contains("frames"));
  EXPECT_EQ(section["short_span"]["frames"], nlohmann::ordered_json({2}));
  EXPECT_NE(section["short_span"]["definition"].get<std::string>().find(
                "esv_ml and ratio"),
            std::string::npos);

  analysis.rotation_measured = {false, false, false};
  section = NotMeasured(analysis);
  EXPECT_EQ(section["frames"], nlohmann::ordered_json({0, 1, 2}));
  EXPECT_EQ(section["short_span"]["frames"], nlohmann::ordered_json({2}));
}

// Frames where nothing places a solid's walls (FitAnalysis::
// walls_measured) are listed under walls_unseen, apart from short_span.
TEST(NotMeasuredJsonTest, ListsTheFramesWithoutWalls) {
  FitAnalysis analysis;
  analysis.rotation_measured = {true, true, true, true};
  analysis.volume_measured = {true, true, true, true};
  analysis.walls_measured = {true, false, false, true};
  const nlohmann::ordered_json section = NotMeasured(analysis);
  EXPECT_FALSE(section.contains("short_span"));
  EXPECT_EQ(section["walls_unseen"]["frames"], nlohmann::ordered_json({1, 2}));
  EXPECT_NE(section["walls_unseen"]["definition"].get<std::string>().find(
                "walls_unseen"),
            std::string::npos);
}

}  // namespace
}  // namespace pfdm
