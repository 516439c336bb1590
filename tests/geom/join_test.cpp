#include "geom/join.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "test_shapes.hpp"

namespace gf {
namespace {

using test::closed;

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

// The check's rule: a curvature jump relative to the larger side where that side's |κ|·UPM is at
// least 0.5, else by |Δκ|·UPM (a curve that flat has no curvature to compare by ratio).
Join join_with(std::optional<double> in, std::optional<double> out) {
  Join j;
  j.kind = JoinKind::smooth;
  j.curvature_in = in, j.curvature_out = out;
  return j;
}

TEST(Join, ACurvatureJumpIsRelativeWhereEitherSideBendsVisibly) {
  // κ·UPM 10 against 10.4 on a 1000-unit em: 4 % of the larger side, within the 5 %.
  const std::optional<CurvatureJump> jump = curvature_jump(join_with(0.01, 0.0104), 1000.0);
  ASSERT_TRUE(jump);
  EXPECT_TRUE(jump->relative);
  EXPECT_NEAR(jump->value, 0.0004 / 0.0104, 1e-12);
  EXPECT_EQ(jump->limit, 0.05);
  EXPECT_FALSE(jump->exceeds());
  // κ·UPM 0.6 against 0: all of it.
  EXPECT_TRUE(curvature_jump(join_with(0.0006, 0.0), 1000.0)->exceeds());
}

TEST(Join, ACurvatureJumpIsAbsoluteWhereBothSidesAreNearlyFlat) {
  // κ·UPM 0.2 against 0.26 (both under 0.5): 0.06 per em, over the 0.05; a ratio would say 23 %.
  const std::optional<CurvatureJump> jump = curvature_jump(join_with(0.0002, 0.00026), 1000.0);
  ASSERT_TRUE(jump);
  EXPECT_FALSE(jump->relative);
  EXPECT_NEAR(jump->value, 0.06, 1e-12);
  EXPECT_TRUE(jump->exceeds());
  // κ·UPM 0.04 against 0, a curve leaving a line: under the 0.05.
  EXPECT_FALSE(curvature_jump(join_with(0.0, 0.00004), 1000.0)->exceeds());
  // The same curvatures on a 2048-unit em: 0.082 per em, over it.
  EXPECT_TRUE(curvature_jump(join_with(0.0, 0.00004), 2048.0)->exceeds());
}

TEST(Join, NoCurvatureJumpIsMeasuredWhereASideHasNoCurvature) {
  EXPECT_FALSE(curvature_jump(join_with(std::nullopt, 0.001), 1000.0));
}

}  // namespace
}  // namespace gf
