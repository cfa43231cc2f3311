#include "pfdm/io/point_reader.h"

#include <sys/stat.h>

#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include "gtest/gtest.h"
#include "pfdm/io/point_source.h"
#include "pfdm/testing/test_util.h"
#include "pfdm/util/error.h"

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
  const PointSequence sequence =
      ReadPointsCsv(CsvFile("id,x,y,z,frame,note\n"
                            "7,1.5,-2,3e1,1,a\n"
                            "7,1,2,3,0,b\n"
                            "8,4,5,6,0,c\n"));
  ASSERT_EQ(sequence.frames.size(), 2u);
  EXPECT_EQ(sequence.frames[0].index, 0);
  ASSERT_EQ(sequence.frames[0].points.size(), 2u);
  EXPECT_EQ(sequence.frames[0].points[1].id, 8);
  EXPECT_EQ(sequence.frames[1].points[0].position,
            Eigen::Vector3d(1.5, -2, 30));
}

// Blank lines, a trailing one or between frames, are skipped; error line
// numbers still count them.
TEST(PointReaderTest, SkipsBlankLines) {
  const PointSequence sequence =
      ReadPointsCsv(CsvFile("frame,id,x,y,z\n0,1,2,3,4\n\n  \n1,1,5,6,7\n\n"));
  ASSERT_EQ(sequence.frames.size(), 2u);
  EXPECT_EQ(sequence.frames[1].points[0].position, Eigen::Vector3d(5, 6, 7));
  EXPECT_EQ(ErrorOf("frame,id,x,y,z\n\n0,1,2,3,nan\n"),
            "points.csv:3: column 'z' is not a finite number");
}

TEST(PointReaderTest, BadInputNamesTheFileAndLine) {
  EXPECT_EQ(ErrorOf("frame,id,x,y\n0,1,2,3\n"),
            "points.csv: missing column 'z'");
  EXPECT_EQ(ErrorOf("frame,id,x,y,z\n0,1,2,3,4\n0,2,nan,3,4\n"),
            "points.csv:3: column 'x' is not a finite number");
  EXPECT_EQ(ErrorOf("frame,id,x,y,z\n0,1,2,3,4\n0,2,abc,3,4\n"),
            "points.csv:3: column 'x' is not a number: 'abc'");
  EXPECT_EQ(ErrorOf("frame,id,x,y,z\n0,1,2,3\n"),
            "points.csv:2: too few columns");
  EXPECT_EQ(ErrorOf("frame,id,x,y,z\n0,1,2,3,4\n2,1,2,3,4\n"),
            "points.csv: frame 1 has no points");
  EXPECT_EQ(ErrorOf("frame,id,x,y,z\n0,1,2,3,4\n0,1,2,3,5\n"),
            "points.csv:3: id 1 appears twice in frame 0");
  // Repeats are found once the file is read: the first line that repeats
  // an id is named, whichever frame, whichever order the ids came in.
  EXPECT_EQ(ErrorOf("frame,id,x,y,z\n0,7,2,3,4\n1,5,2,3,4\n0,2,2,3,4\n"
                    "1,5,2,3,5\n0,7,2,3,5\n0,2,1,1,1\n1,5,0,0,0\n"),
            "points.csv:5: id 5 appears twice in frame 1");
  EXPECT_EQ(ErrorOf("frame,id,x,y,z\n0,9,2,3,4\n0,3,2,3,4\n0,3,1,1,1\n"
                    "0,9,0,0,0\n"),
            "points.csv:4: id 3 appears twice in frame 0");
  EXPECT_EQ(ErrorOf("frame,id,x,y,z\n-1,1,2,3,4\n"),
            "points.csv:2: negative frame -1");
  EXPECT_EQ(ErrorOf("frame,id,x,y,z\n0,1,inf,3,4\n"),
            "points.csv:2: column 'x' is not a finite number");
  EXPECT_EQ(ErrorOf("frame,id,x,y,z\n0,1,2,3,1e999\n"),
            "points.csv:2: column 'z' is out of range: '1e999'");
  EXPECT_EQ(ErrorOf("frame,id,x,y,z\n0,1,2,,4\n"),
            "points.csv:2: column 'y' is not a number: ''");
  EXPECT_EQ(ErrorOf("frame,id,x,y,z\none,1,2,3,4\n"),
            "points.csv:2: column 'frame' is not a number: 'one'");
  EXPECT_EQ(ErrorOf("frame,id,x,y,z\n0.5,1,2,3,4\n"),
            "points.csv:2: column 'frame' is not a number: '0.5'");
  EXPECT_EQ(ErrorOf("frame,id,x,y,z\n0,99999999999999999999,2,3,4\n"),
            "points.csv:2: column 'id' is out of range");
  EXPECT_EQ(ErrorOf("frame,id,x,y,z\n0,1,2,3,4,5\n"),
            "points.csv:2: too many columns");
  EXPECT_EQ(ErrorOf("frame,id,x,y,z\n0,1,\"2,3,4\n"),
            "points.csv:2: a quoted field is not closed");
  EXPECT_EQ(ErrorOf("frame,id,x,x,y,z\n0,1,2,3,4,5\n"),
            "points.csv: column 'x' appears twice");
  EXPECT_EQ(ErrorOf("frame,id,x,y,z\n"), "points.csv: no points");
  EXPECT_EQ(ErrorOf(""), "points.csv: empty file, no header");
}

