// FairedContours on a real font's composites: DejaVu Sans's adieresis repeats the two contours
// of its a point for point, eacute those of its e. A contour met before takes the result it
// had; every glyph comes out as it does faired afresh, whatever the capacity and threads.
#include "fair/faired_contours.hpp"

#include <gtest/gtest.h>

#include <thread>

#include "fair/glyph_fairing.hpp"
#include "io/source.hpp"
#include "test_fonts.hpp"

namespace gf {
namespace {

struct Font {
  GlyphSet set;
  FairSettings settings;
  Font() : set(GlyphSource::open(test::dejavu).load_all()) { settings = resolve_settings({}, set.font.units_per_em); }
  const Glyph& glyph(const std::string& name) const {
    for (const Glyph& g : set.glyphs)
      if (g.name == name) return g;
    throw std::runtime_error("no glyph " + name);
  }
};

void expect_same_outline(const GlyphFairing& a, const GlyphFairing& b) {
  ASSERT_EQ(a.glyph.outline.contours.size(), b.glyph.outline.contours.size()) << a.glyph.name;
  for (std::size_t i = 0; i < a.glyph.outline.contours.size(); ++i)
    EXPECT_TRUE(a.glyph.outline.contours[i] == b.glyph.outline.contours[i]) << a.glyph.name << " contour " << i;
  EXPECT_EQ(a.contours_faired, b.contours_faired) << a.glyph.name;
  EXPECT_EQ(a.deviation, b.deviation) << a.glyph.name;
}

TEST(FairedContours, AComponentsContoursAreFairedOnceAndComeOutAsAfresh) {
  const Font font;
  const Glyph& a = font.glyph("a");
  const Glyph& adieresis = font.glyph("adieresis");
  ASSERT_EQ(a.outline.contours.size(), 2u);
  ASSERT_EQ(adieresis.outline.contours.size(), 4u);
  FairedContours faired;
  const GlyphFairing first = fair_glyph(a, font.settings, faired);
  EXPECT_EQ(faired.size(), 2u);
  const GlyphFairing composite = fair_glyph(adieresis, font.settings, faired);
  EXPECT_EQ(faired.size(), 4u);  // the a's two again, and the two dots
  EXPECT_EQ(first.contours_faired, 2);
  expect_same_outline(first, fair_glyph(a, font.settings));
  expect_same_outline(composite, fair_glyph(adieresis, font.settings));
}

TEST(FairedContours, KeepsNoMoreThanItsCapacity) {
  const Font font;
  FairedContours faired(3);
  for (const char* name : {"a", "adieresis", "e", "eacute"}) {
    const Glyph& g = font.glyph(name);
    expect_same_outline(fair_glyph(g, font.settings, faired), fair_glyph(g, font.settings));
    EXPECT_LE(faired.size(), 3u);
  }
  EXPECT_EQ(faired.size(), 3u);
}

TEST(FairedContours, ThreadsSharingItGetWhatEachWouldAlone) {
  const Font font;
  const std::vector<std::string> names = {"a", "adieresis", "e", "eacute", "adieresis", "a"};
  std::vector<GlyphFairing> shared(names.size());
  FairedContours faired;
  const auto work = [&](std::size_t from) {
    for (std::size_t i = from; i < names.size(); i += 2)
      shared[i] = fair_glyph(font.glyph(names[i]), font.settings, faired);
  };
  std::thread other(work, 1);
  work(0);
  other.join();
  for (std::size_t i = 0; i < names.size(); ++i)
    expect_same_outline(shared[i], fair_glyph(font.glyph(names[i]), font.settings));
  EXPECT_EQ(faired.size(), 7u);  // a 2, dots 2, e 2, acute 1
}

}  // namespace
}  // namespace gf
