// A curve meeting a line of long grid step: the line split, before rounding, at a grid point K
// near it where both parts step short; the curve's end on the grid, leaving along J–K's step
// (no longer than its handle); the line turning at K the way the curve bends into it, gently
// enough for a fillet; the outline moved by no more than the limit. Left alone: lines whose own
// step the handle can take.
#include "fair/line_splits.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "fair/cubic_change.hpp"
#include "fair/grid_rounding.hpp"
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

// Gentium Plus's M (2,048 units), its right leg as the guide basis faired it: the leg's
// 1,110-unit line steps (1, −111) down to J = (1425, 104), where a cubic leaves it G2 with a
// 4.4-unit handle and bends left, away from the vertical, onto the foot's (2, −1). `reversed`:
// the contour runs the other way round (the cubic arrives at J).
std::vector<OutlineNode> m_leg(bool reversed) {
  std::vector<OutlineNode> nodes{
      test::node({1115, 0}, std::nullopt, std::nullopt, false),
      test::node({1115, 43}, std::nullopt, Vec2{1174.3512397558948, 55.169821489996089}, false),
      test::node({1249.2288464008138, 83.820048777745228}, Vec2{1224.5327953366461, 71.472023245604305},
                 Vec2{1270.0, 94.251912791103862}, true, Vec2{2, 1}),
      test::node({1270.0, 104.0}, Vec2{1270.0, 100.49470700443109}, Vec2{1270.0, 162.50213671311499}, true,
                 Vec2{0, 1}),
      test::node({1268.8235433873954, 279.50049546159767}, Vec2{1270.0, 162.50213671311499}, std::nullopt),
      test::node({1260, 1157}, std::nullopt, std::nullopt, false),
      test::node({1415, 1214}, std::nullopt, std::nullopt, false),
      test::node({1425, 104}, std::nullopt, Vec2{1425.0399194780855, 99.568937932501356}),
      test::node({1453.8338232794056, 78.211618996378817}, Vec2{1425.102909225013, 92.577076023541039},
                 Vec2{1477.4462567683197, 66.405402251949667}, true, Vec2{2, -1}),
      test::node({1570, 43}, Vec2{1510.8002773402809, 54.429657168040194}, std::nullopt, false),
      test::node({1570, 0}, std::nullopt, std::nullopt, false),
  };
  if (!reversed) return nodes;
  std::vector<OutlineNode> back;
  for (auto it = nodes.rbegin(); it != nodes.rend(); ++it) {
    OutlineNode n = *it;
    std::swap(n.in_handle, n.out_handle);
    if (n.grid_step) n.grid_step = -*n.grid_step;
    back.push_back(n);
  }
  return back;
}

// Whether every point of `a`, sampled, lies on `b` (densely sampled).
bool lies_on(const Cubic& a, const Cubic& b) {
  std::vector<Vec2> on_b;
  for (int i = 0; i <= 20000; ++i) on_b.push_back(b.point_at(i / 20000.0));
  for (int i = 0; i <= 200; ++i) {
    const Vec2 p = a.point_at(i / 200.0);
    double nearest = 1e300;
    for (const Vec2 q : on_b) nearest = std::min(nearest, distance(p, q));
    if (nearest > 0.01) return false;
  }
  return true;
}

