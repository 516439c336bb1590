// Polynomial spirals (κ a quintic in s with κ, κ′ given at both ends) against the clothoid's
// closed form, recovered from their own ends, and following a log-aesthetic segment given its
// end data; the seed's Bézier profile on the same log-aesthetic data for comparison.
#include "aesthetic/polynomial_spiral.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "aesthetic/clothoid_g1.hpp"
#include "aesthetic/curvature_profile_segment.hpp"
#include "aesthetic/segment_fit.hpp"

namespace gf {
namespace {

TEST(PolynomialSpiral, KeepsItsEndCurvaturesAndSlopesWhateverTheBumps) {
  const PolynomialSpiral s({{3, 4}, 0.2, 0.01, -2e-4}, 120.0, 0.03, 5e-4, 0.004, -0.002);
  EXPECT_NEAR(s.start().curvature, 0.01, 1e-15);
  EXPECT_NEAR(*s.start().curvature_derivative, -2e-4, 1e-15);
  EXPECT_NEAR(s.end().curvature, 0.03, 1e-15);
  EXPECT_NEAR(*s.end().curvature_derivative, 5e-4, 1e-15);
  EXPECT_EQ(s.start().point, (Vec2{3, 4}));
}

TEST(PolynomialSpiral, WithoutBumpsALinearProfileIsTheClothoid) {
  // Closed form of the turning; the position by composite Simpson, independent of Gauss.
  const double k0 = 0.02, slope = -3e-4, length = 90.0, theta0 = 0.4;
  const PolynomialSpiral s({{0, 0}, theta0, k0, slope}, length, k0 + slope * length, slope, 0.0, 0.0);
  const auto theta = [&](double t) { return theta0 + k0 * t + 0.5 * slope * t * t; };
  EXPECT_NEAR(s.tangent_angle_at(length), theta(length), 1e-14);
  const int n = 20000;
  Vec2 sum{};
  for (int k = 0; k <= n; ++k)
    sum += ((k == 0 || k == n) ? 1.0 : (k % 2 ? 4.0 : 2.0)) * direction_of(theta(length * k / n));
  EXPECT_LT(distance(s.end().point, sum * (length / n / 3.0)), 1e-9);
  EXPECT_TRUE(s.curvature_monotone());
}

TEST(PolynomialSpiral, NewtonRecoversSpiralsFromTheirEnds) {
  std::mt19937 random(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 100; ++trial) {
    const double length = 1.5 + 0.5 * u(random);
    const CurvatureEnd start{{0, 0}, 0.3 * u(random), 0.8 * u(random), 0.5 * u(random)};
    const PolynomialSpiral truth(start, length, 0.8 * u(random), 0.5 * u(random), 0.2 * u(random), 0.2 * u(random));
    const LacPoint e = truth.end();
    const SpiralFit fit = fit_polynomial_spiral(start, {e.point, truth.tangent_angle_at(length), e.curvature,
                                                        *e.curvature_derivative});
    ASSERT_TRUE(fit.ok()) << trial << ": " << fit.reason;
    EXPECT_NEAR(fit.spiral->length(), length, 1e-9) << trial;
    EXPECT_NEAR(fit.spiral->symmetric_bump(), truth.symmetric_bump(), 1e-8) << trial;
    EXPECT_NEAR(fit.spiral->odd_bump(), truth.odd_bump(), 1e-8) << trial;
  }
}

TEST(PolynomialSpiral, ScalesWithTheFont) {
  // The same problem at 1 and at 800 units: S × 800, bumps ÷ 800.
  const CurvatureEnd a{{0, 0}, 0.2, 0.9, 0.3};
  const PolynomialSpiral unit(a, 1.3, 1.4, -0.2, 0.05, -0.03);
  const LacPoint e = unit.end();
  const double k = 800.0;
  const SpiralFit fit = fit_polynomial_spiral({{10, 20}, 0.2, 0.9 / k, 0.3 / (k * k)},
                                              {Vec2{10, 20} + k * e.point, unit.tangent_angle_at(1.3), 1.4 / k,
                                               -0.2 / (k * k)});
  ASSERT_TRUE(fit.ok()) << fit.reason;
  EXPECT_NEAR(fit.spiral->length(), 1.3 * k, 1e-8 * k);
  EXPECT_NEAR(fit.spiral->symmetric_bump() * k, 0.05, 1e-8);
}

// A log-aesthetic segment's own end data (lac-math.md §2.4's triangle): both G3 segments
// should follow it. Largest distance at equal shares of arc length, chord ≈ 2.15.
double follow_distance(const LogAestheticSegment& lac, const std::vector<LacPoint>& other) {
  const std::vector<LacPoint> mine = lac.sample(static_cast<int>(other.size()) - 1);
  double d = 0.0;
  for (std::size_t k = 0; k < other.size(); ++k) d = std::max(d, distance(mine[k].point, other[k].point));
  return d;
}

TEST(PolynomialSpiral, FollowsALogAestheticSegmentFromItsEndData) {
  for (const double alpha : {-2.0, -1.0, 0.0, 1.0, 2.0, 3.0}) {
    const SegmentFit lac = fit_three_point({0, 0}, {1, 0}, {2, 0.8}, alpha);
    ASSERT_TRUE(lac.ok());
    const LacPoint a = lac.segment->start(), b = lac.segment->end();
    const double theta0 = angle_of(a.tangent);
    const CurvatureEnd start{a.point, theta0, a.curvature, *a.curvature_derivative};
    const CurvatureEnd end{b.point, theta0 + turning_angle(a.tangent, b.tangent), b.curvature, *b.curvature_derivative};

    const SpiralFit spiral = fit_polynomial_spiral(start, end);
    ASSERT_TRUE(spiral.ok()) << alpha << ": " << spiral.reason;
    // The quintic follows the log-aesthetic κ(s) closely while its κ ratio is moderate; at
    // α = 3 (κ ratio 2.4 with steep κ′ at P0) it overshoots.
    if (alpha <= 2.0) {
      EXPECT_LT(follow_distance(*lac.segment, spiral.spiral->sample(64)), 5e-4) << alpha;
      EXPECT_TRUE(spiral.spiral->curvature_monotone()) << alpha;
    } else {
      EXPECT_FALSE(spiral.spiral->curvature_monotone());
    }
    // The seed's Bézier profile bends its κ(s) as the log-aesthetic one does: closer, and
    // monotone throughout.
    const ProfileFit profile = fit_curvature_profile(start, end);
    ASSERT_TRUE(profile.ok()) << alpha << ": " << profile.reason;
    EXPECT_LT(follow_distance(*lac.segment, profile.segment->sample(64)), 5e-5) << alpha;
    EXPECT_TRUE(profile.segment->curvature_monotone()) << alpha;
  }
}

}  // namespace
}  // namespace gf
