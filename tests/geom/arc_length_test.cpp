#include "geom/arc_length.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace gf {
namespace {

// Length of y = x² from 0 to a: [a sqrt(1 + 4a²) + asinh(2a) / 2] / 2.
double parabola_length(double a) { return 0.5 * (a * std::sqrt(1 + 4 * a * a) + 0.5 * std::asinh(2 * a)); }

TEST(ArcLength, ParabolaToTwelveDigits) {
  const Quad parabola{{{0, 0}, {1, 0}, {2, 4}}};  // y = x², x ∈ [0, 2]
  const ArcLength l = arc_length(parabola);
  EXPECT_TRUE(l.converged);
  EXPECT_NEAR(l.length, parabola_length(2.0), 1e-12 * parabola_length(2.0));
  // A part: x ∈ [0, 1] is t ∈ [0, 0.5].
  EXPECT_NEAR(arc_length(parabola, 0.0, 0.5).length, parabola_length(1.0), 1e-12);
}

TEST(ArcLength, LineIsItsChord) { EXPECT_DOUBLE_EQ(arc_length(Line{{{0, 0}, {3, 4}}}).length, 5.0); }

TEST(ArcLength, CubicWithCuspConverges) {
  // (0,0),(1,1),(0,1),(1,0) has a cusp at t = 0.5 and is symmetric about x = 0.5.
  const Cubic c{{{0, 0}, {1, 1}, {0, 1}, {1, 0}}};
  const ArcLength whole = arc_length(c);
  EXPECT_TRUE(whole.converged);
  EXPECT_NEAR(arc_length(c, 0.0, 0.5).length, 0.5 * whole.length, 1e-11);
}

TEST(ArcLength, TheEstimateMeetsTheParabolaAndItsCubicElevation) {
  const Quad parabola{{{0, 0}, {1, 0}, {2, 4}}};  // y = x², x ∈ [0, 2]; C′(t) = (2, 8t)
  EXPECT_EQ(derivative_at(parabola, 0.25), (Vec2{2, 2}));
  EXPECT_EQ(derivative_at(to_cubic(parabola), 0.25), (Vec2{2, 2}));
  EXPECT_NEAR(arc_length_estimate(parabola), parabola_length(2.0), 1e-7 * parabola_length(2.0));
  EXPECT_NEAR(arc_length_estimate(to_cubic(parabola), 0.0, 0.5), parabola_length(1.0), 1e-7);
  EXPECT_DOUBLE_EQ(arc_length_estimate(Line{{{0, 0}, {3, 4}}}, 0.0, 0.5), 2.5);
}

TEST(ArcLength, QuadraticAndItsCubicElevationAgree) {
  const Quad q{{{0, 0}, {50, 120}, {200, 10}}};
  EXPECT_NEAR(arc_length(q).length, arc_length(to_cubic(q)).length, 1e-10);
}

}  // namespace
}  // namespace gf
