// A kink where a nearly flat curve meets a line, turning against the curve's bend by more than
// the curve turns (TeX Gyre Pagella's E: its base meets its serif's line 2.5° the other way):
// planned as a corner opened to the corner floor where the contour has no G2 chain otherwise,
// and faired so, instead of bending the curve through an inflection into the line.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "fair/contour_fairing.hpp"
#include "fair/contour_plan.hpp"
#include "fair/fair_options.hpp"
#include "geom/curvature.hpp"

namespace gf {
namespace {

double degrees(double rad) { return rad * 180.0 / std::numbers::pi; }

// Pagella's E base, 1000 units per em, as a slab 63 units high: a stem's line down to the base,
// the base's two cubics (arcs of radius about 2,500 and 9,000, the second turning 1.5°), a
// serif's line rising 3 units over 167 (2.5° against the base's bend), and back.
Contour e_base() {
  Contour c;
  c.segments = {Line{{34, 60}, {34, -3}},
                Cubic{{{34, -3}, {75, -1}, {116, 0}, {157, 0}}},
                Cubic{{{157, 0}, {234, 0}, {312, -1}, {389, -3}}},
                Line{{389, -3}, {556, 0}},
                Line{{556, 0}, {556, 60}},
                Line{{556, 60}, {34, 60}}};
  c.nodes.assign(c.segments.size(), NodeFlags{});
  return c;
}

// The signed turn at the join in front of segment k, degrees.
double turn_before(const Contour& c, std::size_t k) {
  const std::size_t n = c.segments.size();
  return degrees(turning_angle(*end_tangent(c.segments[(k + n - 1) % n], SegmentEnd::end),
                               *end_tangent(c.segments[k], SegmentEnd::start)));
}

TEST(AgainstLineKinks, AKinkAgainstAFlatCurveIsPlannedAsACornerOpenedToTheFloor) {
  const Contour c = e_base();
  ASSERT_NEAR(turn_before(c, 3), 2.52, 0.01);  // the source's kink, against the base's clockwise bend
  const ContourPlan smooth = plan_contour(c, {}, {3.0, true});
  EXPECT_EQ(opened_corners(smooth), 0u);
  EXPECT_EQ(std::get<SmoothRun>(smooth.pieces[1]).end.kind, RunEndKind::line);

  PlanOptions options{3.0, true};
  options.open_against_lines = true;
  const ContourPlan opened = plan_contour(c, {}, options);
  EXPECT_EQ(opened_corners(opened), 1u);
  const RunEnd& end = std::get<SmoothRun>(opened.pieces[1]).end;
  EXPECT_EQ(end.kind, RunEndKind::corner);
  EXPECT_TRUE(end.opened);
  // The base's tangent turned (clockwise, its own way) until the corner turns by the floor.
  EXPECT_NEAR(degrees(turning_angle(end.tangent, Vec2{167, 3})), corner_floor_deg, 1e-9);

  // Made smooth (the kink pass), no corner is opened there.
  const std::vector<std::size_t> made{3};
  EXPECT_EQ(opened_corners(plan_contour(c, made, options)), 0u);
}

TEST(AgainstLineKinks, KinksTheCurveTakesWithinItsOwnTurningStayLineJoins) {
  PlanOptions options{3.0, true};
  options.open_against_lines = true;
  // The same kink against a curve that turns 6° over its cubic: the curve takes it.
  Contour turning = e_base();
  turning.segments[2] = Cubic{{{157, 0}, {234, 0}, {312, -8}, {389, -16}}};
  turning.segments[3] = Line{{389, -16}, {556, -26}};
  turning.segments[4] = Line{{556, -26}, {556, 60}};
  ASSERT_NEAR(turn_before(turning, 3), 2.5, 0.1);
  EXPECT_EQ(opened_corners(plan_contour(turning, {}, options)), 0u);
  // A kink the curve's way (the line turns on clockwise): no inflection needed.
  Contour along = e_base();
  along.segments[3] = Line{{389, -3}, {556, -15}};
  EXPECT_EQ(opened_corners(plan_contour(along, {}, options)), 0u);
  // Under 2°: smoothed.
  Contour small = e_base();
  small.segments[3] = Line{{389, -3}, {556, -2}};
  EXPECT_EQ(opened_corners(plan_contour(small, {}, options)), 0u);
}

TEST(AgainstLineKinks, TheBaseIsFairedAsOneArcIntoACornerNotAWaveIntoTheLine) {
  const Contour source = e_base();
  // Text, and rounded: the source is drawn on the grid.
  const FairSettings settings = resolve_settings(FairOptions{}, 1000.0);
  const ContourFairing faired = fair_contour(source, settings);
  ASSERT_TRUE(faired.faired) << faired.reason;
  EXPECT_LE(faired.deviation, settings.tolerance_units);
  const Contour& c = faired.contour;
  // The serif's line starts where the source's does, a corner turning by the kink limit or
  // more (no kink), and the base between the stem and it is at most two cubics, bending one way.
  std::size_t serif = c.segments.size(), stem_end = c.segments.size();
  for (std::size_t k = 0; k < c.segments.size(); ++k) {
    if (is_line(c.segments[k]) && start_point(c.segments[k]) == Vec2{389, -3}) serif = k;
    if (is_line(c.segments[k]) && end_point(c.segments[k]) == Vec2{34, -3}) stem_end = k;
  }
  ASSERT_LT(serif, c.segments.size());
  ASSERT_LT(stem_end, c.segments.size());
  EXPECT_FALSE(c.nodes[serif].smooth.value_or(false));
  EXPECT_GE(turn_before(c, serif), 3.0);
  const std::size_t cubics = (serif + c.segments.size() - stem_end - 1) % c.segments.size();
  EXPECT_GE(cubics, 1u);
  EXPECT_LE(cubics, 2u);
  for (std::size_t i = 1; i <= cubics; ++i)
    for (const double t : {0.0, 0.25, 0.5, 0.75, 1.0})
      if (const std::optional<double> kappa = curvature(derivatives_at(c.segments[(stem_end + i) % c.segments.size()], t))) {
        EXPECT_LE(*kappa, 1e-12);
      }
}

}  // namespace
}  // namespace gf
