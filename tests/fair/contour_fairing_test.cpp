// Whole contours of real fonts through the fairing: every contour faired, within the
// tolerance by an independent brute-force distance (every sample against every sample, not
// the grid the fairing measures with), contour direction kept, on the integer grid, and G1
// exact at every smooth node.
#include "fair/glyph_fairing.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "io/source.hpp"
#include "test_fonts.hpp"

namespace gf {
namespace {

std::vector<Vec2> dense(const Contour& c) {
  std::vector<Vec2> out;
  for (const Segment& s : c.segments)
    for (int k = 0; k < 400; ++k) out.push_back(point_at(s, k / 400.0));
  return out;
}

double brute_force_hausdorff(const Contour& a, const Contour& b) {
  const std::vector<Vec2> pa = dense(a), pb = dense(b);
  auto one_way = [](const std::vector<Vec2>& from, const std::vector<Vec2>& to) {
    double worst = 0.0;
    for (const Vec2 p : from) {
      double best = 1e300;
      for (const Vec2 q : to) best = std::min(best, distance(p, q));
      worst = std::max(worst, best);
    }
    return worst;
  };
  return std::max(one_way(pa, pb), one_way(pb, pa));
}

void expect_faired(const std::string& font, const std::string& glyph, FairProfile profile) {
  SourceOptions options;
  options.selection.names.push_back(glyph);
  const GlyphSource source = GlyphSource::open(font, options);
  const Glyph g = *source.load(0);
  FairOptions fo;
  fo.profile = profile;
  const FairSettings settings = resolve_settings(fo, source.font().units_per_em);
  const GlyphFairing r = fair_glyph(g, settings);
  ASSERT_TRUE(r.kept.empty()) << glyph << ": " << r.kept.front();
  ASSERT_EQ(r.glyph.outline.contours.size(), g.outline.contours.size());
  EXPECT_EQ(r.glyph.name, g.name);
  EXPECT_EQ(r.glyph.advance_width, g.advance_width);
  for (std::size_t i = 0; i < g.outline.contours.size(); ++i) {
    const Contour& a = g.outline.contours[i];
    const Contour& b = r.glyph.outline.contours[i];
    // 1 % slack for the sampled distance: 400 points per segment.
    EXPECT_LE(brute_force_hausdorff(a, b), 1.01 * settings.tolerance_units) << glyph << " contour " << i;
    EXPECT_EQ(signed_area(a) > 0, signed_area(b) > 0) << glyph << " contour " << i;
    for (std::size_t k = 0; k < b.segments.size(); ++k) {
      for_each_point(b.segments[k], [&](Vec2 p) { EXPECT_TRUE(p.x == std::round(p.x) && p.y == std::round(p.y)); });
      if (!b.nodes[k].smooth.value_or(false)) continue;
      const Segment& before = b.segments[(k + b.segments.size() - 1) % b.segments.size()];
      const Segment& after = b.segments[k];
      const Vec2 node = start_point(after);
      Vec2 in = node, out = node;
      for_each_point(before, [&](Vec2 p) { if (p != node) in = p; });
      bool first = true;
      for_each_point(after, [&](Vec2 p) { if (first && p != node) out = p, first = false; });
      EXPECT_EQ(cross(node - in, out - node), 0.0) << glyph << " node " << k;
    }
  }
}

TEST(ContourFairing, ProfessionalGlyphsAreFairedWithinTheTolerance) {
  for (const char* g : {"o", "e", "n", "S", "O", "D"}) expect_faired(test::dejavu, g, FairProfile::text);
}

TEST(ContourFairing, HandwritingGlyphsAreFairedWithinTheTolerance) {
  for (const char* g : {"o", "c", "C"}) expect_faired(test::because_we_learn, g, FairProfile::handwriting);
}

}  // namespace
}  // namespace gf
