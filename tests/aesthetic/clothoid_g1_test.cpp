// The G1 Hermite clothoid against lac-math.md §7.2's reference (check_09_clothoid_g1.py), the
// circle's closed form, and its end conditions integrated independently.
#include "aesthetic/clothoid_g1.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace gf {
namespace {

// The clothoid's end by composite Simpson on θ(s) = θ₀ + κ₀s + κ′s²/2: independent of the
// Gauss rule the fit uses.
struct End {
  Vec2 point;
  double angle;
};
End clothoid_end(Vec2 p0, double theta0, const ClothoidArc& a) {
  const int n = 20000;
  const double h = a.length / n;
  Vec2 sum{};
  for (int k = 0; k <= n; ++k) {
    const double s = k * h;
    const double w = (k == 0 || k == n) ? 1.0 : (k % 2 ? 4.0 : 2.0);
    sum += w * direction_of(theta0 + a.curvature * s + 0.5 * a.curvature_slope * s * s);
  }
  return {p0 + sum * (h / 3.0), theta0 + a.curvature * a.length + 0.5 * a.curvature_slope * a.length * a.length};
}

TEST(ClothoidG1, MatchesTheReferenceExample) {
  // lac-math.md §7.2: build_G1((0,0), 0.3 → (2,1), −0.4).
  const ClothoidFit fit = fit_clothoid_g1({0, 0}, 0.3, {2, 1}, -0.4);
  ASSERT_TRUE(fit.ok()) << fit.reason;
  EXPECT_NEAR(fit.arc->length, 2.341558741015, 1e-11);
  EXPECT_NEAR(fit.arc->curvature, 1.003138876303, 1e-11);
  EXPECT_NEAR(fit.arc->curvature_slope, -1.11215235906, 1e-10);
  EXPECT_LE(fit.iterations, 4);
}

TEST(ClothoidG1, SymmetricEndsGiveTheCircularArc) {
  // Chord 3 at angles ±φ to it: radius R = 1.5 / sin φ, length 2φR, κ′ = 0.
  for (const double phi : {0.1, 0.7, 1.4, 2.5}) {
    const ClothoidFit fit = fit_clothoid_g1({1, 1}, phi, {4, 1}, -phi);
    ASSERT_TRUE(fit.ok()) << phi << ": " << fit.reason;
    const double radius = 1.5 / std::sin(phi);
    EXPECT_NEAR(fit.arc->curvature, -1.0 / radius, 1e-12) << phi;
    EXPECT_NEAR(fit.arc->curvature_slope, 0.0, 1e-12) << phi;
    EXPECT_NEAR(fit.arc->length, 2.0 * phi * radius, 1e-11 * radius) << phi;
  }
}

TEST(ClothoidG1, MeetsItsEndConditionsOnRandomAngles) {
  std::mt19937 random(5);
  std::uniform_real_distribution<double> angle(-0.95 * std::numbers::pi, 0.95 * std::numbers::pi);
  for (int trial = 0; trial < 200; ++trial) {
    const double theta0 = angle(random), theta1 = angle(random);
    const Vec2 p0{-2.0, 3.0}, p1{5.0, -1.0};
    const double phi = angle_of(p1 - p0);
    const ClothoidFit fit = fit_clothoid_g1(p0, phi + theta0, p1, phi + theta1);
    ASSERT_TRUE(fit.ok()) << theta0 << " " << theta1 << ": " << fit.reason;
    EXPECT_LE(fit.iterations, 6);
    const End e = clothoid_end(p0, phi + theta0, *fit.arc);
    EXPECT_LT(distance(e.point, p1), 1e-9) << theta0 << " " << theta1;
    EXPECT_NEAR(std::remainder(e.angle - (phi + theta1), 2.0 * std::numbers::pi), 0.0, 1e-12);
  }
}

TEST(ClothoidG1, CoincidentEndsSayWhy) {
  const ClothoidFit fit = fit_clothoid_g1({1, 1}, 0.0, {1, 1}, 1.0);
  EXPECT_FALSE(fit.ok());
  EXPECT_NE(fit.reason.find("coincide"), std::string::npos);
}

}  // namespace
}  // namespace gf
