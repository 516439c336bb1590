// Examples from the UFO 3 specification and fontTools.ufoLib.filenames.
#include "io/ufo_file_names.hpp"

#include <gtest/gtest.h>

namespace gf {
namespace {

std::string name(const std::string& glyph) {
  std::set<std::string> taken;
  return glif_file_name(glyph, taken);
}

TEST(UfoFileNames, SpecificationExamples) {
  EXPECT_EQ(name("a"), "a.glif");
  EXPECT_EQ(name("A"), "A_.glif");
  EXPECT_EQ(name("AE"), "A_E_.glif");
  EXPECT_EQ(name("Ae"), "A_e.glif");
  EXPECT_EQ(name("ae"), "ae.glif");
  EXPECT_EQ(name("aE"), "aE_.glif");
  EXPECT_EQ(name("a.alt"), "a.alt.glif");
  EXPECT_EQ(name("A.alt"), "A_.alt.glif");
  EXPECT_EQ(name("A.Alt"), "A_.A_lt.glif");
  EXPECT_EQ(name("T_H"), "T__H_.glif");
  EXPECT_EQ(name(".notdef"), "_notdef.glif");
  EXPECT_EQ(name("con"), "_con.glif");
  EXPECT_EQ(name("CON"), "C_O_N_.glif");
  EXPECT_EQ(name("con.alt"), "_con.alt.glif");
  EXPECT_EQ(name("alt.con"), "alt._con.glif");
  EXPECT_EQ(name("a/b"), "a_b.glif");
}

TEST(UfoFileNames, ClashesIgnoringCaseGetNumbers) {
  std::set<std::string> taken;
  EXPECT_EQ(glif_file_name("a", taken), "a.glif");
  EXPECT_NE(glif_file_name("a", taken), "a.glif");
  EXPECT_EQ(taken.size(), 2u);
}

}  // namespace
}  // namespace gf
