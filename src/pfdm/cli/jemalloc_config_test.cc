// The CLI runs on jemalloc with jemalloc_config.cc's settings.
#include <cstdlib>
#include <string>

#include "gtest/gtest.h"
#include "pfdm/testing/test_util.h"

namespace pfdm {
namespace {

TEST(JemallocConfigTest, TheCliAllocatesWithHugePagesAndReusesFreedPages) {
#ifndef PFDM_JEMALLOC
  GTEST_SKIP() << "built with PFDM_JEMALLOC=OFF";
#endif
  const std::string dir = ScratchDirectory("jemalloc_config");
  // jemalloc prints its options at exit when asked; the compiled-in ones
  // stand where the environment does not name them.
  setenv("MALLOC_CONF", "stats_print:true", 1);
  const CommandResult run =
      RunPfdm("simulate --frames 2 --tags 50 --out " + dir + "/phantom.csv");
  unsetenv("MALLOC_CONF");
  ASSERT_EQ(run.exit_code, 0) << run.error;
  const std::string stats = run.output + run.error;
  EXPECT_NE(stats.find("opt.thp: \"always\""), std::string::npos) << stats;
  EXPECT_NE(stats.find("opt.dirty_decay_ms: -1"), std::string::npos);
  EXPECT_NE(stats.find("opt.muzzy_decay_ms: -1"), std::string::npos);
  EXPECT_NE(stats.find("opt.oversize_threshold: 0"), std::string::npos);
}

}  // namespace
}  // namespace pfdm
