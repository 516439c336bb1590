// The small languages of the command line: --unicodes and --location.
#include <gtest/gtest.h>

#include "io/glyph_selection.hpp"
#include "io/input_error.hpp"
#include "io/unicode_ranges.hpp"
#include "io/variation_location.hpp"

namespace gf {
namespace {

TEST(UnicodeRanges, HbSubsetSyntax) {
  const auto r = parse_unicode_ranges("U+0041-005A,U+0061-007A 20, 0x2022,*");
  ASSERT_EQ(r.size(), 5u);
  EXPECT_EQ(r[0].first, U'A');
  EXPECT_EQ(r[0].last, U'Z');
  EXPECT_EQ(r[2].first, U' ');
  EXPECT_TRUE(r[2].single());
  EXPECT_EQ(r[3].first, U'\u2022');
  EXPECT_EQ(r[4].last, U'\U0010FFFF');
}

TEST(UnicodeRanges, MalformedSpecsAreRefusedNamingTheToken) {
  for (const char* bad : {"U+00ZZ", "U+", "41-", "5A-41", "110000", "U+0041-U+12345678", ""}) {
    try {
      parse_unicode_ranges(bad);
      ADD_FAILURE() << bad << " was accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("--unicodes"), std::string::npos);
    }
  }
}

TEST(VariationLocation, ParsesTagsAndValues) {
  const auto l = parse_variation_location("wght=700, wdth=80.5,opsz=-1e1");
  ASSERT_EQ(l.size(), 3u);
  EXPECT_EQ(l[0].tag, "wght");
  EXPECT_EQ(l[1].value, 80.5);
  EXPECT_EQ(l[2].value, -10.0);
  EXPECT_EQ(parse_variation_location("ab=1")[0].tag, "ab  ");
}

TEST(VariationLocation, MalformedSpecsAreRefused) {
  for (const char* bad : {"wght", "wght=", "wght=abc", "toolong=1", "=5", "wght=1,,wdth=2", "wght=1,wght=2", "wght=nan"})
    EXPECT_THROW(parse_variation_location(bad), InputError) << bad;
}

TEST(GlyphNames, SplitsOnCommas) {
  EXPECT_EQ(split_glyph_names("a, b,c,,"), (std::vector<std::string>{"a", "b", "c"}));
}

}  // namespace
}  // namespace gf
