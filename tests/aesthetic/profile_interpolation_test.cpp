// G3 interpolation through points with curvature given (seed 004 §6): the circle and the
// clothoid recovered from their own points (with and without their tangents and κ′), G3 at
// every join, and failures named.
#include "aesthetic/profile_interpolation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace gf {
namespace {

TEST(ProfileInterpolation, PointsOnACircleWithItsCurvatureGiveTheCircle) {
  // Five points over 200° of a radius-50 circle, κ = 1/50, nothing else: the three-point
  // tangents are the circle's, the secant slopes vanish, every span is an arc.
  const double r = 50.0;
  const Vec2 centre{10.0, -20.0};
  std::vector<InterpolationPoint> pts;
  for (int k = 0; k < 5; ++k) {
    const double a = 0.3 + k * (200.0 / 4.0) * std::numbers::pi / 180.0;
    pts.push_back({centre + r * Vec2{std::cos(a), std::sin(a)}, 1.0 / r, std::nullopt, std::nullopt});
  }
  const ProfileSpline spline = interpolate_curvature_profiles(pts);
  ASSERT_TRUE(spline.ok()) << spline.reason;
  double length = 0.0;
  for (const InterpolationSpan& s : spline.segments) {
    length += s.length();
    for (const LacPoint& p : s.sample(16)) {
      EXPECT_NEAR(distance(p.point, centre), r, 1e-9);
      EXPECT_NEAR(p.curvature, 1.0 / r, 1e-12);
    }
  }
  EXPECT_NEAR(length, r * 200.0 * std::numbers::pi / 180.0, 1e-8);
}

// The clothoid κ(s) = 0.2 + 0.5 s from the origin, S = 2.4, as a straight profile (λ = S/3).
CurvatureProfileSegment reference_clothoid() {
  const double length = 2.4, k0 = 0.2, slope = 0.5;
  return CurvatureProfileSegment({{0, 0}, 0.3, k0, slope}, length, length / 3, length / 3, k0 + slope * length, slope);
}

TEST(ProfileInterpolation, PointsOfAClothoidWithTheirDataGiveTheClothoid) {
  const CurvatureProfileSegment c = reference_clothoid();
  std::vector<InterpolationPoint> pts;
  for (int k = 0; k <= 3; ++k) {
    const LacPoint p = c.at_parameter(k / 3.0);
    pts.push_back({p.point, p.curvature, p.curvature_derivative, c.tangent_angle_at_parameter(k / 3.0)});
  }
  const ProfileSpline spline = interpolate_curvature_profiles(pts);
  ASSERT_TRUE(spline.ok()) << spline.reason;
  for (std::size_t i = 0; i < 3; ++i) {
    const InterpolationSpan& s = spline.segments[i];
    EXPECT_NEAR(s.length(), 0.8, 1e-9);
    for (int k = 0; k <= 8; ++k) {
      const double sigma = 0.8 * k / 8.0;
      EXPECT_NEAR(distance(s.at(sigma).point, c.at(0.8 * double(i) + sigma).point), 0.0, 1e-9);
    }
  }
}

TEST(ProfileInterpolation, PointsOfAClothoidWithOnlyTheirCurvatureGiveTheClothoid) {
  // Tangents and κ′ left to be chosen: the clothoids through the true tangents meet the given
  // curvatures exactly (the least squares' zero), and every secant slope is the clothoid's.
  const CurvatureProfileSegment c = reference_clothoid();
  std::vector<InterpolationPoint> pts;
  for (int k = 0; k <= 4; ++k) {
    const LacPoint p = c.at_parameter(k / 4.0);
    pts.push_back({p.point, p.curvature, std::nullopt, std::nullopt});
  }
  const ProfileSpline spline = interpolate_curvature_profiles(pts);
  ASSERT_TRUE(spline.ok()) << spline.reason;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    EXPECT_NEAR(spline.ends[i].tangent_angle, c.tangent_angle_at_parameter(i / 4.0), 1e-8) << i;
    EXPECT_NEAR(spline.ends[i].curvature_slope, 0.5, 1e-7) << i;
  }
  for (std::size_t i = 0; i < spline.segments.size(); ++i) {
    const InterpolationSpan& s = spline.segments[i];
    EXPECT_NEAR(s.length(), 0.6, 1e-8);
    EXPECT_NEAR(distance(s.at(0.3).point, c.at(0.6 * double(i) + 0.3).point), 0.0, 1e-8);
    if (i == 0) continue;
    // G3 at the join, by construction.
    const LacPoint before = spline.segments[i - 1].end(), after = s.start();
    EXPECT_NEAR(distance(before.point, after.point), 0.0, 1e-9);
    EXPECT_NEAR(turning_angle(before.tangent, after.tangent), 0.0, 1e-9);
    EXPECT_NEAR(before.curvature, after.curvature, 1e-12);
    EXPECT_NEAR(*before.curvature_derivative, *after.curvature_derivative, 1e-12);
  }
}

