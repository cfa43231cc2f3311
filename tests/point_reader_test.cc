#include "pfdm/point_reader.h"

#include "gtest/gtest.h"
#include "pfdm/error.h"
#include "test_util.h"

namespace pfdm {
namespace {

std::string CsvFile(const std::string& text) {
  const std::string path = ScratchDirectory("reader") + "/points.csv";
  WriteText(path, text);
  return path;
}

std::string ErrorOf(const std::string& text) {
  const std::string path = CsvFile(text);
  try {
    ReadPointsCsv(path);
  } catch (const InputError& error) {
    std::string message = error.what();
    return message.substr(message.find("points.csv"));
  }
  return "no error";
}

TEST(PointReaderTest, ReadsFramesIdsAndCoordinatesInAnyColumnOrder) {
  const PointSequence sequence = ReadPointsCsv(CsvFile(
      "id,x,y,z,frame,note\n"
      "7,1.5,-2,3e1,1,a\n"
      "7,1,2,3,0,b\n"
      "8,4,5,6,0,c\n"));
  ASSERT_EQ(sequence.frames.size(), 2u);
  EXPECT_EQ(sequence.frames[0].index, 0);
  ASSERT_EQ(sequence.frames[0].points.size(), 2u);
  EXPECT_EQ(sequence.frames[0].points[1].id, 8);
  EXPECT_EQ(sequence.frames[1].points[0].position, Eigen::Vector3d(1.5, -2, 30));
}

TEST(PointReaderTest, BadInputNamesTheFileAndLine) {
  EXPECT_EQ(ErrorOf("frame,id,x,y\n0,1,2,3\n"), "points.csv: missing column 'z'");
  EXPECT_EQ(ErrorOf("frame,id,x,y,z\n0,1,2,3,4\n0,2,nan,3,4\n"),
            "points.csv:3: column 'x' is not a finite number");
  EXPECT_EQ(ErrorOf("frame,id,x,y,z\n0,1,2,3,4\n0,2,abc,3,4\n"),
            "points.csv:3: column 'x' is not a number: 'abc'");
  EXPECT_EQ(ErrorOf("frame,id,x,y,z\n0,1,2,3\n"), "points.csv:2: too few columns");
  EXPECT_EQ(ErrorOf("frame,id,x,y,z\n0,1,2,3,4\n2,1,2,3,4\n"),
            "points.csv: frame 1 has no points");
  EXPECT_EQ(ErrorOf("frame,id,x,y,z\n0,1,2,3,4\n0,1,2,3,5\n"),
            "points.csv:3: id 1 appears twice in frame 0");
  EXPECT_EQ(ErrorOf("frame,id,x,y,z\n-1,1,2,3,4\n"),
            "points.csv:2: negative frame -1");
  EXPECT_EQ(ErrorOf("frame,id,x,y,z\n"), "points.csv: no points");
  EXPECT_EQ(ErrorOf(""), "points.csv: empty file, no header");
}

TEST(PointReaderTest, MissingFileIsReported) {
  try {
    ReadPointsCsv("/nonexistent/tags.csv");
    FAIL();
  } catch (const InputError& error) {
    EXPECT_STREQ(error.what(), "/nonexistent/tags.csv: cannot open the file");
  }
}

TEST(PointReaderTest, GpFilesKeepTheChosenContoursAsUntrackedPoints) {
  const std::string dir = ScratchDirectory("gp");
  const std::string header = "x\ty\tz\tcontour type\tframeID\tweight\ttime frame\n";
  WriteText(dir + "/GPFile_000.txt",
            header + "1\t2\t3\tSAX_LV_ENDOCARDIAL\t2\t1.0\t0\n"
                     "4\t5\t6\tSAX_RV_FREEWALL\t2\t1.0\t0\n"
                     "7\t8\t9\tLAX_LV_ENDOCARDIAL\t9\t1.0\t1.0\n");
  WriteText(dir + "/GPFile_001.txt",
            header + "1\t2\t4\tSAX_LV_ENDOCARDIAL\t2\t1.0\t1\n");
  const PointSequence sequence =
      ReadGpFiles(dir, ExpandContourAlias("lv-endo"));
  ASSERT_EQ(sequence.frames.size(), 2u);
  ASSERT_EQ(sequence.frames[0].points.size(), 2u);
  EXPECT_EQ(sequence.frames[0].points[1].position, Eigen::Vector3d(7, 8, 9));
  EXPECT_NE(sequence.frames[1].points[0].id, sequence.frames[0].points[0].id);
  try {
    ReadGpFiles(dir, {"APEX_POINT"});
    FAIL();
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()),
              dir + "/GPFile_000.txt: frame 0: no points of contour types "
                    "APEX_POINT");
  }
}

TEST(PointReaderTest, ContourAliasesExpand) {
  EXPECT_EQ(ExpandContourAlias("lv-epi,APEX_POINT"),
            (std::vector<std::string>{"SAX_LV_EPICARDIAL", "LAX_LV_EPICARDIAL",
                                      "APEX_POINT"}));
}

TEST(PointReaderTest, ReadsTheBivMePatient) {
  const std::string shared = SharedDataDirectory();
  if (shared.empty()) GTEST_SKIP() << "../shared/data is absent";
  const PointSequence sequence = ReadGpFiles(
      shared + "/biv-me-patient1/guidepoints", ExpandContourAlias("lv-endo"));
  ASSERT_EQ(sequence.frames.size(), 25u);
  for (const Frame& frame : sequence.frames) EXPECT_GT(frame.points.size(), 100u);
}

}  // namespace
}  // namespace pfdm
