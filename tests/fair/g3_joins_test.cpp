#include "fair/g3_joins.hpp"

#include <gtest/gtest.h>

#include "../test_shapes.hpp"

namespace gf {
namespace {

Contour closed_contour(std::vector<Segment> segments) {
  Contour c;
  c.segments = std::move(segments);
  c.nodes.assign(c.segments.size(), NodeFlags{});
  return c;
}

// A cubic split in two (de Casteljau) is the same curve: κ and dκ/ds agree at the new node.
TEST(G3Joins, ACubicSplitInTwoMatchesAtItsNewNode) {
  const Cubic whole{{{0, 0}, {100, 0}, {200, 100}, {200, 200}}};
  const auto [a, b] = whole.split(0.5);
  const G3JoinCount count = g3_joins_of(closed_contour({a, b, Line{{{200, 200}, {0, 0}}}}));
  EXPECT_EQ(count.joins, 1);
  EXPECT_EQ(count.matched, 1);
}

// Four cubic quarter arcs make a circle G2 at its nodes but not G3: κ along each arc is
// symmetric about its middle, so dκ/ds leaves one arc as −d and enters the next as +d, a jump
// of twice the larger side.
TEST(G3Joins, QuarterArcsJumpInCurvatureSlopeAtEveryNode) {
  const double h = 0.5522847498 * 100.0;
  const Contour circle = closed_contour({Cubic{{{100, 0}, {100, h}, {h, 100}, {0, 100}}},
                                         Cubic{{{0, 100}, {-h, 100}, {-100, h}, {-100, 0}}},
                                         Cubic{{{-100, 0}, {-100, -h}, {-h, -100}, {0, -100}}},
                                         Cubic{{{0, -100}, {h, -100}, {100, -h}, {100, 0}}}});
  const G3JoinCount strict = g3_joins_of(circle);
  EXPECT_EQ(strict.joins, 4);
  EXPECT_EQ(strict.matched, 0);
  EXPECT_EQ(g3_joins_of(circle, 2.5).matched, 4);  // the jump is 2 of the larger side
}

// Joins with a line are not counted (the bar's measure is between curves), nor corners.
TEST(G3Joins, OnlyJoinsBetweenTwoCurvesCount) {
  EXPECT_EQ(g3_joins_of(test::comic_neue_i_stem()).joins, 2);  // each cap's middle
  EXPECT_EQ(g3_joins_of(test::polygon({{0, 0}, {100, 0}, {100, 100}})).joins, 0);
}

}  // namespace
}  // namespace gf
