#include "pfdm/io/point_writer.h"

#include "gtest/gtest.h"
#include "pfdm/io/point_reader.h"
#include "pfdm/phantom/phantom.h"
#include "pfdm/testing/test_util.h"

namespace pfdm {
namespace {

TEST(PointWriterTest, CsvRoundTripsExactly) {
  PhantomOptions options;
  options.num_points = 50;
  const PointSequence original = MakePhantom(options).points;
  const std::string path = ScratchDirectory("writer") + "/tags.csv";
  WriteText(path, ToPointsCsv(original));
  const PointSequence read = ReadPointsCsv(path);
  ASSERT_EQ(read.frames.size(), original.frames.size());
  for (size_t t = 0; t < read.frames.size(); ++t) {
    ASSERT_EQ(read.frames[t].points.size(), 50u);
    for (size_t i = 0; i < 50; ++i) {
      EXPECT_EQ(read.frames[t].points[i].id, original.frames[t].points[i].id);
      EXPECT_EQ(read.frames[t].points[i].position,
                original.frames[t].points[i].position);
    }
  }
}

// Trigger times and the points' walls are written only when there: a
// sequence without them keeps the five columns.
TEST(PointWriterTest, TimesAndSurfacesRoundTrip) {
  PointSequence sequence;
  sequence.frames = {{0, {{4, {1, 2, 3}, WallLayer::kEndocardium}}},
                     {1, {{4, {1, 2, 2.5}, WallLayer::kEndocardium}}}};
  EXPECT_EQ(ToPointsCsv(sequence),
            "frame,id,x,y,z,surface\n0,4,1,2,3,endo\n1,4,1,2,2.5,endo\n");
  sequence.time_ms = {0.0, 37.25};
  const std::string path = ScratchDirectory("writer") + "/timed.csv";
  WriteText(path, ToPointsCsv(sequence));
  EXPECT_EQ(ReadText(path),
            "frame,id,x,y,z,time_ms,surface\n0,4,1,2,3,0,endo\n"
            "1,4,1,2,2.5,37.25,endo\n");
  const PointSequence read = ReadPointsCsv(path);
  EXPECT_EQ(read.time_ms, sequence.time_ms);
  EXPECT_EQ(read.frames[1].points[0].layer, WallLayer::kEndocardium);
}

}  // namespace
}  // namespace pfdm