TEST(PointReaderTest, NumbersReadBackExactlyWithSignsAndCrLf) {
  const PointSequence sequence =
      ReadPointsCsv(CsvFile("frame,id,x,y,z\r\n"
                            "0,-3,+0.1,-1e-3,0.30000000000000004\r\n"));
  ASSERT_EQ(sequence.frames.size(), 1u);
  const DataPoint& point = sequence.frames[0].points[0];
  EXPECT_EQ(point.id, -3);
  EXPECT_EQ(point.position.x(), 0.1);
  EXPECT_EQ(point.position.y(), -1e-3);
  EXPECT_EQ(point.position.z(), 0.1 + 0.2);
}

TEST(PointReaderTest, MissingFileOrFolderIsReported) {
  try {
    ReadPointsCsv("/nonexistent/tags.csv");
    FAIL();
  } catch (const InputError& error) {
    EXPECT_STREQ(error.what(), "/nonexistent/tags.csv: cannot open the file");
  }
  const std::string dir = ScratchDirectory("folder");
  try {
    ReadPointsCsv(dir);
    FAIL();
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()), dir + ": is a folder, not a file");
  }
}

// Issue 14: 1e308 aborted the fit through a Ceres CHECK, a NUL byte cut its
// row short silently, and a 5 MB field came back in a 5 MB error line.
TEST(PointReaderTest, HugeCoordinatesNulBytesAndLongFieldsAreOneLineErrors) {
  EXPECT_EQ(ErrorOf("frame,id,x,y,z\n0,1,1e308,3,4\n"),
            "points.csv:2: column 'x' is out of range: '1e308' (more than "
            "1e6 mm from the origin)");
  EXPECT_EQ(ErrorOf("frame,id,x,y,z\n0,1,2,3,-1000001\n"),
            "points.csv:2: column 'z' is out of range: '-1000001' (more than "
            "1e6 mm from the origin)");
  // Read as 0,2,2,3,4 before: the 9 after the NUL was silently lost.
  EXPECT_EQ(ErrorOf(std::string("frame,id,x,y,z\n0,1,2,3,4\n0,2,2,3,4") + '\0' +
                    "9\n"),
            "points.csv:3: contains a NUL byte (not a text file?)");
  const std::string field(5 << 20, '7');
  EXPECT_EQ(ErrorOf("frame,id,x,y,z\n0,1,2,3,4\n0,2,x" + field + ",3,4\n"),
            "points.csv:3: column 'x' is not a number: 'x" +
                std::string(39, '7') + "...'");
}

