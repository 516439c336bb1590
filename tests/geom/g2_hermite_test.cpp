// G2 Hermite cubics against closed forms: on a circle the end curvatures are 1/R and the
// classical symmetric solution a = b is among the answers; every answer meets its ends with
// the requested tangents and curvatures exactly.
#include "geom/g2_hermite.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "geom/curvature.hpp"

namespace gf {
namespace {

void expect_meets(const Cubic& c, const HermiteEnd& s, const HermiteEnd& e) {
  EXPECT_NEAR(distance(c.p[0], s.point), 0.0, 1e-12);
  EXPECT_NEAR(distance(c.p[3], e.point), 0.0, 1e-12);
  EXPECT_NEAR(cross(*end_tangent(c, SegmentEnd::start), s.tangent), 0.0, 1e-12);
  EXPECT_NEAR(cross(*end_tangent(c, SegmentEnd::end), e.tangent), 0.0, 1e-12);
  EXPECT_NEAR(*end_curvature(c, SegmentEnd::start).curvature, s.curvature, 1e-9 * std::max(1.0, std::abs(s.curvature)));
  EXPECT_NEAR(*end_curvature(c, SegmentEnd::end).curvature, e.curvature, 1e-9 * std::max(1.0, std::abs(e.curvature)));
}

TEST(G2Hermite, CircularArcsOfSeveralSpans) {
  for (const double span : {0.3, 1.0, std::numbers::pi / 2, 2.0}) {
    const double R = 250.0;
    const HermiteEnd s{{R, 0.0}, {0.0, 1.0}, 1.0 / R};
    const HermiteEnd e{{R * std::cos(span), R * std::sin(span)}, {-std::sin(span), std::cos(span)}, 1.0 / R};
    const std::vector<Cubic> all = g2_hermite_cubics(s, e);
    ASSERT_FALSE(all.empty()) << span;
    bool symmetric = false;
    for (const Cubic& c : all) {
      expect_meets(c, s, e);
      const double a = distance(c.p[0], c.p[1]), b = distance(c.p[2], c.p[3]);
      if (std::abs(a - b) < 1e-9 * R) {
        symmetric = true;
        // Closed form: 3/(2R) a² + a sin θ − R (1 − cos θ) = 0.
        const double expected = R * (-std::sin(span) + std::sqrt(std::sin(span) * std::sin(span) + 6 * (1 - std::cos(span)))) / 3;
        EXPECT_NEAR(a, expected, 1e-9 * R);
        // And it stays near the circle: under 2e-3 R for a quarter (1.9e-3 R; G1 can reach 2.7e-4 R).
        for (int k = 0; k <= 64; ++k)
          EXPECT_NEAR(norm(c.point_at(k / 64.0)), R, span <= std::numbers::pi / 2 ? 2e-3 * R : 1e-2 * R);
      }
    }
    EXPECT_TRUE(symmetric) << span;
  }
}

TEST(G2Hermite, ZeroCurvatureEndAndSpiral) {
  const HermiteEnd s{{0.0, 0.0}, {1.0, 0.0}, 0.0};
  const HermiteEnd e{{100.0, 30.0}, {std::cos(0.8), std::sin(0.8)}, 0.012};
  const std::vector<Cubic> all = g2_hermite_cubics(s, e);
  ASSERT_FALSE(all.empty());
  for (const Cubic& c : all) expect_meets(c, s, e);
}

TEST(G2Hermite, ParallelTangentsDecouple) {
  // An S with parallel end tangents: each handle length from its own end (k a² = T×D).
  const HermiteEnd s{{0.0, 0.0}, {1.0, 0.0}, 0.01};
  const HermiteEnd e{{100.0, 50.0}, {1.0, 0.0}, -0.01};
  const std::vector<Cubic> all = g2_hermite_cubics(s, e);
  ASSERT_EQ(all.size(), 1u);
  expect_meets(all[0], s, e);
}

TEST(G2Hermite, NoSolutionWhenCurvatureHasTheWrongSign) {
  // Turning left but asking for right-turning curvature at both ends: no positive handles.
  const HermiteEnd s{{0.0, 0.0}, {1.0, 0.0}, -0.05};
  const HermiteEnd e{{100.0, 100.0}, {0.0, 1.0}, -0.05};
  EXPECT_TRUE(g2_hermite_cubics(s, e).empty());
}

}  // namespace
}  // namespace gf
