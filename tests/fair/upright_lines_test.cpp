// Nearly upright lines a curve meets tangentially stand on the axis before the fairing: the
// line turned about its middle, each end moved across the axis only, a curve's handle moved
// with its node and onto the axis, or parallel where that moves too far and the curve turns far
// more than the lean; steep slants, corners, kinks between lines and handles that would move
// too far are left.
#include "fair/upright_lines.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "geom/curvature.hpp"
#include "point_set_distance.hpp"
#include "test_shapes.hpp"

namespace gf {
namespace {

std::vector<Vec2> dense(const Contour& c) { return test::contour_points(c, 200); }

TEST(UprightLines, AStemOffTheVerticalStandsUpright) {
  const Contour source = test::comic_neue_i_stem();
  const MovedContour r = stand_lines_upright(source, UprightLimits{});
  ASSERT_EQ(r.changes, 2);
  EXPECT_DOUBLE_EQ(r.moved, 3.0);  // half of each line's 6 units across
  for (const std::size_t i : {1u, 4u}) {
    const Line& line = std::get<Line>(r.contour.segments[i]);
    const Line& was = std::get<Line>(source.segments[i]);
    EXPECT_DOUBLE_EQ(line.start().x, line.end().x);
    EXPECT_DOUBLE_EQ(line.start().x, 0.5 * (was.start().x + was.end().x));
    EXPECT_DOUBLE_EQ(line.start().y, was.start().y);  // the ends keep their heights
    EXPECT_DOUBLE_EQ(line.end().y, was.end().y);
  }
  // The curves keep their tangents where they meet the lines, and their far ends.
  // (Comic Neue's caps already leave vertically, so turning their handles onto the axis keeps them.)
  for (std::size_t i = 0; i < source.segments.size(); ++i) {
    if (is_line(source.segments[i])) continue;
    for (const SegmentEnd end : {SegmentEnd::start, SegmentEnd::end}) {
      const Vec2 a = *end_tangent(source.segments[i], end), b = *end_tangent(r.contour.segments[i], end);
      EXPECT_NEAR(turning_angle(a, b), 0.0, 1e-12) << i;
    }
  }
  EXPECT_EQ(start_point(r.contour.segments[0]), start_point(source.segments[0]));
  EXPECT_EQ(end_point(r.contour.segments[2]), end_point(source.segments[2]));
  // Nothing moved further than it said.
  EXPECT_LE(test::polyline_hausdorff(dense(source), dense(r.contour)), r.moved + 1e-9);
}

TEST(UprightLines, ALineMovingTooFarOrTooSteepKeepsItsSlant) {
  const Contour source = test::comic_neue_i_stem();
  UprightLimits tight;
  tight.max_move_units = 2.9;
  EXPECT_EQ(stand_lines_upright(source, tight).changes, 0);
  EXPECT_EQ(stand_lines_upright(source, tight).contour, source);
  UprightLimits steep;
  steep.max_angle_deg = 0.7;  // the stem leans 0.79°
  EXPECT_EQ(stand_lines_upright(source, steep).changes, 0);
}

TEST(UprightLines, ALongHandleStaysParallelWhereItsCurveTurnsFarMore) {
  // The stem of ALineAtCorners… leaning 0.38°, and a curve whose handle, 600 units along the
  // lean, would move 4 units turned onto the vertical: the handle moves with its node,
  // parallel, and the fairing turns the curve's end by the 0.38° (Heros's R leg).
  Contour stem;
  stem.segments = {Line{{{0, 0}, {60, 0}}}, Line{{{60, 0}, {62, 300}}},
                   Cubic{{{62, 300}, {66, 900}, {10, 330}, {0, 300}}}, Line{{{0, 300}, {0, 0}}}};
  stem.nodes.assign(4, NodeFlags{});
  const MovedContour stood = stand_lines_upright(stem, UprightLimits{});
  ASSERT_EQ(stood.changes, 1);
  EXPECT_EQ(std::get<Line>(stood.contour.segments[1]).end(), (Vec2{61, 300}));
  const Cubic& curve = std::get<Cubic>(stood.contour.segments[2]);
  EXPECT_EQ(curve.p[1] - curve.p[0], (Vec2{4, 600}));
  EXPECT_DOUBLE_EQ(stood.moved, 1.0);
  // A curve that turns by less than four times the lean (a flat bar: Caladea's z foot) would
  // take an S from it: the line keeps its slant.
  Contour flat = stem;
  flat.segments[2] = Cubic{{{62, 300}, {66, 900}, {71, 1500}, {76, 2100}}};
  flat.segments[3] = Line{{{76, 2100}, {0, 0}}};
  EXPECT_EQ(stand_lines_upright(flat, UprightLimits{}).changes, 0);
}

TEST(UprightLines, StemsUpToTwoAndAHalfDegreesOffStandUpright) {
  // 434-unit stems leaning 2.3° (17.43 units) stand up, each end moving 8.7 units; at 2.6°
  // they are a slant the grid can step along.
  UprightLimits far;
  far.max_move_units = 12.0;
  const double height = 434.0;
  EXPECT_EQ(stand_lines_upright(test::round_ended_stem(height * std::tan(radians(2.3))), far).changes, 2);
  EXPECT_EQ(stand_lines_upright(test::round_ended_stem(height * std::tan(radians(2.6))), far).changes, 0);
}

TEST(UprightLines, ALineAtCornersOrBesideALineOnItsAxisKeepsItsSlant) {
  // A slanted stem on a baseline, reaching a curve at a 40° corner: no tangential curve.
  Contour corner;
  corner.segments = {Line{{{0, 0}, {60, 0}}}, Line{{{60, 0}, {62, 300}}},
                     Cubic{{{62, 300}, {40, 330}, {10, 330}, {0, 300}}}, Line{{{0, 300}, {0, 0}}}};
  corner.nodes.assign(4, NodeFlags{});
  EXPECT_EQ(stand_lines_upright(corner, UprightLimits{}).changes, 0);
  // The same stem meeting the curve tangentially stands upright; the baseline stays level.
  Contour tangent = corner;
  tangent.segments[2] = Cubic{{{62, 300}, {62.2, 330}, {10, 330}, {0, 300}}};
  const MovedContour stood = stand_lines_upright(tangent, UprightLimits{});
  ASSERT_EQ(stood.changes, 1);
  EXPECT_EQ(std::get<Line>(stood.contour.segments[0]).end(), (Vec2{61, 0}));
  EXPECT_EQ(std::get<Line>(stood.contour.segments[1]).end(), (Vec2{61, 300}));
  // The curve leaves the upright line along it, its handle as long as it was.
  const Cubic& top = std::get<Cubic>(stood.contour.segments[2]);
  EXPECT_EQ(top.p[1].x, 61.0);
  EXPECT_NEAR(top.p[1].y - 300.0, distance(Vec2{62, 300}, Vec2{62.2, 330}), 1e-12);
  // A flag saying corner is a corner, whatever the angle.
  Contour flagged = tangent;
  flagged.nodes[2].smooth = false;
  EXPECT_EQ(stand_lines_upright(flagged, UprightLimits{}).changes, 0);
  // Below it a line 1.6° further round: a kink between two lines, the fillet pass's to mend.
  Contour kinked;
  kinked.segments = {Line{{{0, -290}, {50, -290}}}, Line{{{50, -290}, {60, 0}}}, tangent.segments[1],
                     tangent.segments[2], Line{{{0, 300}, {0, -290}}}};
  kinked.nodes.assign(5, NodeFlags{});
  EXPECT_EQ(stand_lines_upright(kinked, UprightLimits{}).changes, 0);
}

}  // namespace
}  // namespace gf