TEST(PointReaderTest, AFifoIsRefusedRatherThanWaitedOn) {
  const std::string path = ScratchDirectory("fifo") + "/tags.csv";
  ASSERT_EQ(mkfifo(path.c_str(), 0600), 0);
  try {
    ReadPoints(path, "auto", "");
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()),
              path + ": is not a regular file (a FIFO, socket or device?)");
  }
  const std::string gp = ScratchDirectory("fifo") + "/GPFile_000.txt";
  ASSERT_EQ(mkfifo(gp.c_str(), 0600), 0);
  EXPECT_THROW(ReadPoints(gp, "auto", ""), InputError);
}

TEST(PointReaderTest, GpFilesKeepTheChosenContoursAsUntrackedPoints) {
  const std::string dir = ScratchDirectory("gp");
  const std::string header =
      "x\ty\tz\tcontour type\tframeID\tweight\ttime frame\n";
  WriteText(dir + "/GPFile_000.txt",
            header +
                "1\t2\t3\tSAX_LV_ENDOCARDIAL\t2\t1.0\t0\n"
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
  EXPECT_EQ(sequence.contour_types, ExpandContourAlias("lv-endo"));
  try {
    ReadGpFiles(dir, {"APEX_POINT"});
    FAIL();
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()),
              dir + ": no points of contour types APEX_POINT");
  }
}

std::string GpErrorOf(const std::string& path,
                      const std::vector<std::string>& types) {
  try {
    ReadGpFiles(path, types);
  } catch (const InputError& error) {
    return error.what();
  }
  return "no error";
}

TEST(PointReaderTest, GpFileAloneIsOneFrameAndAnEmptyFilterKeepsAll) {
  const std::string path = ScratchDirectory("gp1") + "/GPFile_007.txt";
  WriteText(path,
            "x\ty\tz\tcontour type\tframeID\tweight\ttime frame\n"
            "1.25\t2\t3\tSAX_LV_ENDOCARDIAL\t2\t1.0\t7\n"
            "4\t5\t6\tAPEX_POINT\t9\t1.0\t1.0\n\n");  // Blank line.
  const PointSequence sequence = ReadGpFiles(path, {});
  EXPECT_EQ(sequence.source, path);
  ASSERT_EQ(sequence.frames.size(), 1u);
  EXPECT_EQ(sequence.frames[0].index, 0);
  ASSERT_EQ(sequence.frames[0].points.size(), 2u);
  EXPECT_EQ(sequence.frames[0].points[0].id, 0);
  EXPECT_EQ(sequence.frames[0].points[0].position, Eigen::Vector3d(1.25, 2, 3));
  EXPECT_EQ(sequence.frames[0].points[1].id, 1);
}

TEST(PointReaderTest, GpFileErrorsNameTheFileAndLineOrFrame) {
  const std::string dir = ScratchDirectory("gperr");
  const std::string header =
      "x\ty\tz\tcontour type\tframeID\tweight\ttime frame\n";
  WriteText(dir + "/GPFile_000.txt",
            header + "1\t2\t3\tSAX_LV_ENDOCARDIAL\t2\t1.0\t0\n");
  WriteText(dir + "/GPFile_001.txt",
            header + "1\t2\t3\tSAX_RV_SEPTUM\t2\t1.0\t1\n");
  WriteText(dir + "/notes.txt", "not a guide-point file");
  EXPECT_EQ(GpErrorOf(dir, {"SAX_LV_ENDOCARDIAL"}),
            dir +
                "/GPFile_001.txt: frame 1: no points of contour types "
                "SAX_LV_ENDOCARDIAL");
  EXPECT_EQ(GpErrorOf(dir, {"APEX_POINT", "RV_INSERT"}),
            dir + ": no points of contour types APEX_POINT,RV_INSERT");
  WriteText(dir + "/GPFile_001.txt",
            header +
                "1\t2\t3\tSAX_RV_SEPTUM\t2\t1.0\t1\n"
                "1\tnan\t3\tSAX_RV_SEPTUM\t2\t1.0\t1\n");
  EXPECT_EQ(GpErrorOf(dir, {}),
            dir + "/GPFile_001.txt:3: column 'y' is not a finite number");
  WriteText(dir + "/GPFile_001.txt", "x\ty\tcontour type\n");
  EXPECT_EQ(GpErrorOf(dir, {}), dir + "/GPFile_001.txt: missing column 'z'");
  const std::string empty = ScratchDirectory("gpempty");
  EXPECT_EQ(GpErrorOf(empty, {}), empty + ": no GPFile_*.txt in this folder");
}

