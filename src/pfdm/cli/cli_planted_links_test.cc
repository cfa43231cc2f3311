// Issue 29: links planted where the commands write.  A link at an output's
// name is replaced by the file, never written through; the temporaries'
// names (random, made with O_EXCL | O_NOFOLLOW) are tested where they can
// be known, in util/atomic_file_test.cc and io/fit_output_test.cc.
#include <filesystem>
#include <string>

#include "gtest/gtest.h"
#include "pfdm/testing/test_util.h"

namespace pfdm {
namespace {

namespace fs = std::filesystem;

// A link at dir/name to a file of its own, holding "precious".
void PlantLink(const std::string& dir, const std::string& name) {
  WriteText(dir + "/victim_" + name, "precious");
  fs::create_symlink(dir + "/victim_" + name, dir + "/" + name);
}

void ExpectReplacedNotFollowed(const std::string& dir,
                               const std::string& name) {
  EXPECT_EQ(ReadText(dir + "/victim_" + name), "precious") << name;
  EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(dir + "/" + name)))
      << name;
}

TEST(CliPlantedLinksTest, SimulateReplacesLinksAtItsOutputs) {
  const std::string dir = ScratchDirectory("links");
  PlantLink(dir, "p.csv");
  PlantLink(dir, "p_truth.csv");
  const CommandResult run =
      RunPfdm("simulate --frames 2 --tags 100 --out " + dir + "/p.csv");
  ASSERT_EQ(run.exit_code, 0) << run.error;
  ExpectReplacedNotFollowed(dir, "p.csv");
  ExpectReplacedNotFollowed(dir, "p_truth.csv");
  EXPECT_EQ(ReadText(dir + "/p.csv").rfind("frame,id,x,y,z\n", 0), 0u);
}

TEST(CliPlantedLinksTest, MeshPointsReplacesALinkAtItsOutput) {
  const std::string dir = ScratchDirectory("links");
  fs::create_directories(dir + "/obj");
  for (const char* name : {"/obj/lv_000.obj", "/obj/lv_001.obj"}) {
    WriteText(dir + name, "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n");
  }
  PlantLink(dir, "points.csv");
  const CommandResult run = RunPfdm("mesh-points --mesh " + dir +
                                    "/obj --out " + dir + "/points.csv");
  ASSERT_EQ(run.exit_code, 0) << run.error;
  ExpectReplacedNotFollowed(dir, "points.csv");
}

TEST(CliPlantedLinksTest, FitReplacesLinksAtItsOutputs) {
  const std::string dir = ScratchDirectory("links");
  CommandResult run =
      RunPfdm("simulate --frames 2 --tags 300 --out " + dir + "/p.csv");
  ASSERT_EQ(run.exit_code, 0) << run.error;
  fs::create_directories(dir + "/fit");
  for (const char* name :
       {"fit.json", "report.html", "parameters.csv", "frame_001.vtp"}) {
    PlantLink(dir + "/fit", name);
  }
  run = RunPfdm("fit --points " + dir + "/p.csv --out " + dir + "/fit");
  ASSERT_EQ(run.exit_code, 0) << run.error;
  for (const char* name :
       {"fit.json", "report.html", "parameters.csv", "frame_001.vtp"}) {
    ExpectReplacedNotFollowed(dir + "/fit", name);
  }
}

}  // namespace
}  // namespace pfdm
