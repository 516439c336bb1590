// A curve meeting a line that leans a little off an axis joins it, before rounding, through a
// fillet from the axis: the curve leaves along the axis, both fillet handles lie on one vertex
// (κ = 0 at both its ends, so both joins stay G2), the line starts one of its grid steps past
// the vertex, and the outline moves by no more than the limit. Left alone: lines on or far
// from an axis, short steps, fillets that would turn against the curve.
#include "fair/leaning_line_ends.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "geom/curvature.hpp"
#include "point_set_distance.hpp"
#include "test_shapes.hpp"

namespace gf {
namespace {

// A bracket curving from a serif (1115, 43) up into a stem that leans `dx` units over 1,000
// (Gentium Plus's M leans 10 over 1,053: 0.54°), its top a corner. The bracket meets the stem's
// foot (1270, 104) as the fairing leaves it, along the stem with κ = 0: both its handles on
// the stem's line.
std::vector<OutlineNode> bracket_and_stem(double dx) {
  const Vec2 foot{1270, 104}, top = foot + Vec2{dx, 1000};
  const Vec2 t = (top - foot) / norm(top - foot);
  return {test::node({1115, 43}, std::nullopt, foot - t * 60.0, false), test::node(foot, foot - t * 30.0, std::nullopt),
          test::node(top, std::nullopt, std::nullopt, false), test::node({1115, 1104}, std::nullopt, std::nullopt, false)};
}

std::vector<Vec2> dense(const std::vector<OutlineNode>& nodes) { return test::contour_points(to_contour(nodes, true), 400); }

TEST(LeaningLineEnds, ACurveMeetingALeaningStemLeavesAlongTheAxisThroughAFillet) {
  std::vector<OutlineNode> nodes = bracket_and_stem(-10.0);  // leaning left, as the bracket turns
  const std::vector<OutlineNode> before = nodes;
  const LeaningLineLimits limits;
  ASSERT_EQ(fillet_leaning_line_ends(nodes, true, limits), 1);
  ASSERT_EQ(nodes.size(), 5u);
  const OutlineNode &j = nodes[1], &q = nodes[2];
  EXPECT_EQ(j.point, before[1].point);
  EXPECT_EQ(j.grid_step, (Vec2{0, 1}));
  EXPECT_TRUE(j.smooth && q.smooth);
  // The curve arrives upright, the fillet leaves upright, both its handles on the vertex.
  EXPECT_DOUBLE_EQ(j.in_handle->x, j.point.x);
  EXPECT_DOUBLE_EQ(j.out_handle->x, j.point.x);
  EXPECT_EQ(*j.out_handle, *q.in_handle);
  EXPECT_FALSE(q.out_handle.has_value());  // the line starts at q
  // G1 at q: the vertex, q and the stem's top in a line; κ = 0 at both ends of the fillet.
  EXPECT_NEAR(cross(q.point - *q.in_handle, nodes[3].point - q.point) / norm(nodes[3].point - q.point), 0.0, 1e-9);
  const Cubic fillet = outline_cubic(nodes, 1);
  EXPECT_NEAR(*end_curvature(fillet, SegmentEnd::start).curvature, 0.0, 1e-12);
  EXPECT_NEAR(*end_curvature(fillet, SegmentEnd::end).curvature, 0.0, 1e-12);
  // The curve's far handle onto the axis too: κ = 0 where it meets the fillet.
  EXPECT_NEAR(*end_curvature(outline_cubic(nodes, 0), SegmentEnd::end).curvature, 0.0, 1e-12);
  EXPECT_LE(test::polyline_hausdorff(dense(before), dense(nodes)), limits.max_move_units + 1e-9);
  // Walked the other way round, the same fillet.
  std::vector<OutlineNode> reversed;
  for (auto it = before.rbegin(); it != before.rend(); ++it) reversed.push_back(test::node(it->point, it->out_handle, it->in_handle, it->smooth));
  EXPECT_EQ(fillet_leaning_line_ends(reversed, true, limits), 1);
  EXPECT_LE(test::polyline_hausdorff(dense(before), dense(reversed)), limits.max_move_units + 1e-9);
}

// A bowl arriving level at its foot N, a horizontal extremum, and a 9-unit ramp from N on to
// the base line (Liberation Serif 2.1's D), which leans 4 units up over 478: the ramp rises
// 0.05 units and its curvature runs from the foot's down to 0 at the line.
std::vector<OutlineNode> bowl_ramp_and_line() {
  const Vec2 n{718, -4.05}, j{709, -4}, far{231, 0};
  const Vec2 t = (far - j) / norm(far - j);
  return {test::node({1322, 305}, std::nullopt, Vec2{1184, 29}, false), test::node(n, Vec2{884, -4.05}, n + Vec2{-3, 0}),
          test::node(j, j - t * 3.0, std::nullopt), test::node(far, std::nullopt, std::nullopt, false),
          test::node({231, 1000}, std::nullopt, std::nullopt, false)};
}

TEST(LeaningLineEnds, ARampFromAnExtremumIsTheFilletsFirstStretch) {
  std::vector<OutlineNode> nodes = bowl_ramp_and_line();
  const std::vector<OutlineNode> before = nodes;
  const double foot_kappa = *end_curvature(outline_cubic(before, 1), SegmentEnd::start).curvature;
  ASSERT_LT(foot_kappa, 0.0);
  const LeaningLineLimits limits;
  ASSERT_EQ(fillet_leaning_line_ends(nodes, true, limits), 1);
  ASSERT_EQ(nodes.size(), before.size());  // the fillet takes the ramp's place
  const OutlineNode &n = nodes[1], &q = nodes[2];
  EXPECT_EQ(n.point, before[1].point);
  EXPECT_EQ(n.in_handle, before[1].in_handle);  // the bowl as it was
  // The fillet leaves the foot level, with a handle the grid can vary by whole units.
  EXPECT_EQ(n.out_handle->y, n.point.y);
  EXPECT_GE(n.point.x - n.out_handle->x, 8.0);
  // At the foot the ramp's curvature, at q none, and q's handle, q and the line's far end in a line.
  const Cubic fillet = outline_cubic(nodes, 1);
  EXPECT_NEAR(*end_curvature(fillet, SegmentEnd::start).curvature, foot_kappa, 1e-9 * std::abs(foot_kappa));
  EXPECT_NEAR(*end_curvature(fillet, SegmentEnd::end).curvature, 0.0, 1e-12);
  EXPECT_FALSE(q.out_handle.has_value());
  EXPECT_NEAR(cross(q.point - *q.in_handle, nodes[3].point - q.point) / norm(nodes[3].point - q.point), 0.0, 1e-9);
  EXPECT_LE(test::polyline_hausdorff(dense(before), dense(nodes)), limits.max_move_units + 1e-9);
  // Walked the other way round, the same fillet.
  std::vector<OutlineNode> reversed;
  for (auto it = before.rbegin(); it != before.rend(); ++it) reversed.push_back(test::node(it->point, it->out_handle, it->in_handle, it->smooth));
  ASSERT_EQ(fillet_leaning_line_ends(reversed, true, limits), 1);
  EXPECT_LE(test::polyline_hausdorff(dense(before), dense(reversed)), limits.max_move_units + 1e-9);
  const std::size_t foot = reversed.size() - 2;  // the nodes reversed: the foot second to last
  EXPECT_NEAR(*end_curvature(outline_cubic(reversed, foot - 1), SegmentEnd::end).curvature, -foot_kappa,
              1e-9 * std::abs(foot_kappa));
}

TEST(LeaningLineEnds, LinesOnTheAxisFarFromItWithShortStepsOrLeaningAgainstTheCurveStay) {
  const LeaningLineLimits limits;
  for (const double dx : {0.0, -50.0, -500.0}) {  // upright; 2.9° and 26.6°, past the lean limit
    std::vector<OutlineNode> nodes = bracket_and_stem(dx);
    EXPECT_EQ(fillet_leaning_line_ends(nodes, true, limits), 0) << dx;
  }
  // The stem leaning right while the bracket bends left: from the axis onto it would be an S.
  std::vector<OutlineNode> against = bracket_and_stem(10.0);
  EXPECT_EQ(fillet_leaning_line_ends(against, true, limits), 0);
  // Leaning left but moving the outline too far for a tight limit.
  std::vector<OutlineNode> leaning = bracket_and_stem(-10.0);
  LeaningLineLimits tight;
  tight.max_move_units = 0.01;
  EXPECT_EQ(fillet_leaning_line_ends(leaning, true, tight), 0);
}

}  // namespace
}  // namespace gf
