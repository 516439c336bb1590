// A curve meeting a line of long grid step: the line split, before rounding, at a grid point K
// near it where both parts step short; the curve's end on the grid, leaving along J–K's step
// (no longer than its handle); the line turning at K the way the curve bends into it, gently
// enough for a fillet; the outline moved by no more than the limit. Left alone: lines whose own
// step the handle can take.
#include "fair/line_splits.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "point_set_distance.hpp"
#include "test_shapes.hpp"

namespace gf {
namespace {

// FreeSerif Italic's V (1,000 units), its right serif's curve from (738, 637) meeting the left
// stroke at J = (682, 597), G2 (both handles on the stroke's line, the near one `handle` long);
// the stroke runs to the corner (309, −18), step (373, 615): 719 units. `mirror`: x → −x (the
// contour then runs the other way round, so it is reversed too).
std::vector<OutlineNode> serif_and_stroke(double handle, bool mirror = false) {
  const Vec2 j{682, 597}, far{309, -18};
  const Vec2 t = (far - j) / norm(far - j);
  std::vector<OutlineNode> nodes = {test::node({738, 637}, std::nullopt, Vec2{712, 637}, false),
                                    test::node(j, j - t * handle, std::nullopt),
                                    test::node(far, std::nullopt, std::nullopt, false),
                                    test::node({290, -18}, std::nullopt, std::nullopt, false),
                                    test::node({126, 653}, std::nullopt, std::nullopt, false),
                                    test::node({738, 653}, std::nullopt, std::nullopt, false)};
  // The far handle on the stroke's line too: κ = 0 at J.
  *nodes[0].out_handle = j - t * (3.0 * handle);
  if (!mirror) return nodes;
  const auto flip = [](std::optional<Vec2> p) { return p ? std::optional<Vec2>(Vec2{-p->x, p->y}) : std::nullopt; };
  std::vector<OutlineNode> mirrored;
  for (auto it = nodes.rbegin(); it != nodes.rend(); ++it)
    mirrored.push_back(test::node({-it->point.x, it->point.y}, flip(it->out_handle), flip(it->in_handle), it->smooth));
  return mirrored;
}

std::vector<Vec2> dense(const std::vector<OutlineNode>& nodes) { return test::contour_points(to_contour(nodes, true), 600); }

TEST(LineSplits, AStrokeOfLongStepIsSplitWhereBothPartsStepShort) {
  for (const bool mirror : {false, true}) {
    std::vector<OutlineNode> nodes = serif_and_stroke(9.0, mirror);
    const std::vector<OutlineNode> before = nodes;
    const LineSplitLimits limits;
    ASSERT_TRUE(split_line_at(nodes, true, mirror ? 4 : 1, limits)) << "mirror " << mirror;
    ASSERT_EQ(nodes.size(), before.size() + 1);
    // The join, the vertex and the stroke's far end (mirrored, the contour runs F, K, J).
    const std::size_t j = mirror ? 5 : 1, k = mirror ? 4 : 2, f = 3;
    const OutlineNode &join = nodes[j], &vertex = nodes[k];
    const Vec2 far = nodes[f].point;
    EXPECT_TRUE(join.pinned && vertex.pinned);
    EXPECT_TRUE(join.smooth);
    EXPECT_FALSE(vertex.smooth || vertex.in_handle || vertex.out_handle);
    EXPECT_TRUE(test::on_grid(join.point) && test::on_grid(vertex.point));
    // Both parts step short: J–K no longer than the handle, K–F far shorter than the stroke's
    // 719. Each step as the contour runs.
    const Vec2 toward = mirror ? join.point - vertex.point : vertex.point - join.point;
    const std::optional<Vec2> step = primitive_step(toward);
    const std::optional<Vec2> on = primitive_step(mirror ? vertex.point - far : far - vertex.point);
    ASSERT_TRUE(step && on);
    EXPECT_LE(norm(*step), 9.0);
    EXPECT_LT(norm(*on), 100.0);
    EXPECT_EQ(join.grid_step, *step);
    // The curve leaves along the step, its handle as long as it was.
    const Vec2 handle = mirror ? *join.out_handle - join.point : join.point - *join.in_handle;
    EXPECT_NEAR(cross(handle, *step) / norm(*step), 0.0, 1e-9);
    EXPECT_GT(dot(handle, *step), 0.0);
    EXPECT_NEAR(norm(handle), 9.0, 1e-9);
    // The line turns at K the way the serif's curve bends (left, as the contour runs, mirrored
    // or not), gently.
    const double turn = (mirror ? turning_angle(*on, *step) : turning_angle(*step, *on)) * 180.0 / std::acos(-1.0);
    EXPECT_GT(turn, 0.0);
    EXPECT_LE(std::abs(turn), limits.max_turn_deg);
    EXPECT_LE(test::polyline_hausdorff(dense(before), dense(nodes)), limits.max_move_units + 0.01);
  }
}

TEST(LineSplits, ALineWhoseStepTheHandleTakesStays) {
  // The stroke's step (5, 8), 9.4 units: a 12-unit handle takes one whole step of it.
  std::vector<OutlineNode> nodes = serif_and_stroke(12.0);
  nodes[2].point = nodes[1].point - Vec2{5, 8} * 70.0;
  const std::vector<OutlineNode> before = nodes;
  EXPECT_FALSE(split_line_at(nodes, true, 1, LineSplitLimits{}));
  EXPECT_EQ(nodes, before);
}

}  // namespace
}  // namespace gf
