// Tight turns: a bend of small radius through a corner's worth of turning is split at its
// sharpest point (the same curve), and the runs either side leave it along the directions
// before and after the bend; a wide bend and a corner are left alone, and a stroke's end too
// where the limits stop short of a half turn. A hairline's end is a needle.
#include "fair/tight_turn.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "fair/contour_fairing.hpp"
#include "geom/curvature.hpp"
#include "point_set_distance.hpp"

namespace gf {
namespace {

constexpr double deg = std::numbers::pi / 180.0;

// One cubic for the circular arc about `centre` from angle a0 to a1 (k = 4/3·tan(Δ/4)).
Cubic arc(Vec2 centre, double r, double a0, double a1) {
  const double k = 4.0 / 3.0 * std::tan((a1 - a0) / 4.0);
  const Vec2 p0 = centre + direction_of(a0) * r, p3 = centre + direction_of(a1) * r;
  return Cubic{{p0, p0 + perpendicular(direction_of(a0)) * (k * r), p3 - perpendicular(direction_of(a1)) * (k * r), p3}};
}

// A pen's stroke reversing at the origin: two long, gently bowed sides leave a bend of
// radius `r` turning left by `turn`, closed along the top by a cubic meeting both at corners.
Contour reversal(double r, double turn) {
  const double in = -0.5 * turn, out = in + turn;  // the sides' directions; rightwards at the origin
  const Vec2 centre{0.0, r};
  const Cubic bend = arc(centre, r, in - 90.0 * deg, out - 90.0 * deg);
  const Vec2 a = bend.p[0], b = bend.p[3];
  const Vec2 top_a = a - direction_of(in) * 260.0 + Vec2{-12.0, 0.0};
  const Vec2 top_b = b + direction_of(out) * 260.0 + Vec2{12.0, 0.0};
  Contour c;
  c.segments = {Cubic{{top_a, lerp(top_a, a, 1.0 / 3.0), a - direction_of(in) * 80.0, a}}, bend,
                Cubic{{b, b + direction_of(out) * 80.0, lerp(top_b, b, 1.0 / 3.0), top_b}},
                Cubic{{top_b, top_b + Vec2{-40.0, 40.0}, top_a + Vec2{40.0, 40.0}, top_a}}};
  c.nodes.assign(4, NodeFlags{});
  return c;
}

std::vector<Vec2> dense(const Contour& c) { return test::contour_points(c, 400); }

constexpr TightTurnLimits limits{30.0, 160.0, 5.0};

TEST(TightTurn, APenReversalIsSplitAtItsSharpestPoint) {
  const Contour source = reversal(3.0, 120.0 * deg);
  const TightTurns found = find_tight_turns(source, limits);
  ASSERT_EQ(found.turns.size(), 1u);
  const TightTurn& t = found.turns.front();
  ASSERT_EQ(found.contour.segments.size(), source.segments.size() + 1);
  ASSERT_EQ(found.contour.nodes.size(), found.contour.segments.size());
  // At the bend's sharpest point (a cubic's arc is sharpest either side of its middle).
  const Cubic& bend = std::get<Cubic>(source.segments[1]);
  const Vec2 apex = found.contour.node_point(t.node);
  double sharpest = 0.0, nearest = 1e300;
  for (int k = 0; k <= 4000; ++k) {
    sharpest = std::max(sharpest, std::abs(*curvature(derivatives_at(bend, k / 4000.0))));
    nearest = std::min(nearest, distance(apex, bend.point_at(k / 4000.0)));
  }
  EXPECT_LT(nearest, 1e-3);
  EXPECT_GT(std::abs(*curvature(derivatives_at(found.contour.segments[t.node], 0.0))), (1.0 - 1e-6) * sharpest);
  EXPECT_EQ(found.contour.nodes[t.node].smooth, std::optional<bool>(false));
  // Leaving along the sides: exactly at the bend's start, within a sample's turn at its end.
  EXPECT_NEAR(angle_of(t.tangent_in), -60.0 * deg, 1e-9);
  EXPECT_LT(std::abs(turning_angle(t.tangent_out, direction_of(60.0 * deg))), 5.0 * deg);
  // The same curve.
  EXPECT_LT(test::point_set_hausdorff(dense(found.contour), dense(source)), 1e-2);
}

TEST(TightTurn, AWideBendAStrokeEndAndAGentleTurnStayCurves) {
  for (const auto& [r, turn] : {std::pair{30.0, 120.0}, {3.0, 178.0}, {3.0, 20.0}}) {
    const Contour source = reversal(r, turn * deg);
    const TightTurns found = find_tight_turns(source, limits);
    EXPECT_TRUE(found.turns.empty()) << "radius " << r << ", turn " << turn << "°";
    EXPECT_EQ(found.contour.segments, source.segments);
  }
}

// A hairline's end: the pen turns back on itself within a radius of 3 units (178°); with the
// default limits (through up to 200°) it is a needle, the same curve split at its tip, the
// runs leaving it nearly opposite ways; faired, the tip a corner and the sides from it nowhere
// as sharp as the tip was.
TEST(TightTurn, AHairlinesEndIsANeedle) {
  const Contour source = reversal(3.0, 178.0 * deg);
  TightTurnLimits needle;
  needle.deviation_units = 5.0;
  const TightTurns found = find_tight_turns(source, needle);
  ASSERT_EQ(found.turns.size(), 1u);
  const TightTurn& t = found.turns.front();
  EXPECT_GT(std::abs(turning_angle(t.tangent_in, t.tangent_out)), 160.0 * deg);
  // The same curve (sampled ten times as densely as elsewhere: the tip is 3 units round).
  EXPECT_LT(test::point_set_hausdorff(test::contour_points(found.contour, 4000), test::contour_points(source, 4000)), 0.1);
  FairOptions fo;
  fo.profile = FairProfile::handwriting;
  const ContourFairing r = fair_contour(source, resolve_settings(fo, 1000.0));
  ASSERT_TRUE(r.faired) << r.reason;
  // The tip a corner turning back on itself, the sides from it nowhere as sharp as the tip was.
  const Contour& c = r.contour;
  std::size_t tip = 0;
  for (std::size_t i = 1; i < c.segments.size(); ++i)
    if (norm(c.node_point(i)) < norm(c.node_point(tip))) tip = i;
  EXPECT_LE(norm(c.node_point(tip)), 3.0);
  const Segment& before = c.segments[(tip + c.segments.size() - 1) % c.segments.size()];
  EXPECT_GT(std::abs(turning_angle(*end_tangent(before, SegmentEnd::end), *end_tangent(c.segments[tip], SegmentEnd::start))),
            170.0 * deg);
  for (const Segment* s : {&before, &c.segments[tip]})
    for (int k = 0; k <= 64; ++k) EXPECT_LT(std::abs(curvature(derivatives_at(*s, k / 64.0)).value_or(0.0)), 1.0 / 3.0);
}

TEST(TightTurn, ACornerIsNotATightTurn) {
  // The bend drawn as a corner already: the sides' ends (and their handles with them) moved
  // to the origin, the bend gone. Nothing to find.
  Contour c = reversal(3.0, 120.0 * deg);
  Cubic& side_a = std::get<Cubic>(c.segments[0]);
  Cubic& side_b = std::get<Cubic>(c.segments[2]);
  side_a.p[2] -= side_a.p[3], side_a.p[3] = {0.0, 0.0};
  side_b.p[1] -= side_b.p[0], side_b.p[0] = {0.0, 0.0};
  c.segments.erase(c.segments.begin() + 1), c.nodes.pop_back();
  EXPECT_TRUE(find_tight_turns(c, limits).turns.empty());
}

TEST(TightTurn, TheRunsEitherSideLeaveAlongTheTurn) {
  const TightTurns found = find_tight_turns(reversal(3.0, 120.0 * deg), limits);
  ASSERT_EQ(found.turns.size(), 1u);
  ContourPlan plan = plan_contour(found.contour, {}, {30.0});
  aim_runs_at_tight_turns(plan, found.turns);
  const TightTurn& t = found.turns.front();
  int aimed = 0;
  for (std::size_t i = 0; i < plan.pieces.size(); ++i) {
    const SmoothRun& run = std::get<SmoothRun>(plan.pieces[i]);
    if (plan.start_nodes[i] == t.node) {
      EXPECT_EQ(run.start.tangent, t.tangent_out);
      ++aimed;
    }
    if (plan.start_nodes[(i + 1) % plan.pieces.size()] == t.node) {
      EXPECT_EQ(run.end.tangent, t.tangent_in);
      ++aimed;
    }
  }
  EXPECT_EQ(aimed, 2);
}

TEST(TightTurn, FairedTheReversalIsACornerWithoutASpike) {
  const Contour source = reversal(3.0, 120.0 * deg);
  FairOptions fo;
  fo.profile = FairProfile::handwriting;
  const FairSettings settings = resolve_settings(fo, 1000.0);
  const ContourFairing r = fair_contour(source, settings);
  ASSERT_TRUE(r.faired) << r.reason;
  const Contour& c = r.contour;
  std::size_t tip = 0;
  for (std::size_t i = 1; i < c.segments.size(); ++i)
    if (norm(c.node_point(i)) < norm(c.node_point(tip))) tip = i;
  EXPECT_LE(norm(c.node_point(tip)), 3.0);  // near the bend's sharpest point, on the grid
  const Segment& before = c.segments[(tip + c.segments.size() - 1) % c.segments.size()];
  EXPECT_GT(std::abs(turning_angle(*end_tangent(before, SegmentEnd::end), *end_tangent(c.segments[tip], SegmentEnd::start))),
            90.0 * deg);
  // Nowhere as sharp as the bend it replaced (radius 3).
  for (const Segment& s : c.segments)
    for (int k = 0; k <= 64; ++k) {
      const std::optional<double> kappa = curvature(derivatives_at(s, k / 64.0));
      EXPECT_LT(std::abs(kappa.value_or(0.0)), 1.0 / 3.0);
    }
}

}  // namespace
}  // namespace gf
