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

// With one end free (a corner), its handle is given and the other end's curvature met: on a
// circle, a free start with the symmetric solution's handle gives back that solution, and any
// other handle length still meets the end's tangent and curvature; a handle the curvature
// cannot follow (the far end turning the wrong way) gives none.
TEST(G2Hermite, OneFreeEndMeetsTheOtherEndsCurvature) {
  const double R = 250.0, span = 1.0;
  const HermiteEnd s{{R, 0.0}, {0.0, 1.0}, 1.0 / R};
  const HermiteEnd e{{R * std::cos(span), R * std::sin(span)}, {-std::sin(span), std::cos(span)}, 1.0 / R};
  const double symmetric = R * (-std::sin(span) + std::sqrt(std::sin(span) * std::sin(span) + 6 * (1 - std::cos(span)))) / 3;
  for (const SegmentEnd free : {SegmentEnd::start, SegmentEnd::end}) {
    const std::optional<Cubic> same = g2_hermite_cubic_with_free_end(s, e, free, symmetric);
    ASSERT_TRUE(same);
    expect_meets(*same, s, e);
    for (const double handle : {0.3 * symmetric, 1.4 * symmetric}) {
      const std::optional<Cubic> c = g2_hermite_cubic_with_free_end(s, e, free, handle);
      ASSERT_TRUE(c) << handle;
      const bool free_start = free == SegmentEnd::start;
      EXPECT_NEAR(distance(c->p[free_start ? 0 : 3], c->p[free_start ? 1 : 2]), handle, 1e-9 * R);
      EXPECT_NEAR(cross(*end_tangent(*c, SegmentEnd::start), s.tangent), 0.0, 1e-12);
      EXPECT_NEAR(cross(*end_tangent(*c, SegmentEnd::end), e.tangent), 0.0, 1e-12);
      const double met = *end_curvature(*c, free_start ? SegmentEnd::end : SegmentEnd::start).curvature;
      EXPECT_NEAR(met, 1.0 / R, 1e-9 / R) << handle;
    }
  }
  const HermiteEnd wrong{e.point, e.tangent, -1.0 / R};
  EXPECT_FALSE(g2_hermite_cubic_with_free_end(s, wrong, SegmentEnd::start, symmetric));
}

// From a flat end (κ = 0) to a free one: the flat end's far control point lies on its tangent
// line, so the free end's handle is the distance from the free end back to where the two
// tangent lines cross (the closed form), whatever the flat end's handle; parallel tangents, or
// lines crossing behind an end, give none.
TEST(G2Hermite, AFlatEndFixesTheFreeEndsHandle) {
  const double turn = radians(4.0);
  const HermiteEnd s{{0.0, 0.0}, {0.0, 1.0}, 0.0};
  const Vec2 cross_at{0.0, 150.0};  // where the tangent lines meet
  const Vec2 t3{-std::sin(turn), std::cos(turn)};
  const HermiteEnd e{cross_at + t3 * 220.0, t3, 0.0};
  for (const SegmentEnd free : {SegmentEnd::end, SegmentEnd::start}) {
    const bool free_start = free == SegmentEnd::start;
    // Walked backwards, the same curve has its flat end last and its free end first.
    const HermiteEnd a = free_start ? HermiteEnd{e.point, -e.tangent, 0.0} : s;
    const HermiteEnd b = free_start ? HermiteEnd{s.point, -s.tangent, 0.0} : e;
    for (const double flat_handle : {20.0, 75.0, 140.0}) {
      const std::optional<Cubic> c = g2_hermite_cubic_from_flat_end(a, b, free, flat_handle);
      ASSERT_TRUE(c) << flat_handle;
      const SegmentEnd flat = free_start ? SegmentEnd::end : SegmentEnd::start;
      EXPECT_NEAR(*end_curvature(*c, flat).curvature, 0.0, 1e-15);
      EXPECT_NEAR(distance(c->p[free_start ? 3 : 0], c->p[free_start ? 2 : 1]), flat_handle, 1e-9);
      EXPECT_NEAR(distance(c->p[free_start ? 0 : 3], c->p[free_start ? 1 : 2]), 220.0, 1e-9);
      EXPECT_NEAR(cross(*end_tangent(*c, SegmentEnd::start), a.tangent), 0.0, 1e-12);
      EXPECT_NEAR(cross(*end_tangent(*c, SegmentEnd::end), b.tangent), 0.0, 1e-12);
    }
  }
  const HermiteEnd parallel{{10.0, 300.0}, {0.0, 1.0}, 0.0};
  EXPECT_FALSE(g2_hermite_cubic_from_flat_end(s, parallel, SegmentEnd::end, 50.0));
  const HermiteEnd behind{{-20.0, -100.0}, t3, 0.0};  // the lines cross beyond this end
  EXPECT_FALSE(g2_hermite_cubic_from_flat_end(s, behind, SegmentEnd::end, 50.0));
}


}  // namespace
}  // namespace gf
