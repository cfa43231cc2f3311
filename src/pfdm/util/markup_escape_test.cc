#include "pfdm/util/markup_escape.h"

#include "gtest/gtest.h"

namespace pfdm {
namespace {

TEST(MarkupEscapeTest, EscapesTheFourMarkupCharacters) {
  EXPECT_EQ(EscapeMarkup("a<b & \"c\">"), "a&lt;b &amp; &quot;c&quot;&gt;");
  EXPECT_EQ(EscapeMarkup("plain 'text'"), "plain 'text'");
}

}  // namespace
}  // namespace pfdm