TEST(ProfileInterpolation, AGentleWaveIsFollowedWithPolynomialSpiralsWhereTheProfileHasNone) {
  // y = 30 sin(x/40) through 11 points 40 apart (a quarter wave each) with its curvature: the
  // seed's profile runs its legs backwards or stalls on half the spans, which are polynomial
  // spirals instead; every join is G3 and the curve stays within 2% of the amplitude (0.53
  // measured: the tangents and κ′ are chosen, not the wave's).
  const auto wave = [](double x) { return 30.0 * std::sin(x / 40.0); };
  std::vector<InterpolationPoint> pts;
  for (int k = 0; k <= 10; ++k) {
    const double x = 40.0 * k, d1 = 0.75 * std::cos(x / 40.0), d2 = -wave(x) / 1600.0;
    pts.push_back({{x, wave(x)}, d2 / std::pow(1.0 + d1 * d1, 1.5), std::nullopt, std::nullopt});
  }
  const ProfileSpline spline = interpolate_curvature_profiles(pts);
  ASSERT_TRUE(spline.ok()) << spline.reason;
  int spirals = 0;
  for (std::size_t i = 0; i < spline.segments.size(); ++i) {
    const InterpolationSpan& s = spline.segments[i];
    spirals += s.is_profile() ? 0 : 1;
    EXPECT_NEAR(distance(s.start().point, pts[i].point), 0.0, 1e-9) << i;
    EXPECT_NEAR(distance(s.end().point, pts[i + 1].point), 0.0, 1e-6) << i;
    EXPECT_NEAR(s.start().curvature, pts[i].curvature, 1e-12) << i;
    EXPECT_NEAR(s.end().curvature, pts[i + 1].curvature, 1e-9) << i;
    EXPECT_NEAR(*s.start().curvature_derivative, spline.ends[i].curvature_slope, 1e-9) << i;
    EXPECT_NEAR(*s.end().curvature_derivative, spline.ends[i + 1].curvature_slope, 1e-9) << i;
    for (const LacPoint& p : s.sample(8)) EXPECT_NEAR(p.point.y, wave(p.point.x), 0.6) << i;
  }
  EXPECT_GT(spirals, 0);
}

TEST(ProfileInterpolation, CoincidentPointsAreNamed) {
  const std::vector<InterpolationPoint> pts{{{0, 0}, 0.0, {}, {}}, {{0, 0}, 0.0, {}, {}}};
  const ProfileSpline spline = interpolate_curvature_profiles(pts);
  EXPECT_FALSE(spline.ok());
  EXPECT_EQ(spline.reason, "points 0 and 1 coincide");
}

TEST(ProfileInterpolation, ASpanWithNeitherCurveIsNamed) {
  // Ten units straight ahead, asked to bend at κ = 1 (a radius of 1) at both ends with κ′ = 0:
  // neither the seed's profile nor the polynomial spiral meets it, and the reason names both.
  const std::vector<InterpolationPoint> pts{{{0, 0}, 1.0, 0.0, 0.0}, {{10, 0}, 1.0, 0.0, 0.0}};
  const ProfileSpline spline = interpolate_curvature_profiles(pts);
  EXPECT_FALSE(spline.ok());
  EXPECT_EQ(spline.reason.rfind("span 0: curvature profile: ", 0), 0u) << spline.reason;
  EXPECT_NE(spline.reason.find("; polynomial spiral: "), std::string::npos) << spline.reason;
}
}  // namespace
}  // namespace gf
