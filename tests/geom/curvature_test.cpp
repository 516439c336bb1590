#include "geom/curvature.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace gf {
namespace {

// y = x² on x ∈ [0, 1] as a quadratic Bézier: κ = 2 / (1 + 4x²)^(3/2),
// dκ/ds = dκ/dx / sqrt(1 + 4x²) = −24x / (1 + 4x²)^3.
TEST(Curvature, ParabolaMatchesClosedForm) {
  const Quad parabola{{{0, 0}, {0.5, 0}, {1, 1}}};
  for (const double t : {0.0, 0.1, 0.5, 0.77, 1.0}) {
    const Derivatives d = derivatives_at(parabola, t);
    const double x = d.point.x;
    ASSERT_NEAR(d.point.y, x * x, 1e-15);
    EXPECT_NEAR(*curvature(d), 2.0 / std::pow(1 + 4 * x * x, 1.5), 1e-14);
    EXPECT_NEAR(*curvature_derivative(d), -24.0 * x / std::pow(1 + 4 * x * x, 3.0), 1e-13);
  }
}

// The same parabola raised to a cubic, κ many times along it from its hodographs made once.
TEST(Curvature, AlongACubicMatchesTheClosedFormAndEachPlaceAlone) {
  const Cubic parabola = to_cubic(Quad{{{0, 0}, {0.5, 0}, {1, 1}}});
  const CurvatureAlong along(parabola);
  for (const double t : {0.0, 0.1, 0.5, 0.77, 1.0}) {
    const double x = parabola.point_at(t).x;
    EXPECT_NEAR(*along.at(t), 2.0 / std::pow(1 + 4 * x * x, 1.5), 1e-14);
    EXPECT_EQ(along.at(t), curvature(derivatives_at(parabola, t)));
  }
  EXPECT_FALSE(CurvatureAlong(Cubic{{{0, 0}, {0, 0}, {1, 1}, {2, 0}}}).at(0.0).has_value());  // retracted handle
}

TEST(Curvature, SignFollowsTheTurn) {
  const Quad left{{{0, 0}, {1, 0}, {1, 1}}};
  const Quad right{{{0, 0}, {1, 0}, {1, -1}}};
  EXPECT_GT(*curvature(derivatives_at(left, 0.5)), 0.0);
  EXPECT_LT(*curvature(derivatives_at(right, 0.5)), 0.0);
}

TEST(Curvature, CubicDerivativeOfCurvatureMatchesFiniteDifferenceInArcLength) {
  const Cubic c{{{0, 0}, {30, 80}, {120, 90}, {160, 10}}};
  const double t = 0.4, h = 1e-6;
  const Derivatives a = derivatives_at(c, t - h), b = derivatives_at(c, t + h), m = derivatives_at(c, t);
  const double ds = norm(m.d1) * 2 * h;
  EXPECT_NEAR(*curvature_derivative(m), (*curvature(b) - *curvature(a)) / ds, 1e-9);
}

TEST(Curvature, RetractedHandleEndIsUnboundedUnlessStraight) {
  const Cubic bent{{{0, 0}, {0, 0}, {1, 1}, {2, 0}}};
  EXPECT_FALSE(end_curvature(bent, SegmentEnd::start).curvature.has_value());
  EXPECT_TRUE(end_curvature(bent, SegmentEnd::end).curvature.has_value());
  const Cubic straight{{{0, 0}, {0, 0}, {1, 1}, {1, 1}}};
  EXPECT_EQ(end_curvature(straight, SegmentEnd::start).curvature, 0.0);
  // The tangent of a retracted handle comes from the next distinct control point.
  const auto t = end_tangent(bent, SegmentEnd::start);
  ASSERT_TRUE(t);
  EXPECT_NEAR(t->x, std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(t->y, std::sqrt(0.5), 1e-15);
}

TEST(Bezier, SplitAndSubsegmentKeepTheCurve) {
  const Cubic c{{0, 0}, {30, 80}, {120, 90}, {160, 10}};
  const auto [a, b] = c.split(0.3);
  EXPECT_EQ(a.p[0], c.p[0]);
  EXPECT_EQ(b.p[3], c.p[3]);
  for (const double u : {0.0, 0.25, 0.5, 1.0}) {
    EXPECT_NEAR(distance(a.point_at(u), c.point_at(0.3 * u)), 0.0, 1e-12);
    EXPECT_NEAR(distance(b.point_at(u), c.point_at(0.3 + 0.7 * u)), 0.0, 1e-12);
    EXPECT_NEAR(distance(c.subsegment(0.2, 0.6).point_at(u), c.point_at(0.2 + 0.4 * u)), 0.0, 1e-12);
  }
}

TEST(Curvature, DegenerateSegmentHasNoTangent) {
  EXPECT_FALSE(end_tangent(Line{{{3, 3}, {3, 3}}}, SegmentEnd::start).has_value());
}

}  // namespace
}  // namespace gf
