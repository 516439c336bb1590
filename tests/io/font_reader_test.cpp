#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "geom/join.hpp"
#include "io/freetype_reader.hpp"
#include "io/input_error.hpp"
#include "io/source.hpp"
#include "io/text_shaping.hpp"
#include "scratch.hpp"
#include "test_fonts.hpp"

namespace gf {
namespace {

namespace fs = std::filesystem;

template <typename F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(TrueType, KeepsQuadraticsAndMarksImpliedPoints) {
  const FreetypeFont font = FreetypeFont::open(test::dejavu);
  EXPECT_EQ(font.info().units_per_em, 2048);
  EXPECT_EQ(font.info().family_name, "DejaVu Sans");
  const Glyph a = font.load_glyph(*font.glyph_by_name("a"));
  EXPECT_EQ(a.unicodes, std::vector<char32_t>{U'a'});
  EXPECT_EQ(a.advance_width, 1255);
  ASSERT_EQ(a.outline.contours.size(), 2u);
  int implied = 0;
  for (const Contour& c : a.outline.contours) {
    ASSERT_EQ(c.nodes.size(), c.segments.size());
    for (std::size_t i = 0; i < c.segments.size(); ++i) {
      EXPECT_FALSE(std::holds_alternative<Cubic>(c.segments[i]));
      EXPECT_EQ(start_point(c.segments[(i + 1) % c.segments.size()]), end_point(c.segments[i]));
      if (!c.nodes[i].implied) continue;
      ++implied;
      // An implied point is exactly the midpoint of the off-curve points around it.
      const auto& in = std::get<Quad>(c.segments[i - 1]);
      const auto& out = std::get<Quad>(c.segments[i]);
      EXPECT_EQ(out.p[0], (in.p[1] + out.p[1]) * 0.5);
    }
  }
  EXPECT_GT(implied, 0);
}

TEST(Cff, ReadsCubics) {
  const FreetypeFont font = FreetypeFont::open(test::because_we_learn);
  EXPECT_EQ(font.info().units_per_em, 1000);
  const Glyph a = font.load_glyph(*font.glyph_by_name("a"));
  bool cubic = false;
  for (const Contour& c : a.outline.contours)
    for (const Segment& s : c.segments) {
      EXPECT_FALSE(std::holds_alternative<Quad>(s));
      cubic = cubic || std::holds_alternative<Cubic>(s);
    }
  EXPECT_TRUE(cubic);
}

TEST(Cff, KeepsFractionalCoordinates) {
  // Inconsolata's E stands at x = 58.68359375 (fontTools reads the charstring so); FreeType
  // unscaled would give 58.
  const FreetypeFont font = FreetypeFont::open(test::inconsolata);
  const Glyph e = font.load_glyph(*font.glyph_by_name("E"));
  ASSERT_FALSE(e.outline.contours.empty());
  const Vec2 p = start_point(e.outline.contours[0].segments[0]);
  EXPECT_DOUBLE_EQ(p.x, 58.68359375);
  EXPECT_DOUBLE_EQ(p.y, 623.94921875);
}

TEST(Cff, ClosesAContourOnItsStartWithoutAResidueLine) {
  // Linux Libertine's d: HarfBuzz's 16.16 arithmetic brings its inner contour back to
  // (334, 50.3) 1.5e-5 units off and closes it with a line that short (fontTools reads the
  // same). Kept, the line would make a corner of either end of a join the source turns 0.34°.
  const FreetypeFont font = FreetypeFont::open(test::linux_libertine);
  const Glyph d = font.load_glyph(*font.glyph_by_codepoint(U'd'));
  bool seen = false;
  for (const Contour& c : d.outline.contours) {
    ASSERT_TRUE(c.closed);
    EXPECT_EQ(end_point(c.segments.back()), start_point(c.segments.front()));
    for (const Segment& s : c.segments)
      if (std::holds_alternative<Line>(s)) {
        EXPECT_GT(distance(start_point(s), end_point(s)), 1e-3);
      }
    for (const Join& j : joins_of(c))
      if (distance(j.point, {334, 50.3}) < 1e-3) {
        seen = true;
        EXPECT_EQ(j.kind, JoinKind::kink);
        EXPECT_NEAR(std::abs(j.angle_deg), 0.34, 0.01);
      }
  }
  EXPECT_TRUE(seen);
}

TEST(Shaping, TextSelectsTheLigaturesItUses) {
  const FreetypeFont font = FreetypeFont::open(test::dejavu);
  std::vector<std::string> names;
  for (const auto gid : glyphs_for_text(font.bytes(), font.location(), "office"))
    names.push_back(font.glyph_name(gid));
  EXPECT_EQ(names, (std::vector<std::string>{"o", "uniFB03", "c", "e"}));
}

TEST(Selection, NamesCodePointsAndTextCombineInOrderWithoutRepeats) {
  SourceOptions o;
  o.selection.names = {"z", "a"};
  o.selection.unicodes = {{U'a', U'c'}};
  o.selection.text = "bad";
  const GlyphSet set = GlyphSource::open(test::dejavu, o).load_all();
  std::vector<std::string> names;
  for (const Glyph& g : set.glyphs) names.push_back(g.name);
  EXPECT_EQ(names, (std::vector<std::string>{"z", "a", "b", "c", "d"}));
}

TEST(Selection, WholeFontSkipsGlyphsWithoutOutlines) {
  const GlyphSet set = GlyphSource::open(test::dejavu).load_all();
  for (const Glyph& g : set.glyphs) {
    EXPECT_NE(g.name, "space");
    EXPECT_FALSE(g.outline.contours.empty()) << g.name;
  }
  SourceOptions space;
  space.selection.names = {"space"};
  EXPECT_EQ(GlyphSource::open(test::dejavu, space).load_all().glyphs.size(), 1u);
}

TEST(Variable, LocationAndNamedInstanceAgree) {
  FontLoadOptions black;
  black.named_instance = "Black";
  FontLoadOptions heavy;
  heavy.location = {{"wght", 900.0}};
  const FreetypeFont a = FreetypeFont::open(test::inter_variable, black);
  const FreetypeFont b = FreetypeFont::open(test::inter_variable, heavy);
  const FreetypeFont regular = FreetypeFont::open(test::inter_variable);
  const auto o = *a.glyph_by_codepoint(U'o');
  const Glyph ga = a.load_glyph(o), gb = b.load_glyph(o), gr = regular.load_glyph(o);
  ASSERT_EQ(ga.outline.contours.size(), gb.outline.contours.size());
  for (std::size_t i = 0; i < ga.outline.contours.size(); ++i)
    EXPECT_EQ(ga.outline.contours[i].segments, gb.outline.contours[i].segments);
  EXPECT_GT(ga.advance_width, gr.advance_width);  // black is wider than regular
  EXPECT_EQ(a.axes().size(), 2u);
}

TEST(Variable, Cff2InterpolatesBetweenItsMasters) {
  // The probe font has masters at wght 100 and 900; wght 500 is their exact mean.
  const auto load = [](double w) {
    FontLoadOptions o;
    o.location = {{"wght", w}};
    const FreetypeFont f = FreetypeFont::open(test::cff2_variable, o);
    return f.load_glyph(*f.glyph_by_codepoint(U'a'));
  };
  const Glyph light = load(100), black = load(900), mid = load(500);
  const FreetypeFont at_default = FreetypeFont::open(test::cff2_variable);
  const Glyph def = at_default.load_glyph(*at_default.glyph_by_codepoint(U'a'));
  ASSERT_EQ(light.outline.contours.size(), mid.outline.contours.size());
  for (std::size_t c = 0; c < mid.outline.contours.size(); ++c) {
    const auto& sl = light.outline.contours[c].segments;
    const auto& sb = black.outline.contours[c].segments;
    const auto& sm = mid.outline.contours[c].segments;
    EXPECT_EQ(def.outline.contours[c].segments, sl);
    ASSERT_EQ(sl.size(), sm.size());
    for (std::size_t i = 0; i < sm.size(); ++i) {
      std::vector<Vec2> l, b, m;
      for_each_point(sl[i], [&](Vec2 p) { l.push_back(p); });
      for_each_point(sb[i], [&](Vec2 p) { b.push_back(p); });
      for_each_point(sm[i], [&](Vec2 p) { m.push_back(p); });
      ASSERT_EQ(l.size(), m.size());
      for (std::size_t k = 0; k < m.size(); ++k) {
        EXPECT_NEAR(m[k].x, 0.5 * (l[k].x + b[k].x), 1e-3);
        EXPECT_NEAR(m[k].y, 0.5 * (l[k].y + b[k].y), 1e-3);
      }
    }
  }
}

TEST(Errors, EachNamesTheFileOrGlyphAndTheProblem) {
  const fs::path dir = test::scratch_dir();
  const fs::path truncated = dir / "truncated.ttf";
  {
    std::ifstream in(test::dejavu, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), {});
    std::ofstream(truncated, std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  }
  const fs::path text = dir / "text.ttf";
  std::ofstream(text) << "not a font at all\n";

  EXPECT_EQ(error_of([&] { FreetypeFont::open(dir / "missing.ttf"); }), (dir / "missing.ttf").string() + ": no such file");
  EXPECT_NE(error_of([&] { FreetypeFont::open(text); }).find("not a font file"), std::string::npos);
  EXPECT_NE(error_of([&] { FreetypeFont::open(truncated); }).find("truncated font: table"), std::string::npos);
  EXPECT_NE(error_of([&] { FreetypeFont::open(dir); }).find("is a directory"), std::string::npos);
  SourceOptions unknown;
  unknown.selection.names = {"a", "nosuchglyph"};
  EXPECT_EQ(error_of([&] { GlyphSource::open(test::dejavu, unknown); }),
            test::dejavu + ": glyph 'nosuchglyph': no glyph of that name");
  SourceOptions unmapped;
  unmapped.selection.unicodes = {{0x10FFFF, 0x10FFFF}};
  EXPECT_NE(error_of([&] { GlyphSource::open(test::dejavu, unmapped); }).find("U+10FFFF"), std::string::npos);
  FontLoadOptions far;
  far.location = {{"wght", 1200}};
  EXPECT_NE(error_of([&] { FreetypeFont::open(test::inter_variable, far); }).find("outside the axis range"), std::string::npos);
  FontLoadOptions on_static;
  on_static.location = {{"wght", 700}};
  EXPECT_NE(error_of([&] { FreetypeFont::open(test::dejavu, on_static); }).find("needs a variable font"), std::string::npos);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace gf