TEST(LineSplits, ACurveBendingAwayFromItsLegsAxisIsSplitWhereItTurnsOntoAShortStep) {
  for (const bool reversed : {false, true}) {
    const std::vector<OutlineNode> before = m_leg(reversed);
    const std::size_t n = before.size(), j = reversed ? n - 1 - 7 : 7;
    std::vector<OutlineNode> nodes = before;
    // No split of the leg: every short step near the vertical turns the line against the bend.
    ASSERT_FALSE(split_line_at(nodes, true, j, LineSplitLimits{})) << "reversed " << reversed;
    ASSERT_TRUE(split_curve_beside_line(nodes, true, j)) << "reversed " << reversed;
    ASSERT_EQ(nodes.size(), n + 1);
    // The cut goes in between J and the foot's node; reversed, J moves up one.
    const std::size_t cut = reversed ? j : j + 1, join = reversed ? j + 1 : j;
    EXPECT_EQ(nodes[join].point, before[j].point);
    const OutlineNode& c = nodes[cut];
    ASSERT_TRUE(c.smooth && c.in_handle && c.out_handle && c.grid_step);
    // The two cubics are the one cubic, cut: the outline does not move.
    const Cubic whole = outline_cubic(before, reversed ? j - 1 : j);
    EXPECT_TRUE(lies_on(outline_cubic(nodes, reversed ? j - 1 : j), whole));
    EXPECT_TRUE(lies_on(outline_cubic(nodes, reversed ? j : j + 1), whole));
    // The cut's tangent runs along its grid step, a short primitive direction, turned from J's
    // between a third and two thirds of the way the cubic turns, the way it bends.
    const Vec2 step = *c.grid_step;
    EXPECT_EQ(primitive_step(step), step);
    EXPECT_LE(std::max(std::abs(step.x), std::abs(step.y)), 3.0);
    EXPECT_NEAR(cross(step, *c.out_handle - c.point) / norm(*c.out_handle - c.point), 0.0, 1e-9);
    EXPECT_NEAR(cross(step, c.point - *c.in_handle) / norm(c.point - *c.in_handle), 0.0, 1e-9);
    EXPECT_GT(dot(step, *c.out_handle - c.point), 0.0);
    const double j_angle = std::atan2(99.568937932501356 - 104.0, 0.0399194780855);  // J's tangent, leaving
    const double foot = std::atan2(-1.0, 2.0);
    const double cut_angle = std::atan2(reversed ? -step.y : step.y, reversed ? -step.x : step.x);
    EXPECT_GT(cut_angle - j_angle, (foot - j_angle) / 3.0);
    EXPECT_LT(cut_angle - j_angle, 2.0 * (foot - j_angle) / 3.0);
  }
}

TEST(LineSplits, ACurveCutBesideItsLegRoundsWithinTheToleranceWithoutAnInflection) {
  // What the cut is for: on its own, the cubic at J takes a whole (1, −111) step of the leg as
  // its handle and strays tens of units; cut, rounding slides J a step up the leg and the short
  // piece takes that stretch over, bending one way as the cubic did.
  const std::vector<OutlineNode> before = m_leg(false);
  HandleStepLimits limits;
  limits.allowance = 1.78;  // what the float outline leaves of the 2.56-unit tolerance, less 5 %
  limits.flat_curvature = 0.5 / 2048.0;
  const Contour exact = to_contour(before, true);
  const auto strays = [&](const std::vector<OutlineNode>& rounded) {
    return test::point_set_hausdorff(dense(rounded), test::contour_points(exact, 600));
  };
  EXPECT_GT(strays(round_to_grid(before, true, limits)), 10.0);
  std::vector<OutlineNode> nodes = before;
  ASSERT_TRUE(split_curve_beside_line(nodes, true, 7));
  const std::vector<OutlineNode> rounded = round_to_grid(nodes, true, limits);
  EXPECT_LE(strays(rounded), 2.56);
  for (std::size_t i = 0; i < rounded.size(); ++i) {
    const std::size_t next = (i + 1) % rounded.size();
    if (!rounded[i].out_handle || !rounded[next].in_handle) continue;
    const Cubic c = outline_cubic(rounded, i);
    if (c.p[3].y > 300.0 || c.p[0].x < 1400.0) continue;  // the right leg's foot
    EXPECT_EQ(curvature_shape(c, 0.0).sign_changes, 0) << "cubic " << i;
    EXPECT_GE(cross(c.p[1] - c.p[0], c.p[3] - c.p[2]), 0.0) << "cubic " << i;  // bends left
  }
}

}  // namespace
}  // namespace gf
