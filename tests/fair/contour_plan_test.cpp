// Planning a contour: which joins are corners, and the joins the caller makes smooth.
#include "fair/contour_plan.hpp"

#include <gtest/gtest.h>

namespace gf {
namespace {

// A closed contour: a line from (0, 0) to (100, 0), then a curve leaving it turned up by
// `degrees`, a curve back down, and a line home to the start.
Contour line_then_curves(double degrees) {
  const double a = degrees * std::numbers::pi / 180.0;
  const Vec2 p0{0, 0}, p1{100, 0}, p2{200, 100}, p3{100, 200};
  Contour c;
  c.segments = {Line{p0, p1}, Cubic{p1, p1 + Vec2{std::cos(a), std::sin(a)} * 40.0, p2 - Vec2{0, 40}, p2},
                Cubic{p2, p2 + Vec2{0, 40}, p3 + Vec2{40, 0}, p3}, Line{p3, p0}};
  c.nodes.resize(4);
  return c;
}

TEST(ContourPlan, ALineJoinBeyondTheKinkLimitIsACornerUnlessMadeSmooth) {
  const Contour c = line_then_curves(10.0);
  const ContourPlan plain = plan_contour(c, {}, {30.0});
  ASSERT_EQ(plain.pieces.size(), 3u);  // line, run, line
  EXPECT_EQ(plain.start_nodes, (std::vector<std::size_t>{0, 1, 3}));
  const SmoothRun& run = std::get<SmoothRun>(plain.pieces[1]);
  EXPECT_EQ(run.start.kind, RunEndKind::corner);  // 10° from the line: kept

  const std::vector<std::size_t> smooth{1};
  const ContourPlan made = plan_contour(c, smooth, {30.0});
  const SmoothRun& joined = std::get<SmoothRun>(made.pieces[1]);
  EXPECT_EQ(joined.start.kind, RunEndKind::line);  // now it leaves the line tangentially
  EXPECT_NEAR(joined.start.tangent.x, 1.0, 1e-12);  // in the line's direction
  EXPECT_EQ(joined.end.kind, RunEndKind::corner);
}

// A closed contour: a curve down from (0, 100) that reaches (100, 0) level, a line of
// `stub` units on along the level, a corner up to (100 + stub, 100), and a line home.
Contour curve_onto_stub_line(double stub) {
  const Vec2 top{0, 100}, foot{100, 0}, end{100 + stub, 0}, up{100 + stub, 100};
  Contour c;
  c.segments = {Cubic{top, top + Vec2{0, -60}, foot - Vec2{60, 0}, foot}, Line{foot, end}, Line{end, up}, Line{up, top}};
  c.nodes.resize(4);
  return c;
}

TEST(ContourPlan, ALineUnderTwoUnitsBetweenACurveAndACornerIsTheCurvesLastStretch) {
  // A one-unit line that the curve meets level, then a corner: no curve leaves such a line
  // with κ = 0 within it (Linux Biolinum's f), so it is the run's last cubic, drawn straight,
  // and the run ends at the corner.
  const ContourPlan plan = plan_contour(curve_onto_stub_line(1.0), {}, {3.0});
  ASSERT_EQ(plan.pieces.size(), 3u);  // the run, the line up, the line home
  const SmoothRun& run = std::get<SmoothRun>(plan.pieces[0]);
  ASSERT_EQ(run.cubics.size(), 2u);
  EXPECT_TRUE(is_straight(run.cubics[1]));
  EXPECT_EQ(run.cubics[1].p[3], (Vec2{101, 0}));
  EXPECT_EQ(run.end.kind, RunEndKind::corner);
  EXPECT_EQ(run.end.tangent, (Vec2{1, 0}));
  // Two units and longer, it is a line the run meets tangentially.
  const ContourPlan longer = plan_contour(curve_onto_stub_line(2.0), {}, {3.0});
  ASSERT_EQ(longer.pieces.size(), 4u);
  const SmoothRun& meets = std::get<SmoothRun>(longer.pieces[0]);
  EXPECT_EQ(meets.cubics.size(), 1u);
  EXPECT_EQ(meets.end.kind, RunEndKind::line);
  EXPECT_TRUE(std::holds_alternative<Line>(longer.pieces[1]));
}

TEST(ContourPlan, ALineUnderTheStubLengthGivenIsTheCurvesToo) {
  // Handwriting's stub length is twice its tolerance (fair_options): a 20-unit line the curve
  // meets level is its last stretch under a stub length of 28, a line under 20.
  PlanOptions hand{30.0};
  hand.stub_line_units = 28.0;
  const ContourPlan plan = plan_contour(curve_onto_stub_line(20.0), {}, hand);
  ASSERT_EQ(plan.pieces.size(), 3u);
  const SmoothRun& run = std::get<SmoothRun>(plan.pieces[0]);
  ASSERT_EQ(run.cubics.size(), 2u);
  EXPECT_TRUE(is_straight(run.cubics[1]));
  EXPECT_EQ(run.cubics[1].p[3], (Vec2{120, 0}));
  EXPECT_EQ(run.end.kind, RunEndKind::corner);
  hand.stub_line_units = 20.0;
  EXPECT_EQ(plan_contour(curve_onto_stub_line(20.0), {}, hand).pieces.size(), 4u);
}

TEST(ContourPlan, AStubLineMetAtAKinkIsTheCurvesWithinTheStubTurn) {
  // The curve arrives 13° below the level of its 10-unit line: a corner to a line, unless the
  // stub turn (handwriting: half its corner angle) allows it.
  Contour c = curve_onto_stub_line(10.0);
  const Vec2 foot{100, 0}, arrival{std::cos(radians(13.0)), -std::sin(radians(13.0))};
  std::get<Cubic>(c.segments[0]).p[2] = foot - arrival * 60.0;
  PlanOptions hand{30.0};
  hand.stub_line_units = 28.0;
  EXPECT_EQ(plan_contour(c, {}, hand).pieces.size(), 4u);
  hand.stub_turn_deg = 15.0;
  const ContourPlan plan = plan_contour(c, {}, hand);
  ASSERT_EQ(plan.pieces.size(), 3u);
  const SmoothRun& run = std::get<SmoothRun>(plan.pieces[0]);
  ASSERT_EQ(run.cubics.size(), 2u);
  EXPECT_TRUE(is_straight(run.cubics[1]));
  hand.stub_turn_deg = 10.0;
  EXPECT_EQ(plan_contour(c, {}, hand).pieces.size(), 4u);
}

TEST(ContourPlan, CornersThatStaySayWhatLiesBeyondThem) {
  // line_then_curves(10°): the run leaves the first line at a corner of 10° and meets the
  // closing line at (100, 200) at another; each of its ends says the line's direction beyond.
  const Contour c = line_then_curves(10.0);
  const ContourPlan plan = plan_contour(c, {}, {30.0, true});
  const SmoothRun& run = std::get<SmoothRun>(plan.pieces[1]);
  ASSERT_EQ(run.start.kind, RunEndKind::corner);
  EXPECT_EQ(run.start.beyond, (Vec2{1, 0}));  // the line it leaves
  EXPECT_TRUE(run.start.beyond_line);
  ASSERT_EQ(run.end.kind, RunEndKind::corner);
  const Vec2 home = Vec2{-100, -200} / norm(Vec2{-100, -200});
  EXPECT_NEAR(run.end.beyond.x, home.x, 1e-12);  // the line it reaches
  EXPECT_NEAR(run.end.beyond.y, home.y, 1e-12);
  EXPECT_TRUE(run.end.beyond_line);
  // Where corners need not stay (handwriting), nothing is said.
  const SmoothRun& free = std::get<SmoothRun>(plan_contour(c, {}, {30.0}).pieces[1]);
  EXPECT_EQ(free.start.beyond, Vec2{});
  EXPECT_EQ(free.end.beyond, Vec2{});
}

TEST(ContourPlan, AStubHandleBesideALineIsACornerTowardsTheNextControlPoint) {
  // Inconsolata's q: the bowl leaves the stem along it with a 0.4-unit handle (0.26 % of its
  // chord), then turns up and left at once; drawn, that is a corner of about 158°.
  Contour c;
  const Vec2 a{373.7, 456.5}, b{373.7, 390.1}, next{341.9, 468.7}, d{240.5, 468.7};
  c.segments = {Line{a, b}, Cubic{b, b + Vec2{0, -0.4}, next, d}, Line{d, a}};
  c.nodes.resize(3);
  const ContourPlan plan = plan_contour(c, {}, {3.0});
  ASSERT_EQ(plan.pieces.size(), 3u);
  const SmoothRun& run = std::get<SmoothRun>(plan.pieces[1]);
  EXPECT_EQ(run.start.kind, RunEndKind::corner);
  const Vec2 towards = (next - b) / norm(next - b);
  EXPECT_NEAR(run.start.tangent.x, towards.x, 1e-12);
  EXPECT_NEAR(run.start.tangent.y, towards.y, 1e-12);
  EXPECT_EQ(run.cubics.front().p[1], b);  // the stub retracted onto its node

  // A handle of 2 % of the chord is the designer's tangent: a line join, as drawn.
  std::get<Cubic>(c.segments[1]).p[1] = b + Vec2{0, -0.02 * norm(d - b)};
  const SmoothRun& kept = std::get<SmoothRun>(plan_contour(c, {}, {3.0}).pieces[1]);
  EXPECT_EQ(kept.start.kind, RunEndKind::line);
}

TEST(ContourPlan, ACurveMeetsALineTangentiallyWithinTheGivenAngle) {
  // A curve leaving a line at 0.8° (Comic Neue's u: its stem's line against the curve's
  // vertical tangent): a line join by default (within the kink limit), a corner where curves
  // meet lines tangentially only within 0.05°.
  Contour c;
  const Vec2 a{4, 305}, b{0, 0}, d{-100, -100};
  c.segments = {Line{a, b}, Cubic{b, Vec2{0, -40}, Vec2{-60, -100}, d}, Line{d, a}};
  c.nodes.resize(3);
  EXPECT_EQ(std::get<SmoothRun>(plan_contour(c, {}, {3.0}).pieces[1]).start.kind, RunEndKind::line);
  EXPECT_EQ(std::get<SmoothRun>(plan_contour(c, {}, {3.0, false, 0.05}).pieces[1]).start.kind, RunEndKind::corner);
}

TEST(ContourPlan, TwoLinesMadeSmoothAreOneLine) {
  // A quadrilateral whose bottom edge bends by 1° at (100, 0.87).
  Contour c;
  const Vec2 a{0, 0}, b{100, 1.745}, d{200, 0}, e{100, 150};
  c.segments = {Line{a, b}, Line{b, d}, Line{d, e}, Line{e, a}};
  c.nodes.resize(4);
  EXPECT_EQ(plan_contour(c, {}, {30.0}).pieces.size(), 4u);  // two lines meeting are always a corner
  const std::vector<std::size_t> smooth{1};
  const ContourPlan made = plan_contour(c, smooth, {30.0});
  ASSERT_EQ(made.pieces.size(), 3u);
  const Line& merged = std::get<Line>(made.pieces[0]);
  EXPECT_EQ(merged.start(), a);
  EXPECT_EQ(merged.end(), d);
  // At the seam of a closed contour too.
  const std::vector<std::size_t> seam{0};
  const ContourPlan wrapped = plan_contour(c, seam, {30.0});
  ASSERT_EQ(wrapped.pieces.size(), 3u);
  EXPECT_EQ(std::get<Line>(wrapped.pieces[0]).start(), e);
  EXPECT_EQ(std::get<Line>(wrapped.pieces[0]).end(), b);
}

TEST(ContourPlan, StraightQuadraticsAndCubicsAreWrittenAsTheirLines) {
  // Liberation Sans Narrow's V draws its inner vertex with quadratics whose control point sits
  // on their start; a cubic with its handles on its chord is a line too, and a bent one is not.
  Contour c;
  c.segments = {Quad{{{0, 0}, {0, 0}, {24, -89}}}, Cubic{{{24, -89}, {34, -89}, {74, -89}, {124, -89}}},
                Quad{{{124, -89}, {140, -40}, {100, 0}}}, Line{{100, 0}, {0, 0}}};
  c.nodes.resize(4);
  const Contour lines = with_straight_segments_as_lines(c);
  EXPECT_EQ(lines.segments[0], (Segment{Line{{0, 0}, {24, -89}}}));
  EXPECT_EQ(lines.segments[1], (Segment{Line{{24, -89}, {124, -89}}}));
  EXPECT_EQ(lines.segments[2], c.segments[2]);
  EXPECT_EQ(lines.segments[3], c.segments[3]);
  EXPECT_EQ(lines.nodes, c.nodes);
}

}  // namespace
}  // namespace gf