const char kGpHeader[] = "x\ty\tz\tcontour type\tframeID\tweight\ttime frame\n";

// Rows on slices 2 to 5 of `time frame` frame, and biv-me's label 1.0 on
// slice 8 (LAX rows).
std::string GpFrameRows(const std::string& frame) {
  std::string rows;
  for (int slice = 2; slice <= 5; ++slice) {
    rows += std::to_string(slice) + "\t1\t" + frame + "\tSAX_LV_ENDOCARDIAL\t" +
            std::to_string(slice) + "\t1.0\t" + frame + "\n";
  }
  return rows + "7\t8\t9\tLAX_LV_ENDOCARDIAL\t8\t1.0\t1.0\n";
}

// Issue 29: three frames' guide points in one file were fitted as one frame
// of 1,500 points.  Not split by the column: biv-me labels one LAX slice's
// rows 1.0 in every frame's file, which would land in frame 1.
TEST(PointReaderTest, GpFileOfSeveralTimeFramesIsRefused) {
  const std::string path = ScratchDirectory("gp3") + "/GPFile_000.txt";
  WriteText(path, kGpHeader + GpFrameRows("5"));
  EXPECT_EQ(GpErrorOf(path, {}), "no error");  // 5 and the label 1.0.
  WriteText(path, kGpHeader + GpFrameRows("1"));
  EXPECT_EQ(GpErrorOf(path, {}), "no error");
  WriteText(path,
            kGpHeader + GpFrameRows("0") + GpFrameRows("1") + GpFrameRows("2"));
  EXPECT_EQ(GpErrorOf(path, {}),
            path +
                ": holds 3 time frames (0, 1, 2 in column 'time frame'); a "
                "GPFile is one frame: give a folder of GPFile_*.txt, one per "
                "frame");
  // The label on a second slice is a frame.
  WriteText(path, kGpHeader + GpFrameRows("5") +
                      "1\t2\t3\tLAX_LV_ENDOCARDIAL\t9\t1.0\t1.0\n");
  EXPECT_EQ(GpErrorOf(path, {}),
            path +
                ": holds 2 time frames (1, 5 in column 'time frame'); a GPFile "
                "is one frame: give a folder of GPFile_*.txt, one per frame");
  std::string many = kGpHeader;
  for (int t = 0; t < 25; ++t) many += GpFrameRows(std::to_string(t));
  WriteText(path, many);
  EXPECT_EQ(GpErrorOf(path, {}),
            path +
                ": holds 25 time frames (0, 1, 2, 3, ..., 24 in column 'time "
                "frame'); a GPFile is one frame: give a folder of "
                "GPFile_*.txt, one per frame");
  // Without frameID the label cannot be told from a frame.
  WriteText(path,
            "x\ty\tz\tcontour type\ttime frame\n"
            "1\t2\t3\tSAX_LV_ENDOCARDIAL\t4\n"
            "1\t2\t4\tLAX_LV_ENDOCARDIAL\t1.0\n");
  EXPECT_EQ(GpErrorOf(path, {}),
            path +
                ": holds 2 time frames (1, 4 in column 'time frame'); a GPFile "
                "is one frame: give a folder of GPFile_*.txt, one per frame");
}

