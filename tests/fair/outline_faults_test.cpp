// The faults of a faired contour as the fairing issue's check counts them (fair/outline_faults),
// on contours whose faults are known by construction, and how two versions compare.
#include "fair/outline_faults.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "geom/critical_points.hpp"
#include "geom/join.hpp"
#include "test_shapes.hpp"

namespace gf {
namespace {

constexpr double upm = 1000.0;

using test::closed;

const Contour square = closed({Line{{{0, 0}, {100, 0}}}, Line{{{100, 0}, {100, 100}}}, Line{{{100, 100}, {0, 100}}},
                               Line{{{0, 100}, {0, 0}}}});

void expect_faults(const OutlineFaults& f, const OutlineFaults& want) {
  EXPECT_EQ(f.jumps, want.jumps);
  EXPECT_EQ(f.kinks, want.kinks);
  EXPECT_EQ(f.inflections, want.inflections);
  EXPECT_EQ(f.corners_lost, want.corners_lost);
}

TEST(OutlineFaults, ASquareHasNone) { expect_faults(FaultCounter(square, upm).count(square), {}); }

TEST(OutlineFaults, ACurveLeavingALineBentHasAJump) {
  // The cubic leaves the baseline tangentially with κ = (2/3)·(30·10)/30³ = 1/135 (κ·UPM 7.4)
  // against the line's 0; its far end is a corner, as are the lines' other ends.
  const Contour c = closed({Line{{{0, 0}, {100, 0}}}, Cubic{{{100, 0}, {130, 0}, {150, 10}, {160, 30}}},
                            Line{{{160, 30}, {0, 100}}}, Line{{{0, 100}, {0, 0}}}});
  expect_faults(FaultCounter(c, upm).count(c), {.jumps = 1});
}

TEST(OutlineFaults, JumpingJoinsAreWhereTheJumpsAre) {
  // The same contour: its one jump at (100, 0), where the cubic leaves the line; the square's
  // joins are corners and have none.
  const Contour c = closed({Line{{{0, 0}, {100, 0}}}, Cubic{{{100, 0}, {130, 0}, {150, 10}, {160, 30}}},
                            Line{{{160, 30}, {0, 100}}}, Line{{{0, 100}, {0, 0}}}});
  EXPECT_EQ(joins_at_fault(c, JoinFault::jump, upm), std::vector<Vec2>{Vec2(100, 0)});
  EXPECT_TRUE(joins_at_fault(square, JoinFault::jump, upm).empty());
}

TEST(OutlineFaults, AJumpOfExactlyTheLimitIsAJump) {
  // κ·UPM 19/1.024 against 20/1.024, binary fractions: (20 − 19)/20 is 0.05 to the last bit,
  // the check's own limit, which its rule lets pass and a checker rounding otherwise does not.
  Join j;
  j.kind = JoinKind::smooth;
  j.curvature_in = 19.0 / 1024.0, j.curvature_out = 20.0 / 1024.0;
  EXPECT_FALSE(curvature_jump(j, upm)->exceeds());
  EXPECT_EQ(join_fault(j, {}, upm), JoinFault::jump);
  // A hair under it is none.
  j.curvature_in = 19.0001 / 1024.0;
  EXPECT_EQ(join_fault(j, {}, upm), JoinFault::none);
}

TEST(OutlineFaults, ATangentBrokenByADegreeIsAKink) {
  const double rise = 100.0 * std::tan(std::numbers::pi / 180.0);
  const Contour c = closed({Line{{{0, 0}, {100, 0}}}, Line{{{100, 0}, {200, rise}}}, Line{{{200, rise}, {200, 100}}},
                            Line{{{200, 100}, {0, 0}}}});
  expect_faults(FaultCounter(c, upm).count(c), {.kinks = 1});
}

TEST(OutlineFaults, AnSCurveHasAnInflectionAndARoundedCornerIsLost) {
  // The square's corner at (100, 100) rounded off by a cubic from (100, 80) to (80, 100), the
  // lines' tangents kept (two curvature jumps: the cubic bends at both ends), and the base
  // drawn as an S from (0, 0) to (100, 0).
  const Contour c = closed({Cubic{{{0, 0}, {50, 20}, {50, -20}, {100, 0}}}, Line{{{100, 0}, {100, 80}}},
                            Cubic{{{100, 80}, {100, 91}, {91, 100}, {80, 100}}}, Line{{{80, 100}, {0, 100}}},
                            Line{{{0, 100}, {0, 0}}}});
  // (100, 100) lost; (0, 0) and (100, 0) stay corners, turning by 90° less the S's 22°.
  expect_faults(FaultCounter(square, upm).count(c), {.jumps = 2, .inflections = 1, .corners_lost = 1});
}

TEST(OutlineFaults, InflectionsCountOnlyBeyondTheSources) {
  // The S of the test above against itself: its one inflection is the source's.
  const Contour s_curve = closed({Cubic{{{0, 0}, {50, 20}, {50, -20}, {100, 0}}}, Line{{{100, 0}, {100, 100}}},
                                  Line{{{100, 100}, {0, 100}}}, Line{{{0, 100}, {0, 0}}}});
  EXPECT_EQ(inflections_along(s_curve, joins_of(s_curve), upm, JoinThresholds{}.kink_max_deg), 1);
  EXPECT_EQ(FaultCounter(s_curve, upm).count(s_curve).inflections, 0);
  EXPECT_EQ(FaultCounter(square, upm).count(s_curve).inflections, 1);
}

TEST(OutlineFaults, CurvatureChangingSignThroughAFlatNodeIsAnInflection) {
  // Two cubics meet level at (100, 0), each with its handles on one line through the node, so
  // κ = 0 there from both sides; the first bends right into it, the second left out of it
  // (Spartan's e rounded: its right side's cubics, handles on one point, wobbling so). The
  // check sees the sign change across the node; neither cubic has one inside.
  Contour c;
  c.closed = false;
  c.segments = {Cubic{{{0, -10}, {30, 0}, {60, 0}, {100, 0}}}, Cubic{{{100, 0}, {140, 0}, {170, 0}, {200, 10}}}};
  c.nodes.assign(3, NodeFlags{});
  for (const Segment& s : c.segments) ASSERT_TRUE(inflections(s).empty());
  EXPECT_EQ(inflections_along(c, joins_of(c), upm, JoinThresholds{}.kink_max_deg), 1);
  // Cut at a corner there instead, the two bends belong to different stretches.
  c.segments[1] = Cubic{{{100, 0}, {140, 10}, {170, 30}, {200, 60}}};
  ASSERT_TRUE(inflections(c.segments[1]).empty());
  EXPECT_EQ(inflections_along(c, joins_of(c), upm, JoinThresholds{}.kink_max_deg), 0);
}

TEST(OutlineFaults, FewerJumpsAreBetterWithNoMoreKinksOrLostCornersAndAtMostTwoInflectionsEach) {
  const OutlineFaults two_jumps{2, 0, 1, 0};
  EXPECT_TRUE(fewer_faults({1, 0, 1, 0}, two_jumps));
  EXPECT_FALSE(fewer_faults(two_jumps, two_jumps));
  EXPECT_FALSE(fewer_faults({0, 1, 1, 0}, two_jumps));  // a jump traded for a kink
  EXPECT_FALSE(fewer_faults({0, 0, 1, 1}, two_jumps));  // for a corner rounded off
  EXPECT_TRUE(fewer_faults({1, 0, 1, 0}, {1, 1, 1, 0}));  // a kink mended
  EXPECT_FALSE(fewer_faults({2, 0, 1, 0}, {1, 1, 1, 0}));  // a kink traded for a jump: as many
  EXPECT_TRUE(fewer_faults({0, 0, 0, 0}, two_jumps));
  // A jump may cost up to two inflections beyond the source's, not more.
  EXPECT_TRUE(fewer_faults({1, 0, 3, 0}, two_jumps));
  EXPECT_FALSE(fewer_faults({1, 0, 4, 0}, two_jumps));
  EXPECT_TRUE(fewer_faults({0, 0, 5, 0}, two_jumps));
  // Fewer inflections beyond the source's are better with as many jumps, not with more.
  EXPECT_TRUE(fewer_faults({2, 0, 0, 0}, two_jumps));
  EXPECT_FALSE(fewer_faults({3, 0, 0, 0}, two_jumps));
}

}  // namespace
}  // namespace gf
