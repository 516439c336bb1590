// How a cubic's curvature runs inside, against cubics whose κ(t) is known in shape.
#include "fair/cubic_change.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace gf {
namespace {

int turns(const Cubic& c, double hysteresis) { return curvature_shape(c, hysteresis).turns; }

TEST(CurvatureShape, ASymmetricArchTurnsOnceAtItsMiddle) {
  // Mirror-symmetric about t = ½, κ from −0.12 at the ends to −1.33 in the middle: one turn,
  // none once the hysteresis exceeds that range.
  const Cubic arch{{0, 0}, {1, 2}, {2, 2}, {3, 0}};
  EXPECT_EQ(turns(arch, 0.01), 1);
  EXPECT_EQ(turns(arch, 1.3), 0);
  EXPECT_EQ(curvature_shape(arch, 0.0).sign_changes, 0);
}

TEST(CurvatureShape, AQuarterCircleApproximantOnlyWobbles) {
  // The usual four-cubic circle (handles 0.5523 of the radius): κ = 1 within 3 %, swinging
  // above and below three times; under a hysteresis of 5 % of κ that is no turn.
  const Cubic quarter{{0, 0}, {0, 0.5523}, {0.4477, 1}, {1, 1}};
  EXPECT_EQ(turns(quarter, 1e-4), 3);
  EXPECT_EQ(turns(quarter, 0.05), 0);
}

TEST(CurvatureShape, MonotoneCurvatureAndStraightLinesDoNotTurn) {
  EXPECT_EQ(turns(Cubic{{0, 0}, {1, 0}, {2, 0.5}, {3, 1.5}}, 1e-9), 0);
  EXPECT_EQ(turns(Cubic{{0, 0}, {1, 1}, {2, 2}, {3, 3}}, 1e-9), 0);
}

TEST(CubicTurning, ArcsTurnTheirAngleAndLoopsTurnTheLongWayRound) {
  // A quarter-circle approximant turns π/2 (its polyline at 24ths within 1e-3 of it); a
  // straight cubic not at all; a cubic whose handles cross over turns the long way round, a
  // whole turn less the angle between its end tangents, where an arc would turn that angle:
  // what the rounding's fold test (a quarter turn more than the unrounded cubic) catches.
  EXPECT_NEAR(cubic_turning(Cubic{{0, 0}, {0, 0.5523}, {0.4477, 1}, {1, 1}}), std::numbers::pi / 2, 1e-3);
  EXPECT_NEAR(cubic_turning(Cubic{{0, 0}, {1, 1}, {2, 2}, {3, 3}}), 0.0, 1e-12);
  const Cubic loop{{0, 0}, {3, 2}, {-1, 2}, {2, 0}};
  const double ends = std::abs(turning_angle(loop.p[1] - loop.p[0], loop.p[3] - loop.p[2]));
  EXPECT_NEAR(cubic_turning(loop), 2.0 * std::numbers::pi - ends, 1e-2);
  EXPECT_GT(cubic_turning(loop), ends + std::numbers::pi / 2);
}

}  // namespace
}  // namespace gf
