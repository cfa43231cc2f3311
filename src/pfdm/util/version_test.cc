#include "pfdm/util/version.h"

#include <regex>
#include <string>

#include "gtest/gtest.h"

namespace pfdm {
namespace {

TEST(VersionTest, IsTheProjectsAndTheTimeIsUtcToTheMinute) {
  EXPECT_TRUE(std::regex_match(std::string(PfdmVersion()),
                               std::regex(R"(\d+\.\d+\.\d+)")))
      << PfdmVersion();
  EXPECT_TRUE(std::regex_match(UtcMinuteNow(),
                               std::regex(R"(20\d\d-\d\d-\d\d \d\d:\d\d UTC)")))
      << UtcMinuteNow();
}

}  // namespace
}  // namespace pfdm
