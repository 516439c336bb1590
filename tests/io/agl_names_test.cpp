// Glyph names for fonts that store none: the Adobe Glyph List For New Fonts' names for Basic
// Latin and Latin-1 (reference values from the list itself), none elsewhere.
#include "io/agl_names.hpp"

#include <gtest/gtest.h>

namespace gf {
namespace {

TEST(AglNames, BasicLatinAndLatin1TakeTheListsNames) {
  EXPECT_EQ(agl_name(U' '), "space");
  EXPECT_EQ(agl_name(U'0'), "zero");
  EXPECT_EQ(agl_name(U','), "comma");
  EXPECT_EQ(agl_name(U'-'), "hyphen");
  EXPECT_EQ(agl_name(U'~'), "asciitilde");
  for (char32_t c = U'A'; c <= U'Z'; ++c) EXPECT_EQ(agl_name(c), std::string(1, static_cast<char>(c)));
  for (char32_t c = U'a'; c <= U'z'; ++c) EXPECT_EQ(agl_name(c), std::string(1, static_cast<char>(c)));
  EXPECT_EQ(agl_name(0x00A1), "exclamdown");
  EXPECT_EQ(agl_name(0x00C0), "Agrave");
  EXPECT_EQ(agl_name(0x00DF), "germandbls");
  EXPECT_EQ(agl_name(0x00FF), "ydieresis");
}

TEST(AglNames, CodePointsTheListLeavesOutHaveNone) {
  for (const char32_t c : {0x0000u, 0x001Fu, 0x007Fu, 0x009Fu, 0x00A0u, 0x00ADu, 0x00B2u, 0x00B3u, 0x00B9u, 0x0100u, 0x1F600u})
    EXPECT_FALSE(agl_name(c).has_value()) << std::hex << static_cast<unsigned>(c);
}

}  // namespace
}  // namespace gf
