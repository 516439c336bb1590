// Writers change nothing they are not asked to: font → UFO / SVG → glyphfair's readers gives
// back exactly the same outlines; and the UFO reader understands what designers' UFOs hold.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "io/input_error.hpp"
#include "io/json_writer.hpp"
#include "io/source.hpp"
#include "io/svg_reader.hpp"
#include "io/svg_writer.hpp"
#include "io/ufo_reader.hpp"
#include "io/ufo_writer.hpp"
#include "scratch.hpp"
#include "test_fonts.hpp"

namespace gf {
namespace {

namespace fs = std::filesystem;

void expect_same_geometry(const GlyphSet& a, const GlyphSet& b, bool with_flags) {
  ASSERT_EQ(a.glyphs.size(), b.glyphs.size());
  for (std::size_t i = 0; i < a.glyphs.size(); ++i) {
    const Glyph& x = a.glyphs[i];
    const Glyph& y = b.glyphs[i];
    EXPECT_EQ(x.name, y.name);
    EXPECT_EQ(x.advance_width, y.advance_width) << x.name;
    ASSERT_EQ(x.outline.contours.size(), y.outline.contours.size()) << x.name;
    for (std::size_t c = 0; c < x.outline.contours.size(); ++c) {
      const Contour& p = x.outline.contours[c];
      const Contour& q = y.outline.contours[c];
      EXPECT_EQ(p.closed, q.closed);
      EXPECT_EQ(p.segments, q.segments) << x.name << " contour " << c;
      if (!with_flags) continue;
      ASSERT_EQ(p.nodes.size(), q.nodes.size());
      for (std::size_t n = 1; n < p.nodes.size(); ++n) EXPECT_EQ(p.nodes[n].implied, q.nodes[n].implied);
    }
  }
}

class RoundTrip : public ::testing::TestWithParam<std::string> {};

TEST_P(RoundTrip, UfoGivesBackTheSameOutlinesNamesAndUnicodes) {
  const GlyphSet font = GlyphSource::open(GetParam()).load_all();
  const fs::path ufo = test::scratch("font.ufo");
  write_ufo(font, ufo);
  const GlyphSet back = read_ufo(ufo);
  expect_same_geometry(font, back, true);
  for (std::size_t i = 0; i < font.glyphs.size(); ++i) EXPECT_EQ(font.glyphs[i].unicodes, back.glyphs[i].unicodes);
  EXPECT_EQ(back.font.units_per_em, font.font.units_per_em);
  EXPECT_EQ(back.font.ascender, font.font.ascender);
  // Written again, the UFO is byte for byte the same: nothing drifts.
  const fs::path again = test::scratch("again.ufo");
  write_ufo(back, again);
  for (const auto& e : fs::recursive_directory_iterator(ufo)) {
    if (!e.is_regular_file()) continue;
    std::ifstream a(e.path()), b(again / fs::relative(e.path(), ufo));
    EXPECT_EQ(std::string((std::istreambuf_iterator<char>(a)), {}), std::string((std::istreambuf_iterator<char>(b)), {}))
        << e.path();
  }
}

TEST_P(RoundTrip, SvgGivesBackTheSameGeometry) {
  const GlyphSet font = GlyphSource::open(GetParam()).load_all();
  const fs::path svg = test::scratch("font.svg");
  write_svg(font, svg);
  expect_same_geometry(font, read_svg(svg), false);
}

INSTANTIATE_TEST_SUITE_P(Fonts, RoundTrip, ::testing::Values(test::dejavu, test::because_we_learn, test::inter_variable),
                         [](const auto& info) { return std::to_string(info.index); });

TEST(Json, CarriesOutlineAndAnalysisWithFiniteNumbers) {
  SourceOptions o;
  o.selection.names = {"o", "a"};
  const GlyphSet set = GlyphSource::open(test::dejavu, o).load_all();
  const auto j = nlohmann::json::parse(outline_json(set));
  EXPECT_EQ(j["format"], "glyphfair-outline");
  EXPECT_EQ(j["version"], json_format_version);
  ASSERT_EQ(j["glyphs"].size(), 2u);
  const auto& contours = j["glyphs"][0]["contours"];
  ASSERT_EQ(contours.size(), 2u);  // o: an outer and an inner contour, in opposite directions
  EXPECT_NE(contours[0]["direction"], contours[1]["direction"]);
  const auto& o_outer = contours[0];
  int hv = 0;
  for (const auto& s : o_outer["segments"]) {
    EXPECT_GT(s["length"].get<double>(), 0.0);
    hv += static_cast<int>(s["hv_extrema"].size());
  }
  EXPECT_EQ(hv, 0);  // DejaVu's o has nodes at its extrema
  for (const auto& n : o_outer["nodes"]) EXPECT_EQ(n["join"]["kind"], "smooth");
}

fs::path write_ufo_with_glif(const std::string& glif_body) {
  const fs::path ufo = test::scratch("hand.ufo");
  fs::create_directories(ufo / "glyphs");
  std::ofstream(ufo / "metainfo.plist") << R"(<?xml version="1.0"?><plist version="1.0"><dict><key>formatVersion</key><integer>3</integer></dict></plist>)";
  std::ofstream(ufo / "glyphs/contents.plist") << R"(<?xml version="1.0"?><plist version="1.0"><dict>
    <key>base</key><string>base.glif</string><key>x</key><string>x.glif</string></dict></plist>)";
  std::ofstream(ufo / "glyphs/base.glif") << R"(<glyph name="base" format="2"><advance width="100"/><outline>
    <contour><point x="0" y="0" type="line"/><point x="10" y="0" type="line"/><point x="10" y="10" type="line"/></contour>
    </outline></glyph>)";
  std::ofstream(ufo / "glyphs/x.glif") << "<glyph name=\"x\" format=\"2\"><advance width=\"500\"/><unicode hex=\"0078\"/>"
                                       << glif_body << "</glyph>";
  return ufo;
}

