// Every check on a glyph made to trigger it and on one made not to.
#include "check/contour_checks.hpp"

#include "geom/bspline_fit.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "test_shapes.hpp"

namespace gf {
namespace {

FontInfo font(bool truetype = false) {
  FontInfo f;
  f.units_per_em = 1000;
  f.outer_contours_clockwise = truetype;
  return f;
}

using test::closed;

// A counter-clockwise square (a PostScript outer contour).
Contour square(double x0 = 0, double y0 = 0, double size = 400) {
  const Vec2 a{x0, y0}, b{x0 + size, y0}, c{x0 + size, y0 + size}, d{x0, y0 + size};
  return closed({Line{a, b}, Line{b, c}, Line{c, d}, Line{d, a}});
}

// A circle-like contour from four cubics with nodes at its extrema, counter-clockwise.
Contour circle(double r = 200, Vec2 o = {300, 300}, double k = 0.5522847498307936) {
  const Vec2 e{o.x + r, o.y}, n{o.x, o.y + r}, w{o.x - r, o.y}, s{o.x, o.y - r};
  return closed({Cubic{e, {e.x, e.y + k * r}, {n.x + k * r, n.y}, n}, Cubic{n, {n.x - k * r, n.y}, {w.x, w.y + k * r}, w},
                 Cubic{w, {w.x, w.y - k * r}, {s.x - k * r, s.y}, s}, Cubic{s, {s.x + k * r, s.y}, {e.x, e.y - k * r}, e}});
}

Glyph glyph(std::vector<Contour> contours) {
  Glyph g;
  g.name = "test";
  g.outline.contours = std::move(contours);
  return g;
}

int count(const GlyphReport& r, const std::string& check) {
  return static_cast<int>(std::count_if(r.findings.begin(), r.findings.end(), [&](const Finding& f) { return f.check == check; }));
}

GlyphReport run(const Glyph& g, const FontInfo& f = font()) { return check_glyph(g, f, *check_profile("text")); }

TEST(Checks, CleanShapesHaveNoFindings) {
  for (const Glyph& g : {glyph({square()}), glyph({circle()})}) {
    const GlyphReport r = run(g);
    for (const Finding& f : r.findings)
      ADD_FAILURE() << f.check << " on a clean shape: " << f.message;
  }
}

TEST(Checks, OpenContour) {
  Contour c = square();
  c.closed = false;
  c.segments.pop_back();
  c.nodes.assign(c.segments.size() + 1, NodeFlags{});
  EXPECT_EQ(count(run(glyph({c})), "open-contour"), 1);
  EXPECT_EQ(count(run(glyph({square()})), "open-contour"), 0);
}

TEST(Checks, WrongDirectionDependsOnTheFormatAndNesting) {
  // Counter-clockwise outer: right for PostScript outlines, wrong for TrueType.
  EXPECT_EQ(count(run(glyph({square()})), "wrong-direction"), 0);
  EXPECT_EQ(count(run(glyph({square()}), font(true)), "wrong-direction"), 1);
  // A hole must run the other way from its container.
  EXPECT_EQ(count(run(glyph({square(0, 0, 400), square(100, 100, 100)})), "wrong-direction"), 1);
  Contour hole = square(100, 100, 100);
  std::reverse(hole.segments.begin(), hole.segments.end());
  for (Segment& s : hole.segments) std::get<Line>(s) = Line{std::get<Line>(s).p[1], std::get<Line>(s).p[0]};
  EXPECT_EQ(count(run(glyph({square(0, 0, 400), hole})), "wrong-direction"), 0);
}

TEST(Checks, DuplicatePoint) {
  Contour c = square();
  c.segments.insert(c.segments.begin() + 1, Line{{400, 0}, {400, 0}});
  c.nodes.push_back({});
  EXPECT_EQ(count(run(glyph({c})), "duplicate-point"), 1);
}

TEST(Checks, KinkBetweenFiveHundredthsAndThreeDegrees) {
  for (const auto& [deg, expected] : {std::pair{1.0, 1}, {0.04, 0}, {3.5, 0}}) {
    const double a = deg * std::numbers::pi / 180.0;
    const Vec2 p0{0, 0}, p1{300, 0}, p2{300 + 300 * std::cos(a), 300 * std::sin(a)};
    const GlyphReport r = run(glyph({closed({Line{p0, p1}, Line{p1, p2}, Cubic{p2, {600, 500}, {0, 500}, p0}})}));
    EXPECT_EQ(count(r, "kink"), expected) << deg;
  }
}

TEST(Checks, G2JumpAtALineCurveJoinButNotOnACircle) {
  // A line flowing tangentially into a quarter circle: curvature jumps from 0 to 1/r.
  const double k = 0.5522847498307936, r = 200;
  const Contour c = closed({Line{{0, 0}, {300, 0}}, Cubic{{300, 0}, {300 + k * r, 0}, {500, r - k * r}, {500, r}},
                            Line{{500, r}, {0, 0}}});
  EXPECT_GE(count(run(glyph({c})), "g2-jump"), 1);
  EXPECT_EQ(count(run(glyph({circle()})), "g2-jump"), 0);
}

TEST(Checks, MissingExtremumInsideASegment) {
  // An arch from (0,0) to (400,0) whose top is inside the one cubic: no node there.
  const Contour arch = closed({Cubic{{0, 0}, {0, 300}, {400, 300}, {400, 0}}, Line{{400, 0}, {0, 0}}});
  const GlyphReport r = run(glyph({arch}));
  ASSERT_EQ(count(r, "missing-extremum"), 1);
  EXPECT_NEAR(r.findings[0].t.value_or(0.0) + 0.0, 0.5, 0.5);
  EXPECT_EQ(count(run(glyph({circle()})), "missing-extremum"), 0);  // nodes at the extrema
}

TEST(Checks, InflectionInSegmentWithItsT) {
  const Contour s = closed({Cubic{{0, 0}, {200, 300}, {200, -300}, {400, 0}}, Line{{400, 0}, {400, -100}},
                            Line{{400, -100}, {0, -100}}, Line{{0, -100}, {0, 0}}});
  const GlyphReport r = run(glyph({s}));
  ASSERT_EQ(count(r, "inflection-in-segment"), 1);
  for (const Finding& f : r.findings)
    if (f.check == "inflection-in-segment") {
      EXPECT_NEAR(*f.t, 0.5, 1e-12);
    }
  EXPECT_EQ(count(run(glyph({circle()})), "inflection-in-segment"), 0);
}

TEST(Checks, WobbleIsASecondCurvatureExtremumBetweenInflections) {
  // y = 100 sin(x/100) has inflections at multiples of 100π and one curvature extremum
  // between them. A ripple 0.02·sin 5x adds curvature extrema (y''' = cos x + 2.5 cos 5x has
  // more zeros) but no inflection (y'' = sin x + 0.5 sin 5x keeps its sign on (0, π)).
  const auto wave = [](double ripple) {
    std::vector<Vec2> pts;
    for (int i = 0; i <= 600; ++i) {
      const double x = -0.4 + (2 * std::numbers::pi + 0.8) * i / 600;
      pts.push_back({100 * x, 100 * (std::sin(x) + ripple * std::sin(5 * x))});
    }
    const BSplineFit fit = fit_cubic_bspline_within(pts, 1e-3);
    Contour c;
    c.closed = false;
    c.segments.assign(fit.spans.begin(), fit.spans.end());
    c.nodes.assign(c.segments.size() + 1, NodeFlags{});
    return c;
  };
  EXPECT_EQ(count(run(glyph({wave(0.0)})), "wobble"), 0);
  EXPECT_EQ(count(run(glyph({wave(0.02)})), "wobble"), 2);  // one for each pair of inflections
}

TEST(Checks, ShortSegment) {
  Contour c = square();
  c.segments[1] = Line{{400, 0}, {402, 1}};
  c.segments.insert(c.segments.begin() + 2, Line{{402, 1}, {400, 400}});
  c.nodes.push_back({});
  EXPECT_EQ(count(run(glyph({c})), "short-segment"), 1);
}

TEST(Checks, ZeroHandleAndCollinearHandles) {
  const Contour retracted = closed({Cubic{{0, 0}, {0, 0}, {400, 300}, {400, 0}}, Line{{400, 0}, {0, 0}}});
  EXPECT_EQ(count(run(glyph({retracted})), "zero-handle"), 1);
  const Contour straight = closed({Cubic{{0, 0}, {100, 0}, {300, 0}, {400, 0}}, Line{{400, 0}, {400, 300}},
                                   Line{{400, 300}, {0, 0}}});
  EXPECT_EQ(count(run(glyph({straight})), "collinear-handles"), 1);
  EXPECT_EQ(count(run(glyph({circle()})), "zero-handle") + count(run(glyph({circle()})), "collinear-handles"), 0);
}

TEST(Checks, SemiHorizontalAndSemiVerticalLines) {
  const Contour c = closed({Line{{0, 0}, {400, 2}}, Line{{400, 2}, {401, 400}}, Line{{401, 400}, {0, 400}}, Line{{0, 400}, {0, 0}}});
  const GlyphReport r = run(glyph({c}));
  EXPECT_EQ(count(r, "semi-horizontal"), 1);
  EXPECT_EQ(count(r, "semi-vertical"), 1);
  FontInfo italic = font();
  italic.italic_angle = -12;
  EXPECT_EQ(count(run(glyph({c}), italic), "semi-vertical"), 0);  // slanted stems are by design
}

TEST(Checks, HandwritingProfileRelaxesAndSaysSo) {
  const auto hand = *check_profile("handwriting");
  EXPECT_EQ(hand.severity_of("kink"), Severity::info);
  EXPECT_EQ(hand.severity_of("open-contour"), Severity::error);
  EXPECT_FALSE(hand.relaxed.empty());
  EXPECT_FALSE(check_profile("poster").has_value());
}

TEST(Fairness, CircleIsMonotoneFreeAndTheTotalVariationIsExact) {
  // A cubic quarter circle's κ runs 0.978 → 1.0001 → 0.9938 (its minimum) → back: the total
  // variation is the sum of those swings, computed at the extrema, times UPM.
  const GlyphReport r = run(glyph({circle(200)}));
  EXPECT_EQ(r.fairness.inflections, 0);
  EXPECT_EQ(r.fairness.curvature_extrema, 16);  // three inside each quarter, a minimum at each node
  EXPECT_EQ(r.fairness.monotone_fraction, 0.0);
  EXPECT_GT(r.fairness.total_variation, 0.0);
  EXPECT_LT(r.fairness.total_variation, 4 * 4 * 0.03 / 200 * 1000);
  // A square has no curves: nothing varies.
  const GlyphReport s = run(glyph({square()}));
  EXPECT_EQ(s.fairness.total_variation, 0.0);
  EXPECT_EQ(s.fairness.monotone_fraction, 1.0);
}

}  // namespace
}  // namespace gf
