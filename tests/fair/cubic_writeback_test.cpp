// The cubic writeback of a faired chain: an extremum a few units from a corner, and one beside
// a corner drawn; the shortest span it halves; a corner's free curvature; a nearly straight
// stroke cut where it runs along a longer grid direction, or evenly along it; a cubic crossing
// an axis inside; an extremum's curvature moved so that its spans fit whole.
#include "fair/cubic_writeback.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "aesthetic/segment_fit.hpp"
#include "fair/cubic_change.hpp"
#include "geom/curvature.hpp"
#include "point_set_distance.hpp"

namespace gf {
namespace {

// The chain as one log-aesthetic segment (α `alpha`) from (100, 0), leaving `lean_deg` right
// of the vertical along a first leg of its control triangle and turning left by `turn_deg`
// along the second; no segment where none fits.
struct Stroke {
  double lean_deg = 2.0, turn_deg = 60.0, first_leg = 100.0, second_leg = 100.0, alpha = 1.0;
};
FairedChain stroke_leaving_a_corner(const Stroke& s) {
  const double lean = radians(s.lean_deg), turn = radians(s.turn_deg);
  const Vec2 p0{100, 0}, p1 = p0 + Vec2{std::sin(lean), std::cos(lean)} * s.first_leg;
  const Vec2 p2 = p1 + Vec2{std::sin(lean - turn), std::cos(lean - turn)} * s.second_leg;
  const SegmentFit fit = fit_three_point(p0, p1, p2, s.alpha);
  FairedChain chain;
  if (fit.ok()) chain.segments.push_back(*fit.segment);
  return chain;
}
// Turning left by 60° over legs of 100 units: at 2°, its vertical extremum lies about 10 units
// from the corner.
FairedChain stroke_leaving_a_corner(double lean_deg = 2.0) { return stroke_leaving_a_corner(Stroke{.lean_deg = lean_deg}); }

// The point of `c` farthest right (of 4001 samples).
Vec2 rightmost_point(const Cubic& c) {
  Vec2 out = c.p[0];
  for (int i = 0; i <= 4000; ++i)
    if (const Vec2 q = c.point_at(i / 4000.0); q.x > out.x) out = q;
  return out;
}

TEST(CubicWriteback, AnExtremumNextToACornerIsTheCorner) {
  const FairedChain chain = stroke_leaving_a_corner();
  ASSERT_EQ(chain.segments.size(), 1u);
  const double budget = 2.0, flat = 5e-4;
  // As a smooth end (or a corner left alone): a node at the extremum, a few units up.
  const ChainCubics kept = write_chain_as_cubics(chain, budget, flat);
  ASSERT_GE(kept.nodes.size(), 3u);
  EXPECT_LT(distance(kept.nodes[1].point, kept.nodes[0].point), 20.0);
  ASSERT_TRUE(kept.nodes[1].grid_step);
  EXPECT_EQ(*kept.nodes[1].grid_step, (Vec2{0, 1}));
  // At a corner: the corner's tangent turns onto the vertical and the extremum's node goes.
  const ChainCubics snapped = write_chain_as_cubics(chain, budget, flat, {.start_corner = true, .start_axis = {}, .end_axis = {}});
  ASSERT_GE(snapped.nodes.size(), 2u);
  EXPECT_LT(snapped.nodes.size(), kept.nodes.size());
  const OutlineNode& corner = snapped.nodes.front();
  EXPECT_EQ(corner.point, kept.nodes.front().point);
  ASSERT_TRUE(corner.out_handle && corner.grid_step);
  EXPECT_NEAR(corner.out_handle->x, corner.point.x, 1e-9);
  EXPECT_GT(corner.out_handle->y, corner.point.y);
  EXPECT_EQ(*corner.grid_step, (Vec2{0, 1}));
  for (std::size_t k = 1; k < snapped.nodes.size(); ++k) EXPECT_GT(distance(snapped.nodes[k].point, corner.point), 20.0);
  // The end of the chain is no corner: its node stays where the chain ends.
  EXPECT_EQ(snapped.nodes.back().point, kept.nodes.back().point);
}

// A corner drawn turning by 14° (arriving up the vertical, leaving 14° right of it), faired to
// leave 5° right of it, its vertical extremum 15 units on: as Accanthis's serif tips (drawn
// 14°, faired 9°). Turned onto the vertical, as a corner with no drawn turn is, it would turn
// by nothing, and the kink pass would make it smooth. A corner drawn turning by the kink limit
// or more is turned only as far as its floor allows (kept_corner_angle), here not at all, and
// the extremum, more than one grid place across, keeps its node.
TEST(CubicWriteback, ACornerDrawnWideIsNotTurnedOntoTheAxis) {
  const FairedChain chain = stroke_leaving_a_corner(5.0);
  ASSERT_EQ(chain.segments.size(), 1u);
  const double budget = 2.0, flat = 5e-4;
  const ChainCubics snapped = write_chain_as_cubics(chain, budget, flat, {.start_corner = true, .start_axis = {}, .end_axis = {}});
  ASSERT_EQ(snapped.nodes.size(), 2u);  // turned onto the vertical, the extremum's node gone
  RunEnd drawn;
  drawn.tangent = direction_of(radians(90.0 - 14.0));
  drawn.beyond = Vec2{0, 1};
  ChainEnds ends{.start_corner = true, .start_axis = {}, .end_axis = {}};
  ends.start_run_end = drawn;
  const ChainCubics kept = write_chain_as_cubics(chain, budget, flat, ends);
  EXPECT_EQ(kept.nodes.size(), snapped.nodes.size() + 1);
  const OutlineNode& corner = kept.nodes.front();
  ASSERT_TRUE(corner.out_handle);
  const Vec2 leaves = *corner.out_handle - corner.point;
  EXPECT_NEAR(turning_angle(Vec2{0, 1}, leaves), radians(-5.0), 1e-6);
  ASSERT_TRUE(kept.nodes[1].grid_step);
  EXPECT_EQ(*kept.nodes[1].grid_step, (Vec2{0, 1}));
}

// A corner drawn turning by 4.6° (over the check's 3°), faired to leave 4.2° right of the
// vertical and turning left round within 60 units, so that its vertical extremum lies a few
// units on and 0.08 units across (TeX Gyre Bonum's e: 4 units on, 0.15 across).
// Turned onto the vertical it would turn by nothing and be lost; kept, the extremum's node
// would leave a cubic of a few units between them, which the grid can only straighten. So
// the corner keeps its tangent, the extremum's node goes, and the cubic from the corner
// carries the extremum within one grid place of the corner.
TEST(CubicWriteback, ACornerDrawnPastTheKinkLimitKeepsItsTurnAndAnExtremumOneGridPlaceAcrossGoes) {
  const Stroke stroke{.lean_deg = 4.2, .turn_deg = 90.0, .first_leg = 30.0, .second_leg = 30.0};
  const double lean = radians(stroke.lean_deg);
  const Vec2 p0{100, 0};
  const FairedChain chain = stroke_leaving_a_corner(stroke);
  ASSERT_EQ(chain.segments.size(), 1u);
  const double budget = 2.0, flat = 5e-4;
  ChainEnds ends{.start_corner = true, .start_axis = {}, .end_axis = {}};
  // Drawn without a turn of its own: onto the vertical, the extremum's node gone.
  const ChainCubics snapped = write_chain_as_cubics(chain, budget, flat, ends);
  ASSERT_TRUE(snapped.nodes.front().out_handle);
  EXPECT_NEAR(turning_angle(Vec2{0, 1}, *snapped.nodes.front().out_handle - p0), 0.0, 1e-9);
  RunEnd drawn;
  drawn.tangent = direction_of(radians(90.0 - 4.6));
  drawn.beyond = Vec2{0, 1};
  ends.start_run_end = drawn;
  const ChainCubics kept = write_chain_as_cubics(chain, budget, flat, ends);
  ASSERT_GE(kept.nodes.size(), 2u);
  const OutlineNode& corner = kept.nodes.front();
  ASSERT_TRUE(corner.out_handle);
  EXPECT_NEAR(turning_angle(Vec2{0, 1}, *corner.out_handle - corner.point), -lean, 1e-6);
  EXPECT_EQ(kept.nodes.size(), snapped.nodes.size());
  for (std::size_t k = 1; k < kept.nodes.size(); ++k) EXPECT_GT(distance(kept.nodes[k].point, corner.point), 20.0);
  // The first cubic reaches past the corner's vertical by less than one grid place.
  ASSERT_TRUE(kept.nodes[1].in_handle);
  const Cubic first{corner.point, *corner.out_handle, *kept.nodes[1].in_handle, kept.nodes[1].point};
  const double reach = rightmost_point(first).x - corner.point.x;
  EXPECT_GT(reach, 0.0);
  EXPECT_LT(reach, 0.5);
}

// A corner leaving 12.5° right of the vertical and turning left round, so that its vertical
// extremum lies 0.64 units on and 0.06 across (Junicode's u: the bowl's extremum 0.68 units from
// the serif's corner, 12° off the level). Too far off the axis to turn onto it, the corner keeps
// its tangent; as a node, the extremum left a cubic under a unit long, which rounding folded
// into a zigzag. So its node goes, and the cubic from the corner carries it within a unit of
// the corner.
TEST(CubicWriteback, AnExtremumWithinAUnitOfACornerTooFarOffItsAxisGoes) {
  const Stroke stroke{.lean_deg = 12.5, .turn_deg = 40.0, .first_leg = 4.0, .second_leg = 40.0, .alpha = 0.5};
  const double lean = radians(stroke.lean_deg);
  const Vec2 p0{100, 0};
  const FairedChain chain = stroke_leaving_a_corner(stroke);
  ASSERT_EQ(chain.segments.size(), 1u);
  const double budget = 2.0, flat = 5e-4;
  // As a smooth end: a node at the extremum, within a unit of the chain's start.
  const ChainCubics smooth = write_chain_as_cubics(chain, budget, flat);
  ASSERT_GE(smooth.nodes.size(), 3u);
  EXPECT_LT(distance(smooth.nodes[1].point, p0), 1.0);
  ASSERT_TRUE(smooth.nodes[1].grid_step);
  EXPECT_EQ(*smooth.nodes[1].grid_step, (Vec2{0, 1}));
  // At a corner: its tangent kept, no node within 20 units of it.
  const ChainCubics corner = write_chain_as_cubics(chain, budget, flat, {.start_corner = true, .start_axis = {}, .end_axis = {}});
  ASSERT_EQ(corner.nodes.size(), smooth.nodes.size() - 1);
  const OutlineNode& c = corner.nodes.front();
  EXPECT_EQ(c.point, p0);
  ASSERT_TRUE(c.out_handle);
  EXPECT_NEAR(turning_angle(Vec2{0, 1}, *c.out_handle - c.point), -lean, 1e-6);
  for (std::size_t k = 1; k < corner.nodes.size(); ++k) EXPECT_GT(distance(corner.nodes[k].point, p0), 20.0);
  // The first cubic reaches past the corner's vertical by less than a grid place, within a
  // unit of the corner.
  ASSERT_TRUE(corner.nodes[1].in_handle);
  const Vec2 rightmost = rightmost_point({c.point, *c.out_handle, *corner.nodes[1].in_handle, corner.nodes[1].point});
  EXPECT_GT(rightmost.x - p0.x, 0.0);
  EXPECT_LT(rightmost.x - p0.x, 0.5);
  EXPECT_LT(distance(rightmost, p0), 1.0);
}

// Where no cubic may carry an extremum off its nodes (handwriting), the corner takes an
// extremum within a unit of it however far off the axis it leaves: turned onto the axis, its
// cubic arrives along it and the extremum lies on the corner (Delphine's F: 0.55 units on and
// 0.10 across a cusp, whose cubic leaning back had carried it 0.67 units off, 1.16 once
// rounded). One farther off keeps its node, however near the axis.
TEST(CubicWriteback, WithoutInnerExtremaACornerTakesAnExtremumWithinAUnitAndKeepsOneFarther) {
  const SpanCutting handwriting{.no_inner_extrema = true};
  const ChainEnds at_a_corner{.start_corner = true, .start_axis = {}, .end_axis = {}};
  const double budget = 2.0, flat = 5e-4;
  const Vec2 p0{100, 0};
  // As Junicode's u above: 0.64 units on, 12.5° off the axis.
  const FairedChain near =
      stroke_leaving_a_corner({.lean_deg = 12.5, .turn_deg = 40.0, .first_leg = 4.0, .second_leg = 40.0, .alpha = 0.5});
  ASSERT_EQ(near.segments.size(), 1u);
  const ChainCubics smooth = write_chain_as_cubics(near, budget, flat, {}, handwriting);
  const ChainCubics taken = write_chain_as_cubics(near, budget, flat, at_a_corner, handwriting);
  ASSERT_EQ(taken.nodes.size(), smooth.nodes.size() - 1);
  const OutlineNode& c = taken.nodes.front();
  EXPECT_EQ(c.point, p0);
  ASSERT_TRUE(c.out_handle && c.grid_step);
  EXPECT_EQ(*c.grid_step, (Vec2{0, 1}));
  EXPECT_NEAR(c.out_handle->x, p0.x, 1e-9);
  for (std::size_t k = 1; k < taken.nodes.size(); ++k) EXPECT_GT(distance(taken.nodes[k].point, p0), 20.0);
  ASSERT_TRUE(taken.nodes[1].in_handle);
  const Cubic first{c.point, *c.out_handle, *taken.nodes[1].in_handle, taken.nodes[1].point};
  EXPECT_EQ(inner_axis_extrema_of(first).all, 0);
  // As Bonum's e above: a few units on, 0.08 across a corner drawn turning by 4.6°.
  const FairedChain farther =
      stroke_leaving_a_corner({.lean_deg = 4.2, .turn_deg = 90.0, .first_leg = 30.0, .second_leg = 30.0});
  ASSERT_EQ(farther.segments.size(), 1u);
  ChainEnds drawn_corner = at_a_corner;
  drawn_corner.start_run_end.tangent = direction_of(radians(90.0 - 4.6));
  drawn_corner.start_run_end.beyond = Vec2{0, 1};
  const ChainCubics text = write_chain_as_cubics(farther, budget, flat, drawn_corner);
  const ChainCubics kept = write_chain_as_cubics(farther, budget, flat, drawn_corner, handwriting);
  ASSERT_EQ(kept.nodes.size(), text.nodes.size() + 1);
  ASSERT_TRUE(kept.nodes[1].grid_step);
  EXPECT_EQ(*kept.nodes[1].grid_step, (Vec2{0, 1}));
  EXPECT_LT(distance(kept.nodes[1].point, p0), 10.0);
  EXPECT_GT(distance(kept.nodes[1].point, p0), 1.0);
}

// Halving a span that misses the budget stops short of `shortest_span_units`: cubics of two to
// four units, as the default allows, round onto a few grid points whose whole steps cannot set
// their curvature (Lato's W had two of four units at its middle apex, κ·UPM 1,333 and 4,000
// once rounded), so a rounded outline asks for eight (fair/contour_fairing.cpp).
TEST(CubicWriteback, NoHalfOfASpanIsShorterThanHalfTheShortestSpan) {
  const FairedChain chain = stroke_leaving_a_corner();
  ASSERT_EQ(chain.segments.size(), 1u);
  const double unreachable = 1e-9, flat = 5e-4;
  const auto shortest_cubic = [](const ChainCubics& c) {
    double shortest = 1e300;
    for (std::size_t k = 0; k + 1 < c.nodes.size(); ++k) shortest = std::min(shortest, distance(c.nodes[k].point, c.nodes[k + 1].point));
    return shortest;
  };
  const ChainCubics fine = write_chain_as_cubics(chain, unreachable, flat);
  const ChainCubics coarse = write_chain_as_cubics(chain, unreachable, flat, {}, {.shortest_span = 8.0});
  EXPECT_LT(coarse.nodes.size(), fine.nodes.size());
  EXPECT_LT(shortest_cubic(fine), 4.0);
  EXPECT_GE(shortest_cubic(coarse), 4.0 - 1e-6);
}

// A stroke between two corners: up 10° left of the vertical for 100 units, then round to the
// left by 85° and on for 300. The curvature at a corner binds nothing, so a span from one
// need only meet the other end's: with both ends corners, the chain takes three cubics within
// a budget of 0.3 where G2 Hermite cubics at every end took four (as it still does with its
// ends smooth), each still within the budget of the chain and bending one way.
TEST(CubicWriteback, ACornersCurvatureIsFree) {
  const double lean = radians(-10.0), turn = radians(85.0);
  const Vec2 p0{100, 0}, p1 = p0 + Vec2{std::sin(lean), std::cos(lean)} * 100.0;
  const Vec2 p2 = p1 + Vec2{std::sin(lean - turn), std::cos(lean - turn)} * 300.0;
  const SegmentFit fit = fit_three_point(p0, p1, p2, 1.0);
  ASSERT_TRUE(fit.ok());
  FairedChain chain;
  chain.segments.push_back(*fit.segment);
  const double budget = 0.3, flat = 5e-4;
  const ChainCubics bound = write_chain_as_cubics(chain, budget, flat);
  const ChainCubics free = write_chain_as_cubics(chain, budget, flat, {.start_corner = true, .end_corner = true, .start_axis = {}, .end_axis = {}});
  EXPECT_EQ(bound.nodes.size(), 4u);
  EXPECT_EQ(free.nodes.size(), 3u);

  std::vector<Vec2> path;
  for (const LacPoint& p : chain.segments.front().sample(2000)) path.push_back(p.point);
  std::vector<Vec2> written;
  for (std::size_t i = 0; i + 1 < free.nodes.size(); ++i) {
    const Cubic c = outline_cubic(free.nodes, i);
    for (int k = 0; k <= 400; ++k) written.push_back(c.point_at(k / 400.0));
    double first = 0.0;
    for (int k = 0; k <= 64; ++k) {
      const double kappa = curvature(derivatives_at(c, k / 64.0)).value_or(0.0);
      if (first == 0.0) first = kappa;
      EXPECT_GE(kappa * first, 0.0) << "cubic " << i << " at " << k / 64.0;
    }
  }
  EXPECT_LE(test::polyline_hausdorff(written, path), budget + 0.01);
}

// A curve leaving a line (κ = 0) for a corner is one cubic within the budget, κ = 0 at the
// line and bending one way. (Where no G2 Hermite cubic of both ends fits, the flat end's
// handle is tried at lengths, since κ = 0 fixes the corner's: ContourFairing's
// AStemsCurveToACornerIsOneCubic.)
TEST(CubicWriteback, ACurveFromALineToACornerIsOneCubic) {
  const double turn = radians(4.0);
  const Vec2 p0{0, 0}, p1{0, 250}, p2 = p1 + Vec2{-std::sin(turn), std::cos(turn)} * 120.0;
  const SegmentFit fit = fit_inflection_start(p0, p1, p2);
  ASSERT_TRUE(fit.ok());
  FairedChain chain;
  chain.segments.push_back(*fit.segment);
  chain.zero_curvature_start = true;
  ASSERT_EQ(chain.segments.front().start().curvature, 0.0);
  const double budget = 0.5, flat = 5e-4;
  const ChainCubics written = write_chain_as_cubics(chain, budget, flat, {.end_corner = true, .start_axis = {}, .end_axis = {}});
  ASSERT_EQ(written.nodes.size(), 2u);
  const Cubic c = outline_cubic(written.nodes, 0);
  EXPECT_NEAR(*end_curvature(c, SegmentEnd::start).curvature, 0.0, 1e-12);
  std::vector<Vec2> path, cubic;
  for (const LacPoint& p : chain.segments.front().sample(2000)) path.push_back(p.point);
  for (int k = 0; k <= 400; ++k) cubic.push_back(c.point_at(k / 400.0));
  EXPECT_LE(test::polyline_hausdorff(cubic, path), budget + 0.01);
  for (int k = 1; k <= 64; ++k) EXPECT_GE(curvature(derivatives_at(c, k / 64.0)).value_or(0.0), 0.0) << k / 64.0;  // turning left throughout
}

// A long stroke leaning 7.2° right of the vertical and turning right by `turn_deg` over 600
// units: none of the grid directions up to (3, 2) runs along it.
FairedChain nearly_straight_stroke(double turn_deg) {
  const double lean = radians(7.2), turn = radians(turn_deg);
  const Vec2 p0{0, 0}, p1 = p0 + Vec2{std::sin(lean), std::cos(lean)} * 300.0;
  const Vec2 p2 = p1 + Vec2{std::sin(lean + turn), std::cos(lean + turn)} * 300.0;
  const SegmentFit fit = fit_three_point(p0, p1, p2, 1.0);
  FairedChain chain;
  if (fit.ok()) chain.segments.push_back(*fit.segment);
  return chain;
}

// Each cubic within `budget` (plus `slack`, what the writeback's table of points, 2.3 units
// apart, lies inside the curve) of the chain, bending one way (right) and turning horizontal
// or vertical at no place inside.
void expect_faithful_cubics(const FairedChain& chain, const ChainCubics& written, double budget, double slack) {
  std::vector<Vec2> path;
  for (const LacPoint& p : chain.segments.front().sample(4000)) path.push_back(p.point);
  for (std::size_t i = 0; i + 1 < written.nodes.size(); ++i) {
    const Cubic c = outline_cubic(written.nodes, i);
    std::vector<Vec2> points;
    for (int k = 0; k <= 400; ++k) points.push_back(c.point_at(k / 400.0));
    EXPECT_LE(test::directed_to_polyline(points, path), budget + slack) << "cubic " << i;
    EXPECT_EQ(inner_axis_extrema_of(c).all, 0) << "cubic " << i;
    for (int k = 0; k <= 64; ++k)
      EXPECT_LE(curvature(derivatives_at(c, k / 64.0)).value_or(0.0), 0.0) << "cubic " << i << " at " << k / 64.0;
  }
}

// Turning by 3°, from 7.2° to 10.2° right of the vertical, the stroke passes (1, 7) and (1, 6).
// Within a budget of 5e-4 units (the stroke bows 4 units off its chord) it takes three cubics,
// its two inner nodes where the tangent runs along those two exactly, their handles along
// them; halving had cut it at its middle, on no grid direction.
TEST(CubicWriteback, ANearlyStraightStrokeIsCutWhereItRunsAlongLongerGridDirections) {
  const FairedChain chain = nearly_straight_stroke(3.0);
  ASSERT_EQ(chain.segments.size(), 1u);
  const double budget = 5e-4, flat = 5e-4;
  const ChainCubics written = write_chain_as_cubics(chain, budget, flat, {}, {.shortest_span = 8.0});
  ASSERT_EQ(written.nodes.size(), 4u);
  const std::array<Vec2, 2> steps{Vec2{1, 7}, Vec2{1, 6}};
  for (std::size_t k = 1; k <= 2; ++k) {
    const OutlineNode& node = written.nodes[k];
    ASSERT_TRUE(node.grid_step && node.in_handle && node.out_handle) << k;
    EXPECT_EQ(*node.grid_step, steps[k - 1]);
    const Vec2 u = *node.grid_step / norm(*node.grid_step);
    EXPECT_NEAR(cross(u, *node.out_handle - node.point), 0.0, 1e-9) << k;
    EXPECT_NEAR(cross(u, node.point - *node.in_handle), 0.0, 1e-9) << k;
  }
  expect_faithful_cubics(chain, written, budget, 0.6e-4);
}

// Turning by 0.4°, from 7.2° to 7.6°, the stroke passes no grid direction up to (10, 0) either:
// halving takes 8 cubics within a budget of 1e-5; the fewest through places evenly along it
// (handwriting: SpanCutting::evenly) 6, each within the budget.
TEST(CubicWriteback, AStrokeNoGridDirectionCutsTakesTheFewestCubicsThroughEvenPlaces) {
  const FairedChain chain = nearly_straight_stroke(0.4);
  ASSERT_EQ(chain.segments.size(), 1u);
  const double budget = 1e-5, flat = 5e-4;
  const ChainCubics halved = write_chain_as_cubics(chain, budget, flat, {}, {.shortest_span = 8.0});
  const ChainCubics evenly = write_chain_as_cubics(chain, budget, flat, {}, {.shortest_span = 8.0, .evenly = true});
  EXPECT_EQ(halved.nodes.size(), 9u);
  EXPECT_EQ(evenly.nodes.size(), 7u);
  expect_faithful_cubics(chain, evenly, budget, 1e-5);
}

// A stroke's edge that rises, turns left within 20 units to run 5° above level for 300 units
// while turning 4° more, and turns up again at the end: it rises all the way and meets the
// vertical only at its ends, so it has no extremum inside. Within a budget of 15 units (a
// handwriting tolerance) one G2 Hermite cubic from end to end fits, dipping below the level
// and back: two horizontal extrema without nodes. Handwriting turns such a cubic away
// (SpanCutting::no_inner_extrema) and cuts the span instead.
TEST(CubicWriteback, ACubicCrossingAnAxisInsideIsCut) {
  const auto heading = [](double deg) { return Vec2{std::cos(radians(deg)), std::sin(radians(deg))}; };
  const Vec2 p0{0, 0}, p1 = p0 + heading(132.5) * 20.0, p2 = p1 + heading(177.0) * 300.0, p3 = p2 + heading(134.5) * 20.0;
  const SegmentFit rise = fit_three_point(p0, p0 + heading(90.0) * 12.0, p1, 1.0);
  const SegmentFit level = fit_three_point(p1, p1 + heading(175.0) * 150.0, p2, 1.0);
  const SegmentFit up = fit_three_point(p2, p2 + heading(179.0) * 12.0, p3, 1.0);
  ASSERT_TRUE(rise.ok() && level.ok() && up.ok());
  FairedChain chain;
  chain.segments = {*rise.segment, *level.segment, *up.segment};
  const double budget = 15.0, flat = 5e-4;
  const auto off_node_extrema = [](const ChainCubics& w) {
    int count = 0;
    for (std::size_t i = 0; i + 1 < w.nodes.size(); ++i) count += inner_axis_extrema_of(outline_cubic(w.nodes, i)).off_node;
    return count;
  };
  const ChainCubics loose = write_chain_as_cubics(chain, budget, flat, {}, {.shortest_span = 8.0, .evenly = true});
  ASSERT_EQ(loose.nodes.size(), 2u);
  EXPECT_EQ(off_node_extrema(loose), 2);
  const ChainCubics cut = write_chain_as_cubics(chain, budget, flat, {}, {.shortest_span = 8.0, .evenly = true, .no_inner_extrema = true});
  EXPECT_GT(cut.nodes.size(), 2u);
  EXPECT_EQ(off_node_extrema(cut), 0);
  std::vector<Vec2> path;
  for (const LogAestheticSegment& s : chain.segments)
    for (const LacPoint& p : s.sample(1000)) path.push_back(p.point);
  for (std::size_t i = 0; i + 1 < cut.nodes.size(); ++i) {
    const Cubic c = outline_cubic(cut.nodes, i);
    std::vector<Vec2> points;
    for (int k = 0; k <= 400; ++k) points.push_back(c.point_at(k / 400.0));
    EXPECT_LE(test::directed_to_polyline(points, path), budget) << "cubic " << i;
  }
}

// A stroke leaving at 60° that turns right through the level to run straight down, 300 units
// from its turn: its horizontal extremum is a node. Within a budget of 0.2 units the G2 Hermite
// cubic of one of its spans, with the curvatures the path has at the nodes, strays, and the
// span is cut in two. With the extremum's curvature free (SpanCutting::free_node_curvatures)
// each span is one cubic, within the budget, and the node stays G2: both cubics meet there
// with one curvature, another than the path's.
TEST(CubicWriteback, AnExtremumsCurvatureMovesSoThatItsSpansFitWhole) {
  const auto heading = [](double deg) { return Vec2{std::cos(radians(deg)), std::sin(radians(deg))}; };
  const Vec2 p0{0, 0}, p1 = p0 + heading(60.0) * 200.0, p2 = p1 + heading(-90.0) * 300.0;
  const SegmentFit fit = fit_three_point(p0, p1, p2, 1.0);
  ASSERT_TRUE(fit.ok());
  FairedChain chain;
  chain.segments.push_back(*fit.segment);
  const double budget = 0.2, flat = 5e-4;
  const ChainCubics fixed = write_chain_as_cubics(chain, budget, flat, {}, {.shortest_span = 8.0});
  const ChainCubics freed = write_chain_as_cubics(chain, budget, flat, {}, {.shortest_span = 8.0, .free_node_curvatures = true});
  EXPECT_EQ(fixed.nodes.size(), 4u);
  ASSERT_EQ(freed.nodes.size(), 3u);
  const OutlineNode& extremum = freed.nodes[1];
  ASSERT_TRUE(extremum.in_handle && extremum.out_handle);
  EXPECT_NEAR(extremum.out_handle->y, extremum.point.y, 1e-9);
  EXPECT_NEAR(extremum.in_handle->y, extremum.point.y, 1e-9);
  const double arriving = node_curvature(outline_cubic(freed.nodes, 0), SegmentEnd::end);
  const double leaving = node_curvature(outline_cubic(freed.nodes, 1), SegmentEnd::start);
  EXPECT_NEAR(arriving, leaving, 1e-9 * std::abs(leaving));
  // The path's curvature where it runs level: the sample whose tangent is nearest the level.
  double path_kappa = 0.0, least = 1.0;
  for (const LacPoint& p : chain.segments.front().sample(20000))
    if (std::abs(p.tangent.y) < least) least = std::abs(p.tangent.y), path_kappa = p.curvature;
  EXPECT_GT(std::abs(leaving - path_kappa), 1e-2 * std::abs(path_kappa));
  // The chain's ends keep the path's curvature: they bind the runs beside it.
  EXPECT_NEAR(node_curvature(outline_cubic(freed.nodes, 0), SegmentEnd::start), chain.segments.front().start().curvature, 1e-9);
  EXPECT_NEAR(node_curvature(outline_cubic(freed.nodes, 1), SegmentEnd::end), chain.segments.front().end().curvature, 1e-9);
  expect_faithful_cubics(chain, freed, budget, 0.01);
}

}  // namespace
}  // namespace gf
