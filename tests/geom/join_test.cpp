#include "geom/join.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace gf {
namespace {

Contour closed(std::vector<Segment> segments) {
  Contour c;
  c.nodes.assign(segments.size(), NodeFlags{});
  c.segments = std::move(segments);
  return c;
}

TEST(Join, SquareHasFourLeftCorners) {
  const auto joins = joins_of(closed({Line{{{0, 0}, {1, 0}}}, Line{{{1, 0}, {1, 1}}}, Line{{{1, 1}, {0, 1}}},
                                      Line{{{0, 1}, {0, 0}}}}));
  ASSERT_EQ(joins.size(), 4u);
  for (const Join& j : joins) {
    EXPECT_EQ(j.kind, JoinKind::corner);
    EXPECT_NEAR(j.angle_deg, 90.0, 1e-12);
    EXPECT_EQ(j.curvature_in, 0.0);
  }
}

TEST(Join, TangentLineToArcIsSmoothWithACurvatureJump) {
  // A line along +x into a quarter-circle-like cubic of radius 1: G1, not G2.
  const double k = 0.5522847498307936;
  const Contour c = closed({Line{{{-1, 0}, {0, 0}}}, Cubic{{{0, 0}, {k, 0}, {1, 1 - k}, {1, 1}}},
                            Line{{{1, 1}, {-1, 0}}}});
  const auto joins = joins_of(c);
  const Join& j = joins[1];
  EXPECT_EQ(j.kind, JoinKind::smooth);
  EXPECT_NEAR(j.angle_deg, 0.0, 1e-12);
  EXPECT_EQ(*j.curvature_in, 0.0);
  EXPECT_NEAR(*j.curvature_out, 2.0 * (1 - k) / (3.0 * k * k), 1e-12);  // (2/3)|Δ0×Δ1|/|Δ0|³
}

TEST(Join, SmallAngleIsAKinkAndFlaggedSmoothStaysOne) {
  const double a = 1.0 * M_PI / 180.0;  // 1°
  Contour c = closed({Line{{{0, 0}, {1, 0}}}, Line{{{1, 0}, {1 + std::cos(a), std::sin(a)}}},
                      Line{{{1 + std::cos(a), std::sin(a)}, {0, 0}}}});
  EXPECT_EQ(joins_of(c)[1].kind, JoinKind::kink);
  EXPECT_NEAR(joins_of(c)[1].angle_deg, 1.0, 1e-9);
  c.nodes[2].smooth = true;  // a source that says smooth at a real corner: broken smooth node
  EXPECT_EQ(joins_of(c)[2].kind, JoinKind::kink);
}

TEST(Join, OpenContourHasNoJoinAtItsEnds) {
  Contour c;
  c.closed = false;
  c.segments = {Line{{{0, 0}, {1, 0}}}, Line{{{1, 0}, {2, 1}}}};
  c.nodes.assign(3, NodeFlags{});
  const auto joins = joins_of(c);
  ASSERT_EQ(joins.size(), 1u);
  EXPECT_EQ(joins[0].node, 1u);
}

TEST(Join, ZeroLengthSegmentMakesADegenerateJoin) {
  const auto joins = joins_of(closed({Line{{{0, 0}, {1, 0}}}, Line{{{1, 0}, {1, 0}}}, Line{{{1, 0}, {0, 0}}}}));
  EXPECT_EQ(joins[1].kind, JoinKind::degenerate);
}

}  // namespace
}  // namespace gf