TEST(UfoReader, PointTypesSmoothFlagsAndComponents) {
  const fs::path ufo = write_ufo_with_glif(R"(<outline>
      <contour><point x="0" y="0" type="move"/><point x="50" y="80"/><point x="100" y="0" type="qcurve"/></contour>
      <contour><point x="0" y="0"/><point x="100" y="0"/><point x="100" y="100"/><point x="0" y="100"/></contour>
      <contour><point x="0" y="0" type="curve" smooth="yes"/><point x="10" y="20"/><point x="30" y="20"/>
               <point x="40" y="0" type="curve"/><point x="20" y="-30"/></contour>
      <component base="base" xScale="2" yScale="-1" xOffset="5" yOffset="7"/>
    </outline>)");
  const GlyphSet set = read_ufo(ufo);
  const Glyph& x = set.glyphs[1];
  EXPECT_EQ(x.name, "x");
  ASSERT_EQ(x.outline.contours.size(), 4u);
  EXPECT_FALSE(x.outline.contours[0].closed);
  EXPECT_EQ(x.outline.contours[0].nodes.size(), 2u);
  // Four off-curve points only: a quadratic loop through four implied midpoints.
  const Contour& loop = x.outline.contours[1];
  ASSERT_EQ(loop.segments.size(), 4u);
  EXPECT_EQ(start_point(loop.segments[0]), (Vec2{0, 50}));
  EXPECT_TRUE(loop.nodes[0].implied && loop.nodes[1].implied);
  // A closed contour ending in off-curve points wraps round to its first point.
  const Contour& wrap = x.outline.contours[2];
  ASSERT_EQ(wrap.segments.size(), 2u);
  EXPECT_EQ(wrap.segments[1], Segment(Quad{{{40, 0}, {20, -30}, {0, 0}}}));
  EXPECT_EQ(wrap.nodes[0].smooth, true);
  EXPECT_EQ(wrap.nodes[1].smooth, false);
  // The component, decomposed with its transform.
  const Contour& comp = x.outline.contours[3];
  EXPECT_EQ(comp.segments[1], Segment(Line{{{25, 7}, {25, -3}}}));
}

TEST(UfoReader, MalformedGlyphsAreNamed) {
  for (const char* body :
       {R"(<outline><contour><point x="0" y="0" type="line"/><point x="1" type="line"/></contour></outline>)",
        R"(<outline><contour><point x="0" y="0" type="line"/><point x="1" y="1"/><point x="2" y="2" type="line"/></contour></outline>)",
        R"(<outline><contour><point x="0" y="0" type="line"/><point x="1" y="1" type="move"/></contour></outline>)",
        R"(<outline><component base="missing"/></outline>)", R"(<outline><contour><point x="a" y="0" type="line"/></contour></outline>)"}) {
    const fs::path ufo = write_ufo_with_glif(body);
    try {
      read_ufo(ufo);
      ADD_FAILURE() << body << " was accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("glyph 'x'"), std::string::npos) << e.what();
    }
  }
}

TEST(SvgReader, HandlesTheWholePathGrammarAndTransforms) {
  const fs::path svg = test::scratch("hand.svg");
  std::ofstream(svg) << R"svg(<svg xmlns="http://www.w3.org/2000/svg"><g transform="translate(10 0)">
      <path id="r" d="m0 0 h100 v-100 H0 z M 200,0 c 0,-50 50,-50 50,0 s 50,50 50,0 Q 300 -50 350 0 T 400 0 Z"/>
      <path id="arc" d="M0 0 A50 50 0 0 1 100 0"/></g></svg>)svg";
  const GlyphSet set = read_svg(svg);
  ASSERT_EQ(set.glyphs.size(), 2u);
  const Glyph& r = set.glyphs[0];
  EXPECT_EQ(r.name, "r");
  ASSERT_EQ(r.outline.contours.size(), 2u);
  // y flipped, the group's translation applied.
  EXPECT_EQ(end_point(r.outline.contours[0].segments[1]), (Vec2{110, 100}));
  EXPECT_EQ(r.outline.contours[0].segments.size(), 4u);
  // S reflects the previous control point; T reflects the previous quadratic control.
  const auto& s = std::get<Cubic>(r.outline.contours[1].segments[1]);
  EXPECT_EQ(s.p[1], (Vec2{260, -50}));
  const auto& t = std::get<Quad>(r.outline.contours[1].segments[3]);
  EXPECT_EQ(t.p[1], (Vec2{410, -50}));
  // A half circle of radius 50 as cubics: every point within 0.03 of the circle.
  for (const Segment& seg : set.glyphs[1].outline.contours[0].segments)
    for (double u = 0; u <= 1; u += 0.125) {
      const Vec2 p = point_at(seg, u);
      EXPECT_NEAR(norm(p - Vec2{60, 0}), 50.0, 0.03);
    }
}

}  // namespace
}  // namespace gf
