// G2 by rotating junction tangents, on the test chain of lac-math.md §6.1 / check_06: points on
// an ellipse arc with chord-based tangents, the interior ones perturbed by ±0.05 rad.
#include "fair/g2_chain.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace gf {
namespace {

LacChain ellipse_chain(std::vector<double> alphas) {
  LacChain c;
  for (int i = 0; i < 6; ++i) {
    const double t = 0.2 + (2.6 - 0.2) * i / 5.0;
    c.points.push_back({3 * std::cos(t), 1.6 * std::sin(t)});
    c.tangent_angles.push_back(std::atan2(1.6 * std::cos(t), -3 * std::sin(t)) + (i > 0 && i < 5 ? 0.05 * (i % 2 ? -1 : 1) : 0.0));
  }
  c.alphas = std::move(alphas);
  return c;
}

TEST(G2Chain, InitialMismatchMatchesTheReference) {
  // check_06.out: "initial mismatch [-0.17272 0.1511 -0.14143 0.16429]" for α = 1.
  const ChainSegments s = build_chain(ellipse_chain({1, 1, 1, 1, 1}));
  ASSERT_TRUE(s.ok()) << s.reason;
  const std::vector<double> d = curvature_mismatch(ellipse_chain({1, 1, 1, 1, 1}), s.segments);
  const double want[] = {-0.17272, 0.1511, -0.14143, 0.16429};
  for (int j = 0; j < 4; ++j) EXPECT_NEAR(d[j], want[j], 6e-5);
}

// The fits may start anywhere along the chain (a line search starts where its last step
// failed): the same segments, and a chain with no solution names the segment without one.
TEST(G2Chain, BuiltFromAnySegmentTheChainIsTheSame) {
  const LacChain chain = ellipse_chain({2, 1, 0, -0.5, 1.5});
  const ChainSegments from_start = build_chain(chain);
  ASSERT_TRUE(from_start.ok()) << from_start.reason;
  for (std::size_t first = 0; first < chain.segment_count(); ++first) {
    const ChainSegments s = build_chain(chain, first);
    ASSERT_TRUE(s.ok()) << s.reason;
    for (std::size_t i = 0; i < s.segments.size(); ++i) {
      EXPECT_EQ(s.segments[i].start().curvature, from_start.segments[i].start().curvature) << first << " " << i;
      EXPECT_EQ(s.segments[i].end().curvature, from_start.segments[i].end().curvature) << first << " " << i;
    }
  }
  LacChain broken = chain;
  broken.tangent_angles[3] += 2.0;  // segments 2 and 3 lose their control triangles
  for (std::size_t first = 0; first < chain.segment_count(); ++first) {
    const ChainSegments s = build_chain(broken, first);
    EXPECT_FALSE(s.ok());
    EXPECT_TRUE(s.failed_segment == 2 || s.failed_segment == 3) << s.failed_segment;
    EXPECT_FALSE(tangents_meet_in_front(broken, s.failed_segment));
  }
}

class G2Solve : public ::testing::TestWithParam<std::vector<double>> {};

TEST_P(G2Solve, NewtonReachesG2InAFewIterations) {
  const G2Result r = make_g2(ellipse_chain(GetParam()));
  ASSERT_TRUE(r.converged) << r.reason;
  EXPECT_LE(r.iterations, 8);  // check_06 needed 3–4
  EXPECT_LE(r.max_mismatch, 1e-12);
  // The junctions stay where they were, each segment still meets them along the new tangents.
  const LacChain original = ellipse_chain(GetParam());
  for (std::size_t i = 0; i < r.segments.size(); ++i) {
    EXPECT_NEAR(distance(r.segments[i].start().point, original.points[i]), 0.0, 1e-13);
    EXPECT_NEAR(distance(r.segments[i].end().point, original.points[i + 1]), 0.0, 1e-13);
    const double a = r.chain.tangent_angles[i + 1];
    EXPECT_NEAR(cross(r.segments[i].end().tangent, Vec2{std::cos(a), std::sin(a)}), 0.0, 1e-12);
  }
  EXPECT_EQ(r.chain.tangent_angles.front(), original.tangent_angles.front());
  EXPECT_EQ(r.chain.tangent_angles.back(), original.tangent_angles.back());
}

INSTANTIATE_TEST_SUITE_P(Alphas, G2Solve,
                         ::testing::Values(std::vector<double>{1, 1, 1, 1, 1}, std::vector<double>{-1, -1, -1, -1, -1},
                                           std::vector<double>{2, 1, 0, -0.5, 1.5}));

}  // namespace
}  // namespace gf
