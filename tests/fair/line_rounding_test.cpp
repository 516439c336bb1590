// Lines on the grid: a curve meeting a line tangentially keeps its handle exactly on the line,
// and where the line's nearest grid points give it only a long primitive step, the curve's end
// slides along the line to where the step is short, instead of the handle growing to it.
#include "fair/line_rounding.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "fair/cubic_change.hpp"
#include "test_shapes.hpp"

namespace gf {
namespace {

using test::node;

std::vector<OutlineNode> nearest_grid_points(std::vector<OutlineNode> nodes) {
  for (OutlineNode& n : nodes) n.point = nearest_grid_point(n.point);
  return nodes;
}

// The nodes and their handles at their nearest grid points, as rounding first puts them.
std::vector<OutlineNode> all_at_nearest_grid_points(const std::vector<OutlineNode>& nodes) {
  std::vector<OutlineNode> r = nearest_grid_points(nodes);
  for (OutlineNode& n : r) {
    if (n.in_handle) n.in_handle = nearest_grid_point(*n.in_handle);
    if (n.out_handle) n.out_handle = nearest_grid_point(*n.out_handle);
  }
  return r;
}

TEST(LineRounding, ACurveLeavingALongDiagonalLineKeepsItsHandleLength) {
  // Inter's y: a corner, a 1,877-unit diagonal line, a curve leaving it tangentially with a
  // 49-unit handle. The nearest grid points and their neighbours give the line no primitive
  // step shorter than (−65, −176), 187 units: the handle would grow almost fourfold.
  const std::vector<OutlineNode> nodes{
      node(Vec2{1472.0, 1536.0}, std::nullopt, std::nullopt, false),
      node(Vec2{820.0, -224.0}, std::nullopt, Vec2{802.83, -270.34}),
      node(Vec2{683.87, -450.83}, Vec2{766.63, -368.07}, std::nullopt, false),
  };
  std::vector<OutlineNode> r = nearest_grid_points(nodes);
  std::vector<std::optional<Vec2>> steps(nodes.size());
  place_lines_on_grid(nodes, r, steps, true, HandleStepLimits{});

  const Vec2 line = nodes[1].point - nodes[0].point, handle = *nodes[1].out_handle - nodes[1].point;
  ASSERT_TRUE(r[1].out_handle && steps[1]);
  const Vec2 h = *r[1].out_handle;
  EXPECT_TRUE(test::on_grid(h));
  EXPECT_EQ(cross(r[1].point - r[0].point, h - r[1].point), 0.0);  // G1 exact on the grid
  EXPECT_EQ(cross(*steps[1], h - r[1].point), 0.0);
  EXPECT_LT(norm(*steps[1]), 40.0);
  // The handle's tip stays near where it was, so the curve keeps its shape.
  EXPECT_LE(distance(h, *nodes[1].out_handle), 0.5 * norm(*steps[1]) + 1.0);
  EXPECT_LE(std::abs(norm(h - r[1].point) - norm(handle)), 0.25 * norm(handle));
  // The join slid along the line, not off it; the corner moved a unit at most.
  EXPECT_LE(std::abs(cross(line / norm(line), r[1].point - nodes[1].point)), 0.75);
  EXPECT_LE(distance(r[1].point, nodes[1].point), 16.0);
  EXPECT_LE(distance(r[0].point, nodes[0].point), std::sqrt(2.0));
}

TEST(LineRounding, AShortStepNeedsNoSlide) {
  // A line close to (2, 5) from a corner to a curve: the nearest grid points already give the
  // short step, and the curve's end stays at its nearest grid point or a neighbour.
  const std::vector<OutlineNode> nodes{
      node(Vec2{0.3, 0.2}, std::nullopt, std::nullopt, false),
      node(Vec2{100.2, 250.1}, std::nullopt, Vec2{108.2, 270.1}),
      node(Vec2{150.0, 300.0}, Vec2{130.0, 300.0}, std::nullopt, false),
  };
  std::vector<OutlineNode> r = nearest_grid_points(nodes);
  std::vector<std::optional<Vec2>> steps(nodes.size());
  place_lines_on_grid(nodes, r, steps, true, HandleStepLimits{});
  ASSERT_TRUE(steps[1]);
  EXPECT_EQ(*steps[1], Vec2(2.0, 5.0));
  EXPECT_LE(distance(r[1].point, nodes[1].point), std::sqrt(2.0));
  EXPECT_EQ(*r[1].out_handle, r[1].point + Vec2(8.0, 20.0));
}

// The lines of an open outline placed on the grid (within 5 units), its other points at their
// nearest grid points: the cubic from the corner at node 2 to node 3, exact and as placed.
struct CornerCurve {
  Cubic exact, placed;
  std::vector<std::optional<Vec2>> steps;
};

CornerCurve corner_curve_after_lines(const std::vector<OutlineNode>& nodes) {
  std::vector<OutlineNode> r = all_at_nearest_grid_points(nodes);
  std::vector<std::optional<Vec2>> steps(nodes.size());
  HandleStepLimits limits;
  limits.allowance = 5.0;
  place_lines_on_grid(nodes, r, steps, false, limits);
  return {Cubic{nodes[2].point, *nodes[2].out_handle, *nodes[3].in_handle, nodes[3].point},
          Cubic{r[2].point, *r[2].out_handle, *r[3].in_handle, r[3].point}, steps};
}

TEST(LineRounding, ACornerTakesItsCurvesHandleAlong) {
  // Because We Connect's R: a stem's line 0.7° off the vertical, from a curve's tangent join to
  // the corner where the bowl's curve leaves it, 8° to the right. The line stands upright and
  // its corner moves over; with its handle left behind, the curve left the corner straight up
  // or leaning back (in the font, 3 units over: an x-extremum 7 units up, with no node).
  const std::vector<OutlineNode> nodes{
      node(Vec2{140.82, 74.55}, std::nullopt, Vec2{140.82, 86.13}, false),
      node(Vec2{140.17, 142.54}, Vec2{140.66, 100.55}, std::nullopt),
      node(Vec2{138.0, 330.0}, std::nullopt, Vec2{139.18, 337.45}, false),
      node(Vec2{143.0, 352.0}, Vec2{140.85, 344.8}, std::nullopt, false),
  };
  const CornerCurve c = corner_curve_after_lines(nodes);
  ASSERT_NE(c.placed.p[0], nearest_grid_point(nodes[2].point));  // the corner moved
  EXPECT_EQ(inner_axis_extrema(c.exact), 0);
  EXPECT_EQ(inner_axis_extrema(c.placed), 0);
  EXPECT_GT(c.placed.p[1].x, c.placed.p[0].x);  // it leaves the corner to the right, as it did
}

TEST(LineRounding, ACornerMovesOnlyWhereItsCurveGainsNoExtremum) {
  // Breip's M under G3: a line from a curve's tangent join, 9.5° off the vertical, to a corner
  // whose curve leaves straight down (an x-extremum on the corner) and bends left. A (1, −6)
  // step for the line put the corner 2 units left; its handle went along, its curve's far
  // handle stayed right of it, and the curve bulged right past the corner: an extremum inside.
  const std::vector<OutlineNode> nodes{
      node(Vec2{716.63984843591652, 677.640025629864}, std::nullopt, Vec2{738.022076, 634.875570}, false),
      node(Vec2{803.99969069830479, 263.0017433367463}, Vec2{752.107307, 555.486087}, std::nullopt),
      node(Vec2{826.0, 139.0}, std::nullopt, Vec2{826.0, 91.166310}, false),
      node(Vec2{822.4092876093697, 71.438977554373153}, Vec2{826.0, 84.250207}, std::nullopt, false),
  };
  const CornerCurve c = corner_curve_after_lines(nodes);
  ASSERT_TRUE(c.steps[1]);  // the line placed for its curve
  EXPECT_EQ(inner_axis_extrema(c.exact), 0);
  EXPECT_EQ(inner_axis_extrema(c.placed), 0);
  EXPECT_EQ(c.placed.p[1].x, c.placed.p[0].x);  // still leaving straight down
}

TEST(LineRounding, ALineStandsLevelOnlyWhereItsCurveCanMeetItWithoutAnS) {
  // Caladea's z: the base's top descends from its extremum into a line 2.1° off the level,
  // step (−27, −1). With its corner a unit up, the line would stand level at the shortest step,
  // 3 units under the extremum: a curve from one level tangent to another below it is an S, or
  // keeps curvature at the join (κ·UPM 0.29 in the font). The line keeps a lean the curve
  // meets turning one way.
  const std::vector<OutlineNode> nodes{
      node(Vec2{365.0, -3.0}, std::nullopt, Vec2{348.36, -2.11}, false),
      node(Vec2{229.06, 0.02}, Vec2{305.27, 0.02}, Vec2{148.59, 0.02}),
      node(Vec2{67.0, -3.0}, Vec2{84.53, -2.35}, std::nullopt),
      node(Vec2{40.0, -4.0}, std::nullopt, std::nullopt, false),
      node(Vec2{32.0, 38.0}, std::nullopt, std::nullopt, false),
  };
  std::vector<OutlineNode> r = all_at_nearest_grid_points(nodes);
  std::vector<std::optional<Vec2>> steps(nodes.size());
  steps[1] = Vec2{-1.0, 0.0};
  HandleStepLimits limits;
  limits.allowance = 0.6;
  place_lines_on_grid(nodes, r, steps, true, limits);
  ASSERT_TRUE(steps[2] && r[2].in_handle);
  EXPECT_LT(steps[2]->y, 0.0);  // still descending
  EXPECT_EQ(cross(*steps[2], *r[2].in_handle - r[2].point), 0.0);  // G1 exact on the grid
  // The extremum's handle at the whole step nearest the line leaves a curve turning one way.
  const std::vector<Vec2> seats = handles_near_line(r[1].point, *steps[1], 1.0, r[2].point, *steps[2]);
  ASSERT_FALSE(seats.empty());
  const Cubic curve{r[1].point, seats.front(), *r[2].in_handle, r[2].point};
  EXPECT_EQ(curvature_shape(curve, 0.0).sign_changes, 0);
}

TEST(LineRounding, AHandleOnALineOfLongStepStopsShortOfItsCurvesEnd) {
  // Gentium Plus's M: its right leg, 1,110 units of step (1, −111), meets a 4-unit curve at its
  // foot. Any handle on the line is a whole step long: from the foot, 111 units past the curve;
  // slid back a step less a few units, 6 units past its end, and the curve folds into an S there
  // (κ·UPM 88, −179, −488 in the font). The join slides back far enough for a step to end
  // short of the curve's end.
  const std::vector<OutlineNode> nodes{
      node(Vec2{1415.0, 1214.0}, std::nullopt, std::nullopt, false),
      node(Vec2{1425.0, 104.0}, std::nullopt, Vec2{1425.0 + 0.43 / 111.0, 104.0 - 0.43}),  // along the line
      node(Vec2{1425.87, 100.35}, Vec2{1425.02, 102.05}, Vec2{1426.46, 99.16}),
      node(Vec2{1430.73, 93.59}, Vec2{1428.51, 95.80}, std::nullopt, false),
  };
  std::vector<OutlineNode> r = all_at_nearest_grid_points(nodes);
  std::vector<std::optional<Vec2>> steps(nodes.size());
  steps[2] = Vec2{1.0, -2.0};
  HandleStepLimits limits;
  limits.allowance = 1.0;
  place_lines_on_grid(nodes, r, steps, false, limits);
  ASSERT_TRUE(steps[1] && r[1].out_handle);
  const Vec2 join = r[1].point, h = *r[1].out_handle, chord = r[2].point - join;
  EXPECT_EQ(cross(r[1].point - r[0].point, h - join), 0.0);  // G1 exact on the grid
  EXPECT_LE(dot(h - join, chord), dot(chord, chord)) << "handle " << h.x << ", " << h.y;
  EXPECT_LE(distance(r[0].point, nodes[0].point), 2.0);
}

}  // namespace
}  // namespace gf
