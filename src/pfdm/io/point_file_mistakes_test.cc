#include "pfdm/io/point_file_mistakes.h"

#include <string>

#include "gtest/gtest.h"
#include "pfdm/io/point_reader.h"
#include "pfdm/testing/test_util.h"
#include "pfdm/util/error.h"

namespace pfdm {
namespace {

// The message ReadPointsCsv gives for a file named `name` holding `text`,
// from the file's name on.
std::string ErrorOf(const std::string& name, const std::string& text) {
  const std::string path = ScratchDirectory("mistakes") + "/" + name;
  WriteText(path, text);
  try {
    ReadPointsCsv(path);
  } catch (const InputError& error) {
    const std::string message = error.what();
    return message.substr(message.rfind('/', message.find(name)) + 1);
  }
  return "no error";
}

TEST(PointFileMistakesTest, AMeshPointsToMeshPoints) {
  const std::string expected_tail =
      ": a mesh, not a points CSV; 'pfdm mesh-points --mesh ";
  const std::string vtk = ErrorOf(
      "lv.vtk", "# vtk DataFile Version 3.0\nlv\nASCII\nDATASET POLYDATA\n");
  EXPECT_EQ(vtk.substr(0, 6 + expected_tail.size()), "lv.vtk" + expected_tail);
  EXPECT_NE(vtk.find("--out points.csv' writes its vertices"),
            std::string::npos);
  // By its content when the name says nothing.
  EXPECT_EQ(ErrorOf("lv.txt", "<?xml version=\"1.0\"?>\n<VTKFile>\n")
                .substr(0, 6 + expected_tail.size()),
            "lv.txt" + expected_tail);
  EXPECT_EQ(ErrorOf("lv.obj", "v 1 2 3\n").substr(0, 6), "lv.obj");
}

TEST(PointFileMistakesTest, TabsAndSemicolonsAreNamed) {
  EXPECT_EQ(ErrorOf("tabs.csv", "frame\tid\tx\ty\tz\n0\t1\t2\t3\t4\n"),
            "tabs.csv:1: columns separated by tabs; pfdm reads "
            "comma-separated files (frame,id,x,y,z): replace the separators "
            "with commas");
  EXPECT_EQ(ErrorOf("semi.csv", "frame;id;x;y;z\n0;1;2;3;4\n"),
            "semi.csv:1: columns separated by semicolons; pfdm reads "
            "comma-separated files (frame,id,x,y,z): replace the separators "
            "with commas");
  // A comma-separated header is read as a CSV.
  EXPECT_EQ(ErrorOf("fine.csv", "frame,id,x,y,z\n0,1,2,3,4\n"), "no error");
}

TEST(PointFileMistakesTest, FramesFromOneSayWhatToSubtract) {
  EXPECT_EQ(ErrorOf("one.csv", "frame,id,x,y,z\n1,1,2,3,4\n2,1,2,3,5\n"),
            "one.csv: the first frame is 1; pfdm numbers frames from 0 "
            "(end-diastole by default): subtract 1 from the frame column");
  EXPECT_NO_THROW(CheckFramesStartAtZero("a.csv", 0));
}

}  // namespace
}  // namespace pfdm
