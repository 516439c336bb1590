// Balanced starting tangents: points on a circle give the circle's own tangents (every
// segment symmetric), open or closed; a κ = 0 start aims the next tangent at twice the chord
// angle.
#include "fair/initial_tangents.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace gf {
namespace {

double diff(double a, double b) { return std::remainder(a - b, 2 * std::numbers::pi); }

TEST(InitialTangents, CircleClosed) {
  std::vector<Vec2> pts;
  const int n = 7;
  for (int i = 0; i < n; ++i) {
    const double t = 2 * std::numbers::pi * i / n + 0.3 * std::sin(i);  // uneven spacing
    pts.push_back({100 * std::cos(t), 100 * std::sin(t)});
  }
  const std::vector<double> phi = balanced_tangents(pts, true, std::nullopt, std::nullopt);
  for (int i = 0; i < n; ++i) {
    const double t = std::atan2(pts[i].y, pts[i].x);
    EXPECT_NEAR(diff(phi[i], t + std::numbers::pi / 2), 0.0, 1e-4) << i;  // the pull to the bisectors is weak
  }
}

TEST(InitialTangents, CircleOpenWithExactEnds) {
  std::vector<Vec2> pts;
  for (int i = 0; i <= 5; ++i) {
    const double t = 0.25 * i * i;
    pts.push_back({80 * std::cos(t), 80 * std::sin(t)});
  }
  const double start = std::numbers::pi / 2, end = 0.25 * 25 + std::numbers::pi / 2;
  const std::vector<double> phi = balanced_tangents(pts, false, start, end);
  for (int i = 0; i <= 5; ++i) EXPECT_NEAR(diff(phi[i], 0.25 * i * i + std::numbers::pi / 2), 0.0, 1e-4) << i;
}

TEST(InitialTangents, ZeroCurvatureStartTurnsTheOtherEndTwiceAsMuch) {
  // Two segments; only the middle tangent is free. Its least-squares value balances
  // (φ1 − c0) = −2 (φ0 − c0) against the second segment's symmetry.
  const std::vector<Vec2> pts{{0, 0}, {100, 10}, {180, 60}};
  const std::vector<double> balanced = balanced_tangents(pts, false, 0.0, 0.9);
  const std::vector<double> zero = balanced_tangents(pts, false, 0.0, 0.9, true, false);
  const double c0 = std::atan2(10.0, 100.0);
  // From a κ = 0 start the end angle of the first segment grows.
  EXPECT_GT(zero[1] - c0, balanced[1] - c0);
}

}  // namespace
}  // namespace gf