// Issue 29: NaN weights and text in the time frame were accepted.  Rows of
// contour types not kept are checked too.
TEST(PointReaderTest, GpFileWeightsAndTimeFramesAreNumbers) {
  const std::string path = ScratchDirectory("gpcols") + "/GPFile_000.txt";
  struct Case {
    const char* row;
    const char* message;
  };
  const Case cases[] = {
      {"1\t2\t3\tSAX_RV_FREEWALL\t2\tnan\t0\n",
       ":3: column 'weight' is not a finite number"},
      {"1\t2\t3\tSAX_RV_FREEWALL\t2\t-1\t0\n",
       ":3: column 'weight' is negative: '-1'"},
      {"1\t2\t3\tSAX_RV_FREEWALL\t2\theavy\t0\n",
       ":3: column 'weight' is not a number: 'heavy'"},
      {"1\t2\t3\tSAX_LV_ENDOCARDIAL\t2\t1.0\tED\n",
       ":3: column 'time frame' is not a number: 'ED'"},
      {"1\t2\t3\tSAX_LV_ENDOCARDIAL\t2\t1.0\t2.5\n",
       ":3: column 'time frame' is not a frame number (a whole number from "
       "0): '2.5'"},
      {"1\t2\t3\tSAX_LV_ENDOCARDIAL\t2\t1.0\t-1\n",
       ":3: column 'time frame' is not a frame number (a whole number from "
       "0): '-1'"},
  };
  for (const Case& c : cases) {
    WriteText(path, std::string(kGpHeader) +
                        "1\t2\t3\tSAX_LV_ENDOCARDIAL\t2\t1.0\t0\n" + c.row);
    EXPECT_EQ(GpErrorOf(path, ExpandContourAlias("lv-endo")), path + c.message);
  }
  // Only x, y, z and contour type are required.
  WriteText(path, "x\ty\tz\tcontour type\n1\t2\t3\tSAX_LV_ENDOCARDIAL\n");
  EXPECT_EQ(ReadGpFiles(path, {}).frames[0].points.size(), 1u);
}

// Issue 29: one point at 9e5 mm was refused as "the points lie on a line".
TEST(PointReaderTest, APointFarFromTheOthersIsNamedByItsLine) {
  std::string csv = "frame,id,x,y,z\n";
  for (int i = 0; i < 12; ++i) {
    csv += "0," + std::to_string(i) + "," + std::to_string(i % 3) + "," +
           std::to_string(i % 4) + ",7\n";
  }
  // Frame 1: frame 0's points and one more, 900000 mm off their median
  // (1, 1, 7).
  std::string frame1;
  for (int i = 0; i < 12; ++i) {
    frame1 += "1," + std::to_string(i) + "," + std::to_string(i % 3) + "," +
              std::to_string(i % 4) + ",7\n";
  }
  EXPECT_EQ(ErrorOf(csv + frame1 + "1,12,900001,1,7\n"),
            "points.csv:26: frame 1: the point lies 900000 mm from the centre "
            "of the frame's points, beyond any heart (500 mm)");
  EXPECT_EQ(ErrorOf(csv + frame1 + "1,12,401,1,7\n"), "no error");
  const std::string dir = ScratchDirectory("gpfar");
  WriteText(
      dir + "/GPFile_000.txt",
      std::string(kGpHeader) + "1\t2\t3\tSAX_LV_ENDOCARDIAL\t2\t1.0\t0\n");
  WriteText(dir + "/GPFile_001.txt",
            std::string(kGpHeader) +
                "1\t2\t3\tSAX_LV_ENDOCARDIAL\t2\t1.0\t1\n"
                "1\t2\t-900\tSAX_LV_ENDOCARDIAL\t2\t1.0\t1\n"
                "1\t2\t5\tSAX_LV_ENDOCARDIAL\t2\t1.0\t1\n"
                "1\t2\t-9000\tSAX_RV_FREEWALL\t2\t1.0\t1\n");
  EXPECT_EQ(GpErrorOf(dir, ExpandContourAlias("lv-endo")),
            dir +
                "/GPFile_001.txt:3: frame 1: the point lies 903 mm from the "
                "centre of the frame's points, beyond any heart (500 mm)");
  // A point not kept is not fitted: no matter where it lies.
  WriteText(dir + "/GPFile_001.txt",
            std::string(kGpHeader) +
                "1\t2\t3\tSAX_LV_ENDOCARDIAL\t2\t1.0\t1\n"
                "1\t2\t-9000\tSAX_RV_FREEWALL\t2\t1.0\t1\n");
  EXPECT_EQ(GpErrorOf(dir, ExpandContourAlias("lv-endo")), "no error");
}

