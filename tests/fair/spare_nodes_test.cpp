// The writeback's spare nodes (fair/spare_nodes): a smooth node between two cubics on neither
// axis and at no inflection goes where one cubic draws its two within the budget, the curvature
// staying continuous at every node and the curvature beyond the changed cubics kept.
#include "fair/spare_nodes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
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
  EXPECT_EQ(remove_spare_nodes(nodes, true, source, {1.25, upm}), 4);
  ASSERT_EQ(nodes.size(), 4u);
  const std::vector<Cubic> whole = circle(1);
  for (std::size_t k = 0; k < 4; ++k) {
    for (std::size_t i = 0; i < 4; ++i) EXPECT_NEAR(distance(outline_cubic(nodes, k).p[i], whole[k].p[i]), 0.0, 1e-6) << k << i;
    const double in = end_kappa(outline_cubic(nodes, (k + 3) % 4)), out = start_kappa(outline_cubic(nodes, k));
    EXPECT_NEAR(in, out, 1e-9 * std::abs(out));
  }
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
  EXPECT_EQ(remove_spare_nodes(nodes, true, source, {1.25, upm}), 0);
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
  EXPECT_EQ(remove_spare_nodes(nodes, true, source, {0.02, upm}), 0);
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
  EXPECT_EQ(remove_spare_nodes(nodes, true, source, {1.25, upm}), 2);
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

}  // namespace
}  // namespace gf
