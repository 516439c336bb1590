#include "render/proof_document.hpp"

#include <gtest/gtest.h>

#include <cairo.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>

#include "io/source.hpp"
#include "scratch.hpp"
#include "test_fonts.hpp"

namespace gf {
namespace {

namespace fs = std::filesystem;

std::vector<ProofGlyph> pages(const std::string& font, std::vector<std::string> names, FontInfo& info) {
  SourceOptions o;
  o.selection.names = std::move(names);
  const GlyphSet set = GlyphSource::open(font, o).load_all();
  info = set.font;
  std::vector<ProofGlyph> out;
  for (const Glyph& g : set.glyphs) out.push_back({g, std::nullopt});
  return out;
}

TEST(Proof, PdfHasAnOverviewAndAPagePerGlyph) {
  FontInfo info;
  const auto p = pages(test::because_we_learn, {"a", "g", "S"}, info);
  const fs::path pdf = test::scratch("p.pdf");
  ProofOptions options;
  options.title = "test";
  write_proof(p, info, options, pdf);
  std::ifstream in(pdf, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), {});
  EXPECT_EQ(bytes.substr(0, 5), "%PDF-");
  const std::regex page("/Type /Page[^s]");
  EXPECT_EQ(std::distance(std::sregex_iterator(bytes.begin(), bytes.end(), page), std::sregex_iterator()), 1 + 3);
}

TEST(Proof, PngShowsOutlineCombsAndMarksInTheirColours) {
  FontInfo info;
  auto p = pages(test::dejavu, {"S"}, info);
  p[0].compare = pages(test::because_we_learn, {"S"}, info)[0].glyph;  // any second version
  const fs::path png = test::scratch("p.png");
  ProofOptions options{"test", "other", true};
  write_proof(p, info, options, png);
  cairo_surface_t* s = cairo_image_surface_create_from_png(png.c_str());
  ASSERT_EQ(cairo_surface_status(s), CAIRO_STATUS_SUCCESS);
  const int w = cairo_image_surface_get_width(s), h = cairo_image_surface_get_height(s);
  EXPECT_EQ(w, 2 * 595 + 1);
  const unsigned char* data = cairo_image_surface_get_data(s);
  const int stride = cairo_image_surface_get_stride(s);
  int blue = 0, red = 0, magenta = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const unsigned char* px = data + y * stride + 4 * x;  // BGRA
      const int b = px[0], g = px[1], r = px[2];
      blue += b > 150 && r < 120 && g < 160;                // left-turn comb teeth
      red += r > 180 && g < 60 && b < 90;                   // the compared outline, extremum marks
      magenta += r > 150 && b > 100 && g < 60;              // inflection marks (an S has one)
    }
  cairo_surface_destroy(s);
  EXPECT_GT(blue, 500);
  EXPECT_GT(red, 200);
  EXPECT_GT(magenta, 10);
}

TEST(Proof, SvgIsWritten) {
  FontInfo info;
  const fs::path svg = test::scratch("p.svg");
  ProofOptions options;
  options.title = "test";
  write_proof(pages(test::inter_variable, {"uni0061"}, info), info, options, svg);
  std::ifstream in(svg);
  const std::string text((std::istreambuf_iterator<char>(in)), {});
  EXPECT_NE(text.find("<svg"), std::string::npos);
}

}  // namespace
}  // namespace gf