TEST(PointReaderTest, ContourAliasesExpand) {
  EXPECT_EQ(ExpandContourAlias("lv-epi,APEX_POINT"),
            (std::vector<std::string>{"SAX_LV_EPICARDIAL", "LAX_LV_EPICARDIAL",
                                      "APEX_POINT"}));
  EXPECT_EQ(ExpandContourAlias("lv-endo,,LAX_LA"),
            (std::vector<std::string>{"SAX_LV_ENDOCARDIAL",
                                      "LAX_LV_ENDOCARDIAL", "LAX_LA"}));
  EXPECT_EQ(ExpandContourAlias("lv-cavity"),
            (std::vector<std::string>{"SAX_LV_ENDOCARDIAL",
                                      "LAX_LV_ENDOCARDIAL", "AORTA_VALVE"}));
  EXPECT_TRUE(ExpandContourAlias("").empty());
  EXPECT_EQ(ExpandContourAlias(" lv-epi , LAX_LA "),
            (std::vector<std::string>{"SAX_LV_EPICARDIAL", "LAX_LV_EPICARDIAL",
                                      "LAX_LA"}));
}

// biv-me's second test case has a GPFile without the header line: read as
// biv-me's columns, every row kept (biv-me drops the first), errors named by
// the file's own lines.
TEST(PointReaderTest, GpFileWithoutItsHeaderLineKeepsEveryRow) {
  const std::string dir = ScratchDirectory("gp_headerless");
  const std::string rows =
      "1\t2\t3\tSAX_LV_ENDOCARDIAL\t2\t1.0\t0\n"
      "4\t5\t6\tSAX_RV_FREEWALL\t2\t1.0\t0\n"
      "7\t8\t9\tLAX_LV_ENDOCARDIAL\t9\t1.0\t1.0\n";
  WriteText(dir + "/GPFile_000.txt", rows);
  WriteText(dir + "/GPFile_001.txt", std::string(kGpHeader) + rows);
  const PointSequence sequence = ReadGpFiles(dir, {});
  ASSERT_EQ(sequence.frames.size(), 2u);
  ASSERT_EQ(sequence.frames[0].points.size(), 3u);
  ASSERT_EQ(sequence.frames[1].points.size(), 3u);
  for (size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(sequence.frames[0].points[i].position,
              sequence.frames[1].points[i].position);
    EXPECT_EQ(sequence.frames[0].points[i].layer,
              sequence.frames[1].points[i].layer);
  }
  EXPECT_EQ(sequence.frames[0].points[0].position, Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(sequence.frames[0].points[0].layer, WallLayer::kEndocardium);
  WriteText(dir + "/GPFile_000.txt",
            "1\t2\t3\tSAX_LV_ENDOCARDIAL\t2\t1.0\t0\n"
            "1\tnan\t3\tSAX_LV_ENDOCARDIAL\t2\t1.0\t0\n");
  EXPECT_EQ(GpErrorOf(dir, {}),
            dir + "/GPFile_000.txt:2: column 'y' is not a finite number");
}

// The same from the real data: GPFile_000.txt with its header line taken
// off reads as the file does, all 1,814 rows.
TEST(PointReaderTest, BivMeGpFileWithoutItsHeaderLineReadsTheSame) {
  const std::string shared = SharedDataDirectory();
  if (shared.empty()) GTEST_SKIP() << "../shared/data is absent";
  const std::string original =
      shared + "/biv-me-patient1/guidepoints/GPFile_000.txt";
  const std::string text = ReadText(original);
  const std::string copy = ScratchDirectory("gp_real") + "/GPFile_000.txt";
  WriteText(copy, text.substr(text.find('\n') + 1));
  const PointSequence with = ReadGpFiles(original, {});
  const PointSequence without = ReadGpFiles(copy, {});
  ASSERT_EQ(with.frames[0].points.size(), 1814u);
  ASSERT_EQ(without.frames[0].points.size(), 1814u);
  for (size_t i = 0; i < 1814; ++i) {
    ASSERT_EQ(without.frames[0].points[i].position,
              with.frames[0].points[i].position);
    ASSERT_EQ(without.frames[0].points[i].layer,
              with.frames[0].points[i].layer);
  }
  EXPECT_EQ(
      ReadGpFiles(copy, ExpandContourAlias("lv-endo")).frames[0].points.size(),
      441u);
}

// A time_ms column gives each frame's trigger time, a surface column each
// point's wall; both read back from what ToPointsCsv writes.
TEST(PointReaderTest, CsvTimesAndSurfacesAreReadAndChecked) {
  const PointSequence sequence = ReadPointsCsv(
      CsvFile("frame,id,x,y,z,time_ms,surface\n0,1,0,0,0,0,endo\n"
              "0,2,1,0,0,0,epi\n1,1,0,0,1,42.5,\n1,2,1,0,1,42.5,midwall\n"));
  EXPECT_EQ(sequence.time_ms, (std::vector<double>{0.0, 42.5}));
  EXPECT_EQ(sequence.frames[0].points[0].layer, WallLayer::kEndocardium);
  EXPECT_EQ(sequence.frames[0].points[1].layer, WallLayer::kEpicardium);
  EXPECT_EQ(sequence.frames[1].points[0].layer, WallLayer::kAnywhere);
  EXPECT_EQ(sequence.frames[1].points[1].layer, WallLayer::kAnywhere);
  EXPECT_TRUE(
      ReadPointsCsv(CsvFile("frame,id,x,y,z\n0,1,0,0,0\n")).time_ms.empty());
  EXPECT_EQ(ErrorOf("frame,id,x,y,z,time_ms\n0,1,0,0,0,0\n0,2,1,0,0,5\n"),
            "points.csv:3: time_ms 5 differs from frame 0's 0 (line 2)");
  EXPECT_EQ(ErrorOf("frame,id,x,y,z,time_ms\n0,1,0,0,0,40\n1,1,1,0,0,30\n"),
            "points.csv:3: frame 1's time_ms 30 is not after frame 0's 40");
  EXPECT_EQ(ErrorOf("frame,id,x,y,z,time_ms\n0,1,0,0,0,\n"),
            "points.csv:2: column 'time_ms' is not a number: ''");
  EXPECT_EQ(ErrorOf("frame,id,x,y,z,surface\n0,1,0,0,0,endocardium\n"),
            "points.csv:2: column 'surface' is 'endocardium' (expected endo, "
            "midwall, epi or empty)");
}

TEST(PointReaderTest, ReadsTheBivMePatient) {
  const std::string shared = SharedDataDirectory();
  if (shared.empty()) GTEST_SKIP() << "../shared/data is absent";
  const PointSequence sequence = ReadGpFiles(
      shared + "/biv-me-patient1/guidepoints", ExpandContourAlias("lv-endo"));
  ASSERT_EQ(sequence.frames.size(), 25u);
  std::set<std::int64_t> ids;
  for (size_t i = 0; i < sequence.frames.size(); ++i) {
    const Frame& frame = sequence.frames[i];
    EXPECT_EQ(frame.index, static_cast<int>(i));
    EXPECT_GT(frame.points.size(), 100u);
    for (const DataPoint& point : frame.points) ids.insert(point.id);
  }
  // GPFile_000.txt: 233 SAX and 208 LAX LV endocardial rows.
  EXPECT_EQ(sequence.frames[0].points.size(), 441u);
  // Untracked: no id is shared between frames.
  size_t total = 0;
  for (const Frame& frame : sequence.frames) total += frame.points.size();
  EXPECT_EQ(ids.size(), total);
}

}  // namespace
}  // namespace pfdm
