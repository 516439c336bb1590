// Cubics split beside the joins rounding left jumping (fair/jump_splits): where the split goes,
// and that the outline stays the same curve.
#include "fair/jump_splits.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "point_set_distance.hpp"
#include "test_shapes.hpp"

namespace gf {
namespace {

// A closed outline of four cubics round (0, 0)–(200, 200): a rounded square whose nodes are its
// four extrema, each handle 80 units long.
std::vector<OutlineNode> rounded_square() {
  return {test::node({100, 0}, Vec2{20, 0}, Vec2{180, 0}), test::node({200, 100}, Vec2{200, 20}, Vec2{200, 180}),
          test::node({100, 200}, Vec2{180, 200}, Vec2{20, 200}), test::node({0, 100}, Vec2{0, 180}, Vec2{0, 20})};
}

// Whether `split` draws what `nodes` draws: each within a thousandth of a unit of the other's
// polyline of 500 points a cubic (whose chords stray under 10⁻⁴ units from these cubics).
void expect_same_curve(const std::vector<OutlineNode>& nodes, const std::vector<OutlineNode>& split) {
  // Closed polylines: each back to its first point.
  std::vector<Vec2> a = test::contour_points(to_contour(nodes, true), 500);
  std::vector<Vec2> b = test::contour_points(to_contour(split, true), 500);
  a.push_back(a.front()), b.push_back(b.front());
  EXPECT_LT(test::directed_to_polyline(a, b), 1e-3);
  EXPECT_LT(test::directed_to_polyline(b, a), 1e-3);
}

TEST(JumpSplits, ASplitGoesWhereTheTangentRunsAlongAShortGridDirection) {
  // A quarter turn from (1, 0) to (0, 1), symmetric: the tangent runs along (1, 1) at t = 0.5.
  const Cubic quarter{{{0, 0}, {60, 0}, {100, 40}, {100, 100}}};
  const CubicSplit at = split_place(quarter);
  EXPECT_NEAR(at.t, 0.5, 1e-12);
  ASSERT_TRUE(at.grid_step);
  EXPECT_EQ(*at.grid_step, (Vec2{1, 1}));
  // Lopsided: the tangent crosses (2, 1) and (1, 1) inside; the one nearer the middle is taken,
  // and it runs exactly along it there.
  const Cubic lopsided{{{0, 0}, {90, 0}, {100, 10}, {100, 100}}};
  const CubicSplit l = split_place(lopsided);
  ASSERT_TRUE(l.grid_step);
  EXPECT_GE(l.t, 0.25);
  EXPECT_LE(l.t, 0.75);
  const Vec2 v = lopsided.hodograph().point_at(l.t);
  EXPECT_NEAR(cross(v, *l.grid_step) / norm(v), 0.0, 1e-9);
  EXPECT_GT(dot(v, *l.grid_step), 0.0);
}

TEST(JumpSplits, ACubicTurningPastNoShortDirectionSplitsAtItsMiddle) {
  // Its tangent stays between slopes 1/30 and 1/15: no (1, 0), (2, 1) or steeper inside.
  const CubicSplit at = split_place(Cubic{{{0, 0}, {30, 1}, {60, 2}, {90, 4}}});
  EXPECT_EQ(at.t, 0.5);
  EXPECT_FALSE(at.grid_step);
}

TEST(JumpSplits, TheCubicsBesideAJumpAreSplitAndTheCurveStaysTheSame) {
  const std::vector<OutlineNode> nodes = rounded_square();
  // A join rounding moved a unit off (200, 100): the cubics into and out of that node split.
  const std::vector<Vec2> joins{{201, 99}};
  const std::vector<OutlineNode> split = split_cubics_beside(nodes, true, joins, 16.0, 3.0);
  ASSERT_EQ(split.size(), 6u);
  EXPECT_EQ(split[0].point, nodes[0].point);
  EXPECT_EQ(split[2].point, nodes[1].point);
  EXPECT_EQ(split[4].point, nodes[2].point);
  for (const std::size_t k : {1u, 3u}) {
    // Each new node is smooth, at the (1, 1) diagonal of its quarter, its handles along it.
    EXPECT_TRUE(split[k].smooth);
    ASSERT_TRUE(split[k].grid_step);
    EXPECT_EQ(std::abs(split[k].grid_step->x), 1.0);
    EXPECT_EQ(std::abs(split[k].grid_step->y), 1.0);
    EXPECT_NEAR(cross(*split[k].out_handle - split[k].point, *split[k].grid_step), 0.0, 1e-9);
    EXPECT_NEAR(cross(split[k].point - *split[k].in_handle, *split[k].grid_step), 0.0, 1e-9);
  }
  expect_same_curve(nodes, split);
}

TEST(JumpSplits, TheClosingCubicSplitsToo) {
  const std::vector<OutlineNode> nodes = rounded_square();
  const std::vector<Vec2> joins{{100, 0}};  // node 0: the closing cubic from (0, 100) and the first
  const std::vector<OutlineNode> split = split_cubics_beside(nodes, true, joins, 16.0, 3.0);
  ASSERT_EQ(split.size(), 6u);
  EXPECT_EQ(split.front().point, nodes.front().point);
  EXPECT_NE(split.front().in_handle, nodes.front().in_handle);  // shortened with its cubic
  expect_same_curve(nodes, split);
}

TEST(JumpSplits, NothingSplitsFarFromAJoinOrWhereACubicIsShort) {
  const std::vector<OutlineNode> nodes = rounded_square();
  const std::vector<Vec2> far{{150, 50}};
  EXPECT_EQ(split_cubics_beside(nodes, true, far, 16.0, 3.0), nodes);
  // Chords of 141 units: none as long as 200.
  const std::vector<Vec2> at_node{{100, 0}};
  EXPECT_EQ(split_cubics_beside(nodes, true, at_node, 200.0, 3.0), nodes);
}

}  // namespace
}  // namespace gf
