// A stroke's edge that leaves a corner bending one way for a short stretch and then turns the
// other way (a scan's rounded corner, cut at the inflection) becomes one cubic from the corner
// that bends one way, meeting the node where the lobe's cubics ended with that node's tangent
// and curvature; the corner stays a corner, the outline moves within the allowance. Left alone
// where the allowance is too small.
#include "fair/corner_end_lobes.hpp"

#include <gtest/gtest.h>

#include "geom/critical_points.hpp"
#include "geom/curvature.hpp"
#include "point_set_distance.hpp"
#include "test_shapes.hpp"

namespace gf {
namespace {

// A corner C = (0, 0) that the outline reaches going down its left side. From C the edge rises
// about a unit and comes back, bending right, to the inflection node N = (60, 0), which it
// leaves heading a little down (along T) with κ = 0 on both sides (each cubic's far handle on
// that tangent); the cubic beyond bends left up to the corner M = (200, 60). Then lines back
// to the top left and down to C. `rise`: how far the lobe's first handle stands off T's line.
std::vector<OutlineNode> corner_lobe_and_curve(double rise = 3.0) {
  const Vec2 n{60, 0}, t = Vec2{1, -rise / 40.0} / norm(Vec2{1, -rise / 40.0});
  return {test::node({0, 0}, std::nullopt, n - t * 40.0, false), test::node(n, n - t * 20.0, n + t * 40.0),
          test::node({200, 60}, n + t * 80.0, std::nullopt, false), test::node({0, 150}, std::nullopt, std::nullopt, false)};
}

std::vector<Vec2> dense(const std::vector<OutlineNode>& nodes) { return test::contour_points(to_contour(nodes, true), 400); }

// The sign changes of κ along the cubics from node `from` up to node `to` (exclusive).
int sign_changes(const std::vector<OutlineNode>& nodes, std::size_t from, std::size_t to) {
  int changes = 0, last = 0;
  for (std::size_t i = from; i < to; ++i)
    for (int step = 0; step <= 64; ++step) {
      const std::optional<double> k = curvature(derivatives_at(outline_cubic(nodes, i), step / 64.0));
      if (!k || std::abs(*k) < 1e-12) continue;
      const int sign = *k > 0.0 ? 1 : -1;
      changes += last != 0 && sign != last;
      last = sign;
    }
  return changes;
}

// The way a cubic bends at its middle.
int bend_sign(const Cubic& c) { return *curvature(derivatives_at(c, 0.5)) > 0.0 ? 1 : -1; }

std::vector<OutlineNode> reversed(const std::vector<OutlineNode>& nodes) {
  std::vector<OutlineNode> out;
  for (auto it = nodes.rbegin(); it != nodes.rend(); ++it)
    out.push_back(test::node(it->point, it->out_handle, it->in_handle, it->smooth));
  return out;
}

TEST(CornerEndLobes, ALobeLeavingACornerBecomesPartOfOneCubicThatBendsOneWay) {
  std::vector<OutlineNode> nodes = corner_lobe_and_curve();
  const std::vector<OutlineNode> before = nodes;
  ASSERT_EQ(sign_changes(before, 0, 2), 1);  // the lobe, then the curve
  const double room = 5.0;
  std::vector<double> allowance(nodes.size(), room);
  ASSERT_EQ(drop_corner_end_lobes(nodes, true, allowance), 1);
  ASSERT_EQ(allowance.size(), nodes.size());
  // The start and the corners stay; N goes, and the new cubic keeps a node where it runs level
  // (as the curve beyond N did), its handles exactly level.
  ASSERT_EQ(nodes.size(), 4u);
  EXPECT_EQ(nodes[0].point, before[0].point);
  EXPECT_EQ(nodes[2].point, before[2].point);
  EXPECT_FALSE(nodes[0].smooth);
  const OutlineNode& level = nodes[1];
  EXPECT_TRUE(level.smooth);
  EXPECT_EQ(level.grid_step, (Vec2{1, 0}));
  EXPECT_EQ(level.in_handle->y, level.point.y);
  EXPECT_EQ(level.out_handle->y, level.point.y);
  EXPECT_EQ(sign_changes(nodes, 0, 2), 0);
  EXPECT_NEAR(*end_curvature(outline_cubic(nodes, 0), SegmentEnd::end).curvature,
              *end_curvature(outline_cubic(nodes, 1), SegmentEnd::start).curvature, 1e-12);
  // M is met as before: its tangent and its curvature.
  const Cubic old_beyond = outline_cubic(before, 1), now = outline_cubic(nodes, 1);
  EXPECT_NEAR(cross(*end_tangent(now, SegmentEnd::end), *end_tangent(old_beyond, SegmentEnd::end)), 0.0, 1e-12);
  EXPECT_NEAR(*end_curvature(now, SegmentEnd::end).curvature, *end_curvature(old_beyond, SegmentEnd::end).curvature, 1e-12);
  // C still turns the same way round, by at least the limit.
  const double corner = turning_angle(arriving_direction(nodes, 0), leaving_direction(nodes, 0));
  EXPECT_GT(corner, radians(CornerLobeLimits{}.least_corner_deg));
  // Within the allowance, and what is left of it follows the cubic.
  const double moved = test::polyline_hausdorff(dense(before), dense(nodes));
  EXPECT_LE(moved, room + 1e-9);
  EXPECT_LT(allowance[0], room);
  EXPECT_EQ(allowance[1], allowance[0]);
  EXPECT_EQ(allowance[2], room);
}

TEST(CornerEndLobes, ALobeArrivingAtACornerIsDroppedTheSameWay) {
  std::vector<OutlineNode> nodes = reversed(corner_lobe_and_curve());
  const std::vector<OutlineNode> before = nodes;
  std::vector<double> allowance(nodes.size(), 5.0);
  ASSERT_EQ(drop_corner_end_lobes(nodes, true, allowance), 1);
  ASSERT_EQ(nodes.size(), 4u);
  EXPECT_EQ(nodes[0].point, before[0].point);  // the outline starts where it did
  // From M the outline now runs into C through the level node, bending one way.
  const auto m = std::find_if(nodes.begin(), nodes.end(), [](const OutlineNode& q) { return q.point == Vec2{200, 60}; });
  ASSERT_NE(m, nodes.end());
  const std::size_t i = static_cast<std::size_t>(m - nodes.begin());
  ASSERT_LT(i + 2, nodes.size());
  EXPECT_EQ(nodes[i + 1].grid_step, (Vec2{-1, 0}));
  EXPECT_EQ(nodes[i + 2].point, (Vec2{0, 0}));
  EXPECT_EQ(sign_changes(nodes, i, i + 2), 0);
  EXPECT_LE(test::polyline_hausdorff(dense(before), dense(nodes)), 5.0 + 1e-9);
}

TEST(CornerEndLobes, ALobeInsideTheCornersCubicIsDroppedFromIt) {
  // C's cubic itself bends right and then left (one inflection), ending at N as the curve
  // beyond it goes on: the same shape as one cubic less.
  std::vector<OutlineNode> nodes = {
      test::node({0, 0}, std::nullopt, Vec2{40, 4}, false), test::node({120, 20}, Vec2{80, 0}, Vec2{160, 40}),
      test::node({200, 60}, Vec2{180, 50}, std::nullopt, false), test::node({0, 150}, std::nullopt, std::nullopt, false)};
  ASSERT_EQ(critical_points(outline_cubic(nodes, 0)).inflections.size(), 1u);
  const std::vector<OutlineNode> before = nodes;
  std::vector<double> allowance(nodes.size(), 5.0);
  ASSERT_EQ(drop_corner_end_lobes(nodes, true, allowance), 1);
  ASSERT_EQ(nodes.size(), before.size());
  EXPECT_TRUE(critical_points(outline_cubic(nodes, 0)).inflections.empty());
  EXPECT_EQ(nodes[1].point, before[1].point);
  EXPECT_EQ(*nodes[1].out_handle, *before[1].out_handle);  // the curve beyond N as it was
  const Cubic now = outline_cubic(nodes, 0), was = outline_cubic(before, 0);
  EXPECT_NEAR(*end_curvature(now, SegmentEnd::end).curvature, *end_curvature(was, SegmentEnd::end).curvature, 1e-12);
  EXPECT_LE(test::polyline_hausdorff(dense(before), dense(nodes)), 5.0 + 1e-9);
}

TEST(CornerEndLobes, ALobeIntoALineBecomesTheLineFromTheCornerMovedOntoIt) {
  // From the corner C = (0, 0), 2 units left of the upright line x = 2 from N = (2, 60) to
  // E = (2, 200), the lobe bends left into the line (κ = 0 at N); beyond the line the curve
  // bends right to the corner F. C is reached by a line from the corner (−40, −100).
  std::vector<OutlineNode> nodes = {
      test::node({0, 0}, std::nullopt, Vec2{2, 20}, false),   test::node({2, 60}, Vec2{2, 40}, std::nullopt),
      test::node({2, 200}, std::nullopt, Vec2{2, 240}),      test::node({40, 300}, Vec2{2, 270}, std::nullopt, false),
      test::node({100, 300}, std::nullopt, std::nullopt, false), test::node({100, -100}, std::nullopt, std::nullopt, false),
      test::node({-40, -100}, std::nullopt, std::nullopt, false)};
  const std::vector<OutlineNode> before = nodes;
  ASSERT_EQ(sign_changes(nodes, 0, 1) + (bend_sign(outline_cubic(nodes, 0)) != bend_sign(outline_cubic(nodes, 2))), 1);
  std::vector<double> allowance(nodes.size(), 5.0);
  ASSERT_EQ(drop_corner_end_lobes(nodes, true, allowance), 1);
  ASSERT_EQ(nodes.size(), before.size() - 1);
  // The corner on the line's extension, the line from it to E, E and what follows as they were.
  EXPECT_EQ(nodes[0].point, (Vec2{2, 0}));
  EXPECT_FALSE(nodes[0].smooth);
  EXPECT_FALSE(nodes[0].out_handle.has_value());
  EXPECT_EQ(nodes[1], before[2]);
  EXPECT_EQ(nodes[2], before[3]);
  // Still a corner, turning left as before.
  EXPECT_GT(turning_angle(arriving_direction(nodes, 0), leaving_direction(nodes, 0)), radians(6.0));
  EXPECT_LE(test::polyline_hausdorff(dense(before), dense(nodes)), 5.0 + 1e-9);
  EXPECT_EQ(allowance.size(), nodes.size());
}

TEST(CornerEndLobes, ALobeFartherFromAOneWayCurveThanTheAllowanceStays) {
  std::vector<OutlineNode> nodes = corner_lobe_and_curve(12.0);  // a lobe 4 units high
  const std::vector<OutlineNode> before = nodes;
  std::vector<double> allowance(nodes.size(), 1.0);
  EXPECT_EQ(drop_corner_end_lobes(nodes, true, allowance), 0);
  EXPECT_EQ(nodes, before);
  EXPECT_EQ(allowance, std::vector<double>(before.size(), 1.0));
}

// Steve Hand's A (sjfonts, GPL with the font exception; handwriting, tolerance 14), float,
// before the pass: from the corner at (568, 47), where the foot's line ends, the right stroke's
// edge bends left for 90 units and then right into its line at (499, 206), κ = 0 there. The
// cubic from the corner that meets that line flat starts almost on the line's extension: its
// corner handle came out 0.55 units long on a 173-unit chord, and rounding set it on a 2-unit
// step back along the foot, a cusp of κ·UPM 19,800. No cubic the pass writes has a handle
// under 3 % of its chord, which whole grid steps cannot hold.
TEST(CornerEndLobes, NoCubicFromTheCornerHasAHandleTooShortForTheGrid) {
  // The curve's last cubic, from B, has its handles crossed and meets the line at E flat: B's
  // out-handle lies on the line through its far handle F and E.
  const Vec2 b{529.1927, 136.4397}, f{524.1110, 148.1269}, e{499, 206};
  std::vector<OutlineNode> nodes{test::node({568, 47}, std::nullopt, Vec2{552.0385, 83.8087}, false),
                                 test::node(b, Vec2{539.2325, 113.3123}, e + (f - e) * 0.33345),
                                 test::node(e, f, std::nullopt),
                                 test::node({403, 427.25}, std::nullopt, std::nullopt, false),
                                 test::node({516, 47}, std::nullopt, std::nullopt, false)};
  const std::vector<OutlineNode> before = nodes;
  std::vector<double> allowance(nodes.size(), 11.7);
  drop_corner_end_lobes(nodes, true, allowance);
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    if (!nodes[i].out_handle) continue;
    const Cubic c = outline_cubic(nodes, i);
    const double chord = distance(c.p[0], c.p[3]);
    EXPECT_GE(distance(c.p[0], c.p[1]), 0.03 * chord) << "cubic " << i;
    EXPECT_GE(distance(c.p[2], c.p[3]), 0.03 * chord) << "cubic " << i;
  }
  EXPECT_LE(test::polyline_hausdorff(dense(before), dense(nodes)), 11.7 + 1e-9);
}

}  // namespace
}  // namespace gf
