// Spurs: a scan's overshoot that turns back on itself at a cusp and runs back along the edge
// it drew is cut out before the fairing; a stroke's pointed end, a spike standing off the
// outline and a plain corner stay.
#include "fair/spurs.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <optional>

#include "fair/contour_fairing.hpp"
#include "fair/fair_options.hpp"
#include "point_set_distance.hpp"

namespace gf {
namespace {

// A 300 × 100 bar whose top edge, drawn rightwards, turns back at (200, 100) by 180° and runs
// 20 units back over itself before going on (a quadratic from the cusp: control (140, 103),
// leftmost at (180, 101.3), through (200, 101.3) again): Breip's E has one so.
Contour bar_with_spur(double control_y = 103.0) {
  Contour c;
  c.segments = {Line{{{0.0, 0.0}, {0.0, 100.0}}}, Line{{{0.0, 100.0}, {200.0, 100.0}}},
                Quad{{{200.0, 100.0}, {140.0, control_y}, {260.0, 100.0}}}, Line{{{260.0, 100.0}, {300.0, 100.0}}},
                Line{{{300.0, 100.0}, {300.0, 0.0}}}, Line{{{300.0, 0.0}, {0.0, 0.0}}}};
  c.nodes.assign(c.segments.size(), NodeFlags{});
  return c;
}

// The turn at the node of `c` at `at`, degrees; none where no node is there.
std::optional<double> turn_at(const Contour& c, Vec2 at) {
  const std::size_t n = c.segments.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (c.node_point(i) != at) continue;
    const Vec2 in = derivative_at(c.segments[(i + n - 1) % n], 1.0), out = derivative_at(c.segments[i], 0.0);
    return std::abs(turning_angle(in, out)) * 180.0 / std::numbers::pi;
  }
  return std::nullopt;
}

TEST(Spurs, ASpurLyingOnItsOwnEdgeIsCutAtItsCusp) {
  const Contour source = bar_with_spur();
  const Vec2 cusp{200.0, 100.0};
  ASSERT_GT(turn_at(source, cusp).value_or(0.0), 170.0);
  const MovedContour cut = cut_spurs(source, SpurLimits{});
  EXPECT_EQ(cut.changes, 1);
  // The kept stretch joins at the cusp itself, and the edge goes nearly straight on there.
  EXPECT_LT(turn_at(cut.contour, cusp).value_or(180.0), 10.0);
  // Nothing of the filled bar changes: the spur lay within 1.33 units of the edge.
  EXPECT_LT(test::point_set_hausdorff(test::contour_points(cut.contour, 400), test::contour_points(source, 400)),
            SpurLimits{}.width_units);
  EXPECT_NEAR(signed_area(cut.contour), signed_area(source), 0.01 * std::abs(signed_area(source)));
}

TEST(Spurs, ASpurOfLinesIsCutWhereTheOutlineComesBackAlongALine) {
  // The same bar, its spur drawn as two lines: 20 units back from the cusp and then on along
  // the edge, past the cusp (the outline comes back on a line, cut there).
  Contour source = bar_with_spur();
  source.segments[2] = Line{{{200.0, 100.0}, {180.0, 101.0}}};
  source.segments.insert(source.segments.begin() + 3, Line{{{180.0, 101.0}, {260.0, 100.0}}});
  source.nodes.assign(source.segments.size(), NodeFlags{});
  const MovedContour cut = cut_spurs(source, SpurLimits{});
  EXPECT_EQ(cut.changes, 1);
  EXPECT_LT(turn_at(cut.contour, {200.0, 100.0}).value_or(180.0), 10.0);
  EXPECT_LT(test::point_set_hausdorff(test::contour_points(cut.contour, 400), test::contour_points(source, 400)),
            SpurLimits{}.width_units);
}

TEST(Spurs, APointedStrokeEndASpikeOffTheOutlineAndACornerStay) {
  // A wedge 100 units long closing to a point: the outline never comes back to its tip.
  Contour wedge;
  wedge.segments = {Line{{{0.0, 0.0}, {100.0, 1.0}}}, Line{{{100.0, 1.0}, {0.0, 2.0}}}, Line{{{0.0, 2.0}, {0.0, 0.0}}}};
  wedge.nodes.assign(3, NodeFlags{});
  EXPECT_EQ(cut_spurs(wedge, SpurLimits{}).changes, 0);
  // The spur bowed 30 units off the edge (control (140, 190)): it comes back near the cusp,
  // but most of it lies far from the rest of the outline.
  EXPECT_EQ(cut_spurs(bar_with_spur(190.0), SpurLimits{}).changes, 0);
  // The bar alone: corners of 90°.
  Contour bar = bar_with_spur();
  bar.segments[2] = Line{{{200.0, 100.0}, {260.0, 100.0}}};
  EXPECT_EQ(cut_spurs(bar, SpurLimits{}).changes, 0);
}

TEST(Spurs, FairedAsHandwritingTheSpurLeavesNoHook) {
  FairOptions options;
  options.profile = FairProfile::handwriting;
  const FairSettings settings = resolve_settings(options, 1000.0);
  const Contour source = bar_with_spur();
  const ContourFairing faired = fair_contour(source, settings);
  ASSERT_TRUE(faired.faired) << faired.reason;
  // No part of the top edge turns back: every point of the outline near the top runs
  // rightwards or stands at a corner, and the outline keeps within the tolerance.
  for (const Segment& s : faired.contour.segments)
    for (int k = 1; k < 32; ++k) {
      const double t = k / 32.0;
      const Vec2 p = point_at(s, t), d = derivative_at(s, t);
      if (p.y > 95.0 && p.x > 20.0 && p.x < 280.0) {
        EXPECT_GT(d.x, 0.0) << p.x << ", " << p.y;
      }
    }
  EXPECT_LE(contour_distance(faired.contour, source), settings.tolerance_units);
}

}  // namespace
}  // namespace gf
