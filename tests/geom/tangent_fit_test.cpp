// The cubic with given end tangents nearest a run of points: points taken from such a cubic give
// it back; points of a quarter circle give handles of the least-squares quarter circle.
#include "geom/tangent_fit.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace gf {
namespace {

TEST(TangentFit, PointsOfACubicGiveItBack) {
  const Cubic c{{0.0, 0.0}, {60.0, 10.0}, {150.0, 80.0}, {170.0, 200.0}};
  std::vector<Vec2> points;
  // Unevenly in the parameter, so chord lengths alone would not do.
  for (int k = 0; k <= 60; ++k) points.push_back(c.point_at(std::pow(k / 60.0, 1.3)));
  const Vec2 t0 = (c.p[1] - c.p[0]) / norm(c.p[1] - c.p[0]), t3 = (c.p[3] - c.p[2]) / norm(c.p[3] - c.p[2]);
  const std::optional<Cubic> fit = fit_cubic_with_end_tangents(c.p[0], t0, c.p[3], t3, points);
  ASSERT_TRUE(fit);
  EXPECT_NEAR(distance(fit->p[1], c.p[1]), 0.0, 1e-6);
  EXPECT_NEAR(distance(fit->p[2], c.p[2]), 0.0, 1e-6);
}

TEST(TangentFit, AQuarterCircle) {
  // The cubic nearest a quarter of the unit circle in least squares has handles of about
  // 0.5519 (Riškus's minimax value 0.551915); either way within 1e-3 of it.
  const double r = 100.0;
  std::vector<Vec2> points;
  for (int k = 0; k <= 200; ++k) {
    const double a = 0.5 * std::numbers::pi * k / 200.0;
    points.push_back({r * std::cos(a), r * std::sin(a)});
  }
  const std::optional<Cubic> fit = fit_cubic_with_end_tangents({r, 0.0}, {0.0, 1.0}, {0.0, r}, {-1.0, 0.0}, points);
  ASSERT_TRUE(fit);
  EXPECT_NEAR(distance(fit->p[0], fit->p[1]) / r, 0.5519, 1e-3);
  EXPECT_NEAR(distance(fit->p[3], fit->p[2]) / r, 0.5519, 1e-3);
}

TEST(TangentFit, HandlesPointingAwayGiveNone) {
  // Points bulging to the right of a chord whose end tangents both point left of it.
  std::vector<Vec2> points;
  for (int k = 0; k <= 20; ++k) {
    const double t = k / 20.0;
    points.push_back({100.0 * t, -30.0 * std::sin(std::numbers::pi * t)});
  }
  const double s = std::sqrt(0.5);
  EXPECT_FALSE(fit_cubic_with_end_tangents({0.0, 0.0}, {s, s}, {100.0, 0.0}, {s, -s}, points));
}

}  // namespace
}  // namespace gf
