// The writeback's spare nodes (fair/spare_nodes): a smooth node between two cubics on neither
// axis and at no inflection goes where one cubic draws its two within the budget, the curvature
// staying continuous at every node and the curvature beyond the changed cubics kept.
#include "fair/spare_nodes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include "geom/curvature.hpp"
#include "test_shapes.hpp"

namespace gf {
namespace {

constexpr double upm = 1000.0, radius = 300.0;

// The nodes of a closed chain of cubics, each ending where the next starts.
std::vector<OutlineNode> nodes_of(const std::vector<Cubic>& cubics) {
  std::vector<OutlineNode> nodes;
  for (std::size_t k = 0; k < cubics.size(); ++k)
    nodes.push_back(test::node(cubics[k].p[0], cubics[(k + cubics.size() - 1) % cubics.size()].p[2], cubics[k].p[1]));
  return nodes;
}

// The quarter of a circle of `radius` about the origin from angle a (radians) on, as the usual
// cubic (handles (4/3)·tan(π/8)·r), in `pieces` equal pieces of its parameter.
std::vector<Cubic> quarter(double a, int pieces) {
  const double h = (4.0 / 3.0) * std::tan(std::numbers::pi / 8.0) * radius, b = a + 0.5 * std::numbers::pi;
  const Vec2 p0{radius * std::cos(a), radius * std::sin(a)}, p3{radius * std::cos(b), radius * std::sin(b)};
  const Cubic c{p0, p0 + Vec2{-std::sin(a), std::cos(a)} * h, p3 - Vec2{-std::sin(b), std::cos(b)} * h, p3};
  std::vector<Cubic> out;
  for (int i = 0; i < pieces; ++i) out.push_back(c.subsegment(static_cast<double>(i) / pieces, static_cast<double>(i + 1) / pieces));
  return out;
}

std::vector<Cubic> circle(int pieces_per_quarter) {
  std::vector<Cubic> out;
  for (int q = 0; q < 4; ++q)
    for (const Cubic& c : quarter(q * 0.5 * std::numbers::pi, pieces_per_quarter)) out.push_back(c);
  return out;
}

double start_kappa(const Cubic& c) { return *end_curvature(c, SegmentEnd::start).curvature; }
double end_kappa(const Cubic& c) { return *end_curvature(c, SegmentEnd::end).curvature; }

TEST(SpareNodes, ACircleHalvedIsDrawnAgainOnItsExtrema) {
  // Each quarter of the usual four-cubic circle cut in half: the halves' nodes at 45° are spare,
  // and the four cubics come back.
  std::vector<OutlineNode> nodes = nodes_of(circle(2));
  for (std::size_t k = 0; k < 8; ++k) EXPECT_EQ(is_spare_node(nodes, true, k, upm), k % 2 == 1) << k;
  const SampledContour source(to_contour(nodes, true));
  EXPECT_EQ(remove_spare_nodes(nodes, true, source, {1.25, upm}).removed, 4);
  ASSERT_EQ(nodes.size(), 4u);
  const std::vector<Cubic> whole = circle(1);
  for (std::size_t k = 0; k < 4; ++k) {
    for (std::size_t i = 0; i < 4; ++i) EXPECT_NEAR(distance(outline_cubic(nodes, k).p[i], whole[k].p[i]), 0.0, 1e-6) << k << i;
    const double in = end_kappa(outline_cubic(nodes, (k + 3) % 4)), out = start_kappa(outline_cubic(nodes, k));
    EXPECT_NEAR(in, out, 1e-9 * std::abs(out));
  }
}

TEST(SpareNodes, ExtremaOffTheSourceSlideBackAsTheirQuartersBecomeOne) {
  // The halved circle with each axis node (and its handles) 3 units along its tangent: no
  // cubic through those nodes comes within the budget of the circle, so no spare node goes in
  // its window. Fitted again whole to the source, the extrema sliding, the four cubics come
  // back, their nodes on the circle's axes.
  std::vector<OutlineNode> nodes = nodes_of(circle(2));
  for (std::size_t k = 0; k < 8; k += 2) {
    const Vec2 along = (*nodes[k].out_handle - nodes[k].point) / norm(*nodes[k].out_handle - nodes[k].point) * 3.0;
    nodes[k].point = nodes[k].point + along;
    nodes[k].in_handle = *nodes[k].in_handle + along, nodes[k].out_handle = *nodes[k].out_handle + along;
  }
  const SampledContour source(to_contour(nodes_of(circle(1)), true));
  std::vector<OutlineNode> windows = nodes;
  EXPECT_EQ(remove_spare_nodes(windows, true, source, {1.25, upm, false, false}).removed, 0);
  const SpareNodeRemoval removal = remove_spare_nodes(nodes, true, source, {1.25, upm});
  EXPECT_EQ(removal.removed, 4);
  EXPECT_EQ(removal.in_runs, 4);
  ASSERT_EQ(nodes.size(), 4u);
  for (std::size_t k = 0; k < 4; ++k) {
    const double a = static_cast<double>(k) * 0.5 * std::numbers::pi;
    EXPECT_NEAR(distance(nodes[k].point, Vec2{radius * std::cos(a), radius * std::sin(a)}), 0.0, 1e-3) << k;
    const Vec2 out = *nodes[k].out_handle - nodes[k].point, in = nodes[k].point - *nodes[k].in_handle;
    EXPECT_NEAR(std::min(std::abs(out.x), std::abs(out.y)), 0.0, 1e-9) << k;  // still an extremum
    EXPECT_NEAR(cross(in, out) / (norm(in) * norm(out)), 0.0, 1e-12) << k;
    const double before = end_kappa(outline_cubic(nodes, (k + 3) % 4)), after = start_kappa(outline_cubic(nodes, k));
    EXPECT_NEAR(before, after, 1e-9 * std::abs(after)) << k;
  }
  EXPECT_LE(distance_between(SampledContour(to_contour(nodes, true)), source), 0.01);
}

TEST(SpareNodes, ACircleOfEighthArcsKeepsItsNodes) {
  // Each eighth of the circle its own cubic: κ varies by 4e-6 of itself along them. One cubic
  // for a quarter varies by 2 % (κ·r 0.98 at its ends, 1.00 inside), past the variation the
  // changed cubics may take on.
  std::vector<OutlineNode> nodes;
  const double h = (4.0 / 3.0) * std::tan(std::numbers::pi / 16.0) * radius;
  for (int k = 0; k < 8; ++k) {
    const double a = k * std::numbers::pi / 4.0;
    const Vec2 p{radius * std::cos(a), radius * std::sin(a)}, t{-std::sin(a), std::cos(a)};
    nodes.push_back(test::node(p, p - t * h, p + t * h));
  }
  const std::vector<OutlineNode> before = nodes;
  const SampledContour source(to_contour(nodes, true));
  EXPECT_EQ(remove_spare_nodes(nodes, true, source, {1.25, upm}).removed, 0);
  EXPECT_EQ(nodes, before);
}

TEST(SpareNodes, ATightBudgetKeepsEveryNode) {
  // The halved circle against a source 0.03 units outside it, with a budget of 0.02 (which
  // the halved circle itself does not meet either): no node goes.
  std::vector<OutlineNode> nodes = nodes_of(circle(2));
  const std::vector<OutlineNode> before = nodes;
  std::vector<OutlineNode> shifted = nodes;
  for (OutlineNode& q : shifted) {
    q.point = q.point * 1.0001;
    q.in_handle = *q.in_handle * 1.0001, q.out_handle = *q.out_handle * 1.0001;
  }
  const SampledContour source(to_contour(shifted, true));  // 0.03 units out all round
  EXPECT_EQ(remove_spare_nodes(nodes, true, source, {0.02, upm}).removed, 0);
  EXPECT_EQ(nodes, before);
}

TEST(SpareNodes, AnInflectionIsNoSpareNode) {
  // An S: a left turn, then a right turn of the same radius, meeting at (0, 0).
  const double h = (4.0 / 3.0) * std::tan(std::numbers::pi / 8.0) * radius;
  std::vector<OutlineNode> nodes{test::node({-radius, -radius}, std::nullopt, Vec2{-radius + h, -radius}),
                                 test::node({0.0, 0.0}, Vec2{0.0, -h}, Vec2{0.0, h}),
                                 test::node({radius, radius}, Vec2{radius - h, radius}, std::nullopt)};
  nodes.insert(nodes.begin() + 1, test::node({-radius * (1.0 - std::sqrt(0.5)), -radius * std::sqrt(0.5)}, std::nullopt,
                                             std::nullopt));
  // Only the S's middle node lies between two cubics here; it is flat, and no spare node.
  std::vector<OutlineNode> s{nodes[0], nodes[2], nodes[3]};
  EXPECT_FALSE(is_spare_node(s, false, 1, upm));
}

TEST(SpareNodes, ABowlBetweenCornersKeepsItsCornersAndExtremum) {
  // A D: the right half of the circle, each quarter cut in half, from its foot round through
  // (300, 0) to its top, and the stem back down; corners at both ends of the stem, which bind
  // no curvature.
  std::vector<Cubic> bowl = quarter(-0.5 * std::numbers::pi, 2);
  for (const Cubic& c : quarter(0.0, 2)) bowl.push_back(c);
  std::vector<OutlineNode> nodes = nodes_of(bowl);
  nodes.front().in_handle.reset(), nodes.front().smooth = false;
  nodes.push_back(test::node(bowl.back().p[3], bowl.back().p[2], std::nullopt, false));
  ASSERT_EQ(nodes.size(), 5u);
  const SampledContour source(to_contour(nodes, true));
  EXPECT_EQ(remove_spare_nodes(nodes, true, source, {1.25, upm}).removed, 2);
  ASSERT_EQ(nodes.size(), 3u);
  EXPECT_FALSE(nodes[0].smooth);
  EXPECT_NEAR(distance(nodes[1].point, Vec2{radius, 0.0}), 0.0, 1e-9);
  EXPECT_FALSE(nodes[2].smooth);
  EXPECT_FALSE(nodes[2].out_handle);  // the stem still a line
  const std::vector<Cubic> whole = quarter(-0.5 * std::numbers::pi, 1);
  for (std::size_t i = 0; i < 4; ++i) EXPECT_NEAR(distance(outline_cubic(nodes, 0).p[i], whole[0].p[i]), 0.0, 1e-6);
  // The same curve: only the samples' chords part them.
  EXPECT_LE(distance_between(SampledContour(to_contour(nodes, true)), source), 0.01);
}

// Junicode's 6 (OFL; UPM 1000) as its first fairing drew it before rounding: 11 nodes, a
// corner at each end of its stroke's cut. Against its own outline, on the 0.75 units a halved
// budget leaves, one spare node goes as the tangents stand, (92.8, 407.9) on the bowl's back.
// A second, (238.5, 534.9) on the stroke's way up, goes only with the tangent turned at the
// inflection node its window ends at, (376.1, 646.6): the cubics past it fitted again, κ = 0
// kept there on both sides.
TEST(SpareNodes, ATurnAtAnInflectionNodeFreesTheSpareNodeBesideIt) {
  const std::vector<OutlineNode> six{
      test::node({231.78969257502735, -8.0588124378379664}, Vec2{102.13527925222647, -8.0588124376890811}, Vec2{344.45389093017843, -8.0588124379673403}),
      test::node({422.0081905820893, 190.59656415205313}, Vec2{422.00819058198073, 81.597549386903651}, Vec2{422.00819058218946, 291.10561068959248}),
      test::node({270.97955378702665, 373.9526901245045}, Vec2{356.06483514858911, 373.95269012474347}, Vec2{232.6552619249311, 373.9526901243969}),
      test::node({137, 307}, Vec2{191.95608897894286, 357.14466834115944}, Vec2{148.40615278796443, 376.86893729415283}, false),
      test::node({238.46099377133424, 534.90379861228905}, Vec2{173.19034216927969, 458.75470507655064}, Vec2{297.51804746427086, 603.80369458738903}),
      test::node({376.08741991057985, 646.63177962663701}, Vec2{367.28607089638626, 641.83417322730406}, Vec2{380.2092640056772, 648.87859265220857}),
      test::node({383.64529134959133, 655.4002793253818}, Vec2{383.64529134951124, 650.75156766393422}, Vec2{383.64529134968484, 660.82924929229853}),
      test::node({370.11926954351861, 673.49314006149643}, Vec2{378.95903253687487, 673.49314006120289}, Vec2{369.17715829768412, 673.4931400615277}),
      test::node({367, 673}, Vec2{368.13302194208615, 673.34929654574307}, Vec2{236.21958705333324, 614.6537328667946}, false),
      test::node({92.794346517936717, 407.8523596443751}, Vec2{139.2603043380953, 500.78427528481996}, Vec2{77.600797019582188, 377.46526064762429}),
      test::node({48.9592701608927, 226.56968958348591}, Vec2{48.959270160865856, 311.62355827235154}, Vec2{48.959270160929279, 110.67758243452437}),
  };
  const SampledContour source(to_contour(six, true));
  std::vector<OutlineNode> kept = six, turned = six;
  const SpareNodeRemoval plain = remove_spare_nodes(kept, true, source, {0.75, upm});
  EXPECT_EQ(plain.removed, 1);
  EXPECT_EQ(plain.turned, 0);
  const SpareNodeRemoval turning = remove_spare_nodes(turned, true, source, {0.75, upm, true});
  EXPECT_EQ(turning.removed, 2);
  EXPECT_EQ(turning.turned, 1);
  ASSERT_EQ(turned.size(), 9u);
  EXPECT_LE(distance_between(SampledContour(to_contour(turned, true)), source), 0.75);
  int corners = 0, flat = 0;
  for (std::size_t k = 0; k < turned.size(); ++k) {
    const OutlineNode& q = turned[k];
    if (!q.smooth) {
      ++corners;
      continue;
    }
    // G1: the handles on one line through the node; G2: κ the same either side.
    const Vec2 in = q.point - *q.in_handle, out = *q.out_handle - q.point;
    EXPECT_NEAR(cross(in, out) / (norm(in) * norm(out)), 0.0, 1e-9) << k;
    const double before = end_kappa(outline_cubic(turned, (k + turned.size() - 1) % turned.size()));
    const double after = start_kappa(outline_cubic(turned, k));
    EXPECT_NEAR(before, after, 1e-9 * std::max(std::abs(before), 1.0 / upm)) << k;
    if (std::abs(after) * upm < 0.05) ++flat;
  }
  EXPECT_EQ(corners, 2);
  EXPECT_EQ(flat, 1);  // the inflection node, turned and still flat
  const auto direction = [](const OutlineNode& q) { return angle_of(*q.out_handle - q.point); };
  ASSERT_EQ(turned[4].point, six[5].point);
  const double turn = std::abs(direction(turned[4]) - direction(six[5])) * 180.0 / std::numbers::pi;
  EXPECT_GT(turn, 0.1);
  EXPECT_LE(turn, 4.0 + 1e-9);  // the most it may turn
  // Every other node's tangent as it was (its place in `six`: 4 and 9 went).
  const std::array<std::pair<std::size_t, std::size_t>, 8> same{{{0, 0}, {1, 1}, {2, 2}, {3, 3}, {5, 6}, {6, 7}, {7, 8}, {8, 10}}};
  for (const auto& [k, was] : same) {
    ASSERT_EQ(turned[k].point, six[was].point) << k;
    EXPECT_NEAR(direction(turned[k]), direction(six[was]), 1e-9) << k;
  }
}

}  // namespace
}  // namespace gf
