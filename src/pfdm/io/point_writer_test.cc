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

}  // namespace
}  // namespace pfdm
