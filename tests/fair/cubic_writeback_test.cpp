// The cubic writeback of a faired chain: an extremum a few units from a corner; the shortest
// span it halves.
#include "fair/cubic_writeback.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "aesthetic/segment_fit.hpp"

namespace gf {
namespace {

// A chain leaving a corner 2° right of the vertical and turning left by 60°: its vertical
// extremum lies about 10 units from the corner.
FairedChain stroke_leaving_a_corner() {
  const double lean = radians(2.0), turn = radians(60.0);
  const Vec2 p0{100, 0}, p1 = p0 + Vec2{std::sin(lean), std::cos(lean)} * 100.0;
  const Vec2 p2 = p1 + Vec2{std::sin(lean - turn), std::cos(lean - turn)} * 100.0;
  const SegmentFit fit = fit_three_point(p0, p1, p2, 1.0);
  FairedChain chain;
  if (fit.ok()) chain.segments.push_back(*fit.segment);
  return chain;
}

TEST(CubicWriteback, AnExtremumNextToACornerIsTheCorner) {
  const FairedChain chain = stroke_leaving_a_corner();
  ASSERT_EQ(chain.segments.size(), 1u);
  const double budget = 2.0, flat = 5e-4;
  // As a smooth end (or a corner left alone): a node at the extremum, a few units up.
  const ChainCubics kept = write_chain_as_cubics(chain, budget, flat);
  ASSERT_GE(kept.nodes.size(), 3u);
  EXPECT_LT(distance(kept.nodes[1].point, kept.nodes[0].point), 20.0);
  ASSERT_TRUE(kept.nodes[1].grid_step);
  EXPECT_EQ(*kept.nodes[1].grid_step, (Vec2{0, 1}));
  // At a corner: the corner's tangent turns onto the vertical and the extremum's node goes.
  const ChainCubics snapped = write_chain_as_cubics(chain, budget, flat, {.start_corner = true});
  ASSERT_GE(snapped.nodes.size(), 2u);
  EXPECT_LT(snapped.nodes.size(), kept.nodes.size());
  const OutlineNode& corner = snapped.nodes.front();
  EXPECT_EQ(corner.point, kept.nodes.front().point);
  ASSERT_TRUE(corner.out_handle && corner.grid_step);
  EXPECT_NEAR(corner.out_handle->x, corner.point.x, 1e-9);
  EXPECT_GT(corner.out_handle->y, corner.point.y);
  EXPECT_EQ(*corner.grid_step, (Vec2{0, 1}));
  for (std::size_t k = 1; k < snapped.nodes.size(); ++k) EXPECT_GT(distance(snapped.nodes[k].point, corner.point), 20.0);
  // The end of the chain is no corner: its node stays where the chain ends.
  EXPECT_EQ(snapped.nodes.back().point, kept.nodes.back().point);
}

// Halving a span that misses the budget stops short of `shortest_span_units`: cubics of two to
// four units, as the default allows, round onto a few grid points whose whole steps cannot set
// their curvature (Lato's W had two of four units at its middle apex, κ·UPM 1,333 and 4,000
// once rounded), so a rounded outline asks for eight (fair/contour_fairing.cpp).
TEST(CubicWriteback, NoHalfOfASpanIsShorterThanHalfTheShortestSpan) {
  const FairedChain chain = stroke_leaving_a_corner();
  ASSERT_EQ(chain.segments.size(), 1u);
  const double unreachable = 1e-9, flat = 5e-4;
  const auto shortest_cubic = [](const ChainCubics& c) {
    double shortest = 1e300;
    for (std::size_t k = 0; k + 1 < c.nodes.size(); ++k) shortest = std::min(shortest, distance(c.nodes[k].point, c.nodes[k + 1].point));
    return shortest;
  };
  const ChainCubics fine = write_chain_as_cubics(chain, unreachable, flat);
  const ChainCubics coarse = write_chain_as_cubics(chain, unreachable, flat, {}, 8.0);
  EXPECT_LT(coarse.nodes.size(), fine.nodes.size());
  EXPECT_LT(shortest_cubic(fine), 4.0);
  EXPECT_GE(shortest_cubic(coarse), 4.0 - 1e-6);
}

}  // namespace
}  // namespace gf
