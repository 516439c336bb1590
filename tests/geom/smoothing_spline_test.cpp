// The smoothing spline against oracles: a parabola lies in the penalty's null space (no third
// derivative), so a tight fit smooths as hard as it can and still keeps its curvature; a circle with
// noise inside the tolerance comes back within the tolerance with its curvature of one sign
// and near 1/R; held end tangents and interpolated ends are exact.
#include "geom/smoothing_spline.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "geom/curvature.hpp"

namespace gf {
namespace {

TEST(SmoothingSpline, AParabolaKeepsItsCurvature) {
  const double a = 0.004;
  std::vector<Vec2> pts;
  for (int i = 0; i <= 200; ++i) {
    const double x = -100.0 + i;
    pts.push_back({x, a * x * x});
  }
  const BSplineFit fit = fit_smoothing_spline(pts, 1e-3, 12, false);
  ASSERT_EQ(fit.spans.size(), 12u);
  EXPECT_LE(fit.max_residual, 1e-3 * 1.001);
  // y = a x²: κ = 2a / (1 + 4a²x²)^{3/2}, at the spline's own x.
  double worst = 0.0;
  for (const Cubic& c : fit.spans)
    for (int k = 0; k <= 10; ++k) {
      const Derivatives d = derivatives_at(c, k / 10.0);
      const double exact = 2 * a / std::pow(1 + 4 * a * a * d.point.x * d.point.x, 1.5);
      worst = std::max(worst, std::abs(*curvature(d) / exact - 1.0));
    }
  EXPECT_LT(worst, 0.02);
}

TEST(SmoothingSpline, ANoisyCircleComesBackRoundWithinTheTolerance) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> noise(-3.0, 3.0);
  const double r = 200.0, tolerance = 5.0;
  std::vector<Vec2> pts;
  for (int i = 0; i < 600; ++i) {
    const double t = 2.0 * std::numbers::pi * i / 600;
    const double rr = r + noise(rng);  // wobbles of up to 3 units: well inside the tolerance
    pts.push_back({rr * std::cos(t), rr * std::sin(t)});
  }
  const BSplineFit fit = fit_smoothing_spline(pts, tolerance, 40, true);
  ASSERT_EQ(fit.spans.size(), 40u);
  EXPECT_LE(fit.max_residual, tolerance * 1.001);
  for (const Cubic& c : fit.spans)
    for (int k = 0; k <= 20; ++k) {
      const double kappa = *curvature(derivatives_at(c, k / 20.0));
      EXPECT_GT(kappa, 0.0);                   // no inflection: the wobbles are gone
      EXPECT_NEAR(kappa * r, 1.0, 0.1);        // and the circle is round
    }
  // Closed: the last span returns to the first, C2 across the seam too.
  EXPECT_NEAR(distance(fit.spans.back().p[3], fit.spans.front().p[0]), 0.0, 1e-9);
}

TEST(SmoothingSpline, HeldEndTangentsAndEndPointsAreExact) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> noise(-1.0, 1.0);
  std::vector<Vec2> pts;
  for (int i = 0; i <= 300; ++i) {
    const double t = std::numbers::pi * i / 300;
    pts.push_back({300.0 * std::cos(t) + noise(rng), 150.0 * std::sin(t) + noise(rng)});
  }
  pts.front() = {300.0, 0.0}, pts.back() = {-300.0, 0.0};
  SmoothingEnds ends;
  ends.start_tangent = Vec2{0.0, 1.0};
  ends.end_tangent = Vec2{0.0, -1.0};
  const BSplineFit fit = fit_smoothing_spline(pts, 3.0, 24, false, ends);
  ASSERT_FALSE(fit.spans.empty());
  EXPECT_LE(fit.max_residual, 3.0 * 1.001);
  EXPECT_EQ(fit.spans.front().p[0], pts.front());
  EXPECT_EQ(fit.spans.back().p[3], pts.back());
  const Vec2 t0 = fit.spans.front().p[1] - fit.spans.front().p[0];
  const Vec2 t1 = fit.spans.back().p[3] - fit.spans.back().p[2];
  EXPECT_NEAR(t0.x, 0.0, 1e-9);
  EXPECT_GT(t0.y, 0.0);
  EXPECT_NEAR(t1.x, 0.0, 1e-9);
  EXPECT_LT(t1.y, 0.0);
}

}  // namespace
}  // namespace gf
