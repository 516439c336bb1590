// Stem jogs: a line, then a flat S that a curve continues from, becomes one straight line
// halfway across the jog; a bend away from the line (a taper), a jog too wide or too steep, a
// flagged corner and a line of no length are left alone.
#include "fair/stem_jogs.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "point_set_distance.hpp"
#include "test_shapes.hpp"

namespace gf {
namespace {

std::vector<Vec2> dense(const Contour& c) { return test::contour_points(c, 200); }

// A stem down x = 100, a flat S two units over to x = 98, then a bowl round to a second stem.
Contour jogged(Cubic jog) {
  Contour c;
  c.segments = {Line{{{100, 1000}, {100, 800}}}, jog, Cubic{{{98, 500}, {98, 400}, {150, 350}, {250, 350}}},
                Line{{{250, 350}, {250, 1000}}}, Line{{{250, 1000}, {100, 1000}}}};
  c.nodes.assign(c.segments.size(), NodeFlags{});
  return c;
}

// `r`, `source` straightened once: the stem one line from (99, 1000) down to `foot`, half the
// 2-unit jog across; the bowl leaving it there along it, its first handle at `handle`; the top
// line ending on the stem; the outline within the move of the source.
void expect_one_stem(const Contour& source, const MovedContour& r, Vec2 foot, Vec2 handle) {
  ASSERT_EQ(r.changes, 1);
  EXPECT_DOUBLE_EQ(r.moved, 1.0);  // half the jog
  ASSERT_EQ(r.contour.segments.size(), 4u);
  const Line& stem = std::get<Line>(r.contour.segments[0]);
  EXPECT_EQ(stem.start(), (Vec2{99, 1000}));
  EXPECT_EQ(stem.end(), foot);
  const Cubic& bowl = std::get<Cubic>(r.contour.segments[1]);
  EXPECT_EQ(bowl.p[0], foot);
  EXPECT_EQ(bowl.p[1], handle);
  EXPECT_EQ(std::get<Line>(r.contour.segments[3]).end(), (Vec2{99, 1000}));
  EXPECT_LE(test::polyline_hausdorff(dense(source), dense(r.contour)), r.moved + 1e-9);
}

// `c` walked the other way.
Contour reversed(const Contour& c) {
  Contour out;
  for (auto s = c.segments.rbegin(); s != c.segments.rend(); ++s)
    out.segments.push_back(std::visit([](const auto& b) { return Segment{b.reversed()}; }, *s));
  out.nodes.assign(out.segments.size(), NodeFlags{});
  return out;
}

// Whether `c` has the line from `a` to `b`.
bool has_line(const Contour& c, Vec2 a, Vec2 b) {
  return std::any_of(c.segments.begin(), c.segments.end(), [&](const Segment& s) {
    const Line* l = std::get_if<Line>(&s);
    return l && l->start() == a && l->end() == b;
  });
}

TEST(StemJogs, AFlatSAfterAStemBecomesPartOfIt) {
  const Contour source = jogged(Cubic{{{100, 800}, {100, 700}, {98, 600}, {98, 500}}});
  const MovedContour r = straighten_stem_jogs(source, JogLimits{});
  ASSERT_NO_FATAL_FAILURE(expect_one_stem(source, r, {99, 500}, {99, 400}));
  EXPECT_EQ(std::get<Cubic>(r.contour.segments[1]).p[3], (Vec2{250, 350}));
}

TEST(StemJogs, TheSameReadBackwardsIsStraightenedToo) {
  // The contour reversed: the bowl, the S, then the stem.
  const MovedContour r = straighten_stem_jogs(reversed(jogged(Cubic{{{100, 800}, {100, 700}, {98, 600}, {98, 500}}})), JogLimits{});
  ASSERT_EQ(r.changes, 1);
  EXPECT_TRUE(has_line(r.contour, {99, 500}, {99, 1000}));
}

// Between two parallel lines a jog need not be an S: a stem down x = 100, a bend leaving it by
// 1.4° (a quadratic, as TrueType draws it) that straightens down x = 98, a line on down it,
// then a bowl (Liberation Sans Narrow's d: 674 units across, then 673). The two lines and the
// bend become one line halfway across, and the bowl leaves it where the second line ended.
TEST(StemJogs, ABendBetweenTwoParallelLinesBecomesOneLine) {
  const Vec2 p0{100, 800}, control{98, 720}, p3{98, 500};
  Contour c;
  c.segments = {Line{{{100, 1000}, p0}}, Cubic{{p0, p0 + (control - p0) * (2.0 / 3.0), p3 + (control - p3) * (2.0 / 3.0), p3}},
                Line{{p3, {98, 400}}}, Cubic{{{98, 400}, {98, 300}, {150, 250}, {250, 250}}},
                Line{{{250, 250}, {250, 1000}}}, Line{{{250, 1000}, {100, 1000}}}};
  c.nodes.assign(c.segments.size(), NodeFlags{});
  EXPECT_NO_FATAL_FAILURE(expect_one_stem(c, straighten_stem_jogs(c, JogLimits{}), {99, 400}, {99, 300}));
  // Read backwards, the same.
  const MovedContour b = straighten_stem_jogs(reversed(c), JogLimits{});
  ASSERT_EQ(b.changes, 1);
  ASSERT_EQ(b.contour.segments.size(), 4u);
  EXPECT_TRUE(has_line(b.contour, {99, 400}, {99, 1000}));
  // The second line leaning a unit farther across by its end: not parallel to the first, left alone.
  Contour apart = c;
  apart.segments[2] = Line{{p3, {97, 400}}};
  apart.segments[3] = Cubic{{{97, 400}, {97, 300}, {150, 250}, {250, 250}}};
  EXPECT_EQ(straighten_stem_jogs(apart, JogLimits{}).changes, 0);
}

TEST(StemJogs, ABendATooWideOrTooSteepJogAFlaggedCornerAndALineOfNoLengthAreLeft) {
  // A taper: the curve bends 2 units over and ends still bending (not back along the line).
  EXPECT_EQ(straighten_stem_jogs(jogged(Cubic{{{100, 800}, {100, 700}, {99.5, 600}, {98, 500}}}), JogLimits{}).changes, 0);
  // Four units across: past twice the limit of one unit.
  EXPECT_EQ(straighten_stem_jogs(jogged(Cubic{{{100, 800}, {100, 700}, {96, 600}, {96, 500}}}), JogLimits{}).changes, 0);
  JogLimits wide;
  wide.max_move_units = 2.0;
  EXPECT_EQ(straighten_stem_jogs(jogged(Cubic{{{100, 800}, {100, 700}, {96, 600}, {96, 500}}}), wide).changes, 1);
  // Twenty units over 300: steeper than the kink limit, a stroke's own slant.
  wide.max_move_units = 20.0;
  EXPECT_EQ(straighten_stem_jogs(jogged(Cubic{{{100, 800}, {100, 700}, {80, 600}, {80, 500}}}), wide).changes, 0);
  // A source that flags the line's end a corner.
  Contour flagged = jogged(Cubic{{{100, 800}, {100, 700}, {98, 600}, {98, 500}}});
  flagged.nodes[1].smooth = false;
  EXPECT_EQ(straighten_stem_jogs(flagged, JogLimits{}).changes, 0);
  // A contour closed on a line of no length (Lato's N) has no direction there to read.
  Contour closed_on_nothing = jogged(Cubic{{{100, 800}, {100, 700}, {98, 600}, {98, 500}}});
  closed_on_nothing.segments.insert(closed_on_nothing.segments.begin(), Line{{{100, 1000}, {100, 1000}}});
  closed_on_nothing.nodes.push_back(NodeFlags{});
  EXPECT_EQ(straighten_stem_jogs(closed_on_nothing, JogLimits{}).changes, 1);
}

}  // namespace
}  // namespace gf
