// Rounding to the grid: integer coordinates everywhere, and G1 exact — a smooth node's two
// handles exactly collinear with it (integer cross product zero), axis nodes axis-parallel.
#include "fair/grid_rounding.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace gf {
namespace {

bool on_grid(Vec2 p) { return p.x == std::round(p.x) && p.y == std::round(p.y); }

TEST(GridRounding, PrimitiveStepsDivideByTheCommonDivisor) {
  // DejaVu's s spine: (63, −14) = 7·(9, −2).
  EXPECT_EQ(primitive_step({63, -14}), (Vec2{9, -2}));
  EXPECT_EQ(primitive_step({0, -5}), (Vec2{0, -1}));
  EXPECT_EQ(primitive_step({-270, -1650}), (Vec2{-9, -55}));
  EXPECT_FALSE(primitive_step({0, 0}));
  EXPECT_TRUE(is_primitive({2, 1}));
  EXPECT_TRUE(is_primitive({-1, 0}));
  EXPECT_FALSE(is_primitive({2, 2}));
  EXPECT_FALSE(is_primitive({0, 0}));
}

TEST(GridRounding, SmoothNodesStayExactlyCollinear) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    // A closed contour of 6 smooth nodes on a wobbly circle, handles along the tangent.
    std::vector<OutlineNode> nodes;
    for (int i = 0; i < 6; ++i) {
      const double t = i * std::numbers::pi / 3 + 0.2 * u(rng);
      const double r = 300 + 40 * u(rng);
      const Vec2 p{r * std::cos(t) + 0.37, r * std::sin(t) - 0.81};
      const Vec2 tangent{-std::sin(t), std::cos(t)};
      OutlineNode n;
      n.point = p;
      n.in_handle = p - tangent * (60 + 30 * u(rng));
      n.out_handle = p + tangent * (60 + 30 * u(rng));
      if (i % 3 == 0) n.grid_step = std::abs(tangent.x) > std::abs(tangent.y) ? Vec2{tangent.x > 0 ? 1.0 : -1.0, 0.0}
                                                                             : Vec2{0.0, tangent.y > 0 ? 1.0 : -1.0};
      nodes.push_back(n);
    }
    const std::vector<OutlineNode> r = round_to_grid(nodes, true);
    ASSERT_EQ(r.size(), nodes.size());
    for (const OutlineNode& n : r) {
      EXPECT_TRUE(on_grid(n.point) && on_grid(*n.in_handle) && on_grid(*n.out_handle));
      EXPECT_EQ(cross(n.point - *n.in_handle, *n.out_handle - n.point), 0.0);  // exact in integers
      EXPECT_GT(dot(n.point - *n.in_handle, *n.out_handle - n.point), 0.0);
    }
    // Nodes move to a neighbouring grid point at most; handles are placed for G1 and G2.
    for (std::size_t i = 0; i < nodes.size(); ++i) EXPECT_LE(distance(r[i].point, nodes[i].point), 1.5 * std::sqrt(2.0));
  }
}

TEST(GridRounding, CornersRoundFreelyAndLinesKeepTheirHandleOnTheLine) {
  // A line (0,0)→(200.3,0.2) meeting a curve tangentially at node 1, then a corner.
  std::vector<OutlineNode> nodes(3);
  nodes[0].point = {0.2, 0.1};
  nodes[0].smooth = false;
  nodes[0].in_handle = Vec2{30.4, 150.6};
  nodes[1].point = {200.3, 0.2};
  nodes[1].out_handle = Vec2{260.7, 0.2};
  nodes[2].point = {300.4, 100.6};
  nodes[2].smooth = false;
  nodes[2].in_handle = Vec2{300.4, 60.2};
  nodes[2].out_handle = Vec2{150.2, 180.9};
  const std::vector<OutlineNode> r = round_to_grid(nodes, true);
  const OutlineNode& join = r[1];
  EXPECT_EQ(cross(join.point - r[0].point, *join.out_handle - join.point), 0.0);
  for (const OutlineNode& n : r) EXPECT_TRUE(on_grid(n.point));
}

}  // namespace
}  // namespace gf
