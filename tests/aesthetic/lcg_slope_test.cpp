// LCG slope estimation (lac-math.md §4) on log-aesthetic curves sampled as points, through the
// B-spline least-squares fit of seed 000: the estimator must give back the curve's α.
#include "aesthetic/lcg_slope.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "aesthetic/segment_fit.hpp"
#include "geom/bspline_fit.hpp"

namespace gf {
namespace {

// Points on the LAC, then the smooth representation the estimator needs (seed 000's B-spline
// least squares, spans raised until the points are met to 1e-8 of the length).
std::vector<Segment> smooth_fit(const LogAestheticSegment& lac, int points) {
  std::vector<Vec2> samples;
  for (const LacPoint& p : lac.sample(points)) samples.push_back(p.point);
  const BSplineFit fit = fit_cubic_bspline_within(samples, 1e-8 * lac.length());
  EXPECT_LT(fit.max_residual, 1e-6 * lac.length());
  return {fit.spans.begin(), fit.spans.end()};
}

class LcgOfLac : public ::testing::TestWithParam<double> {};

TEST_P(LcgOfLac, DenselySampledLacGivesBackItsAlphaWithin002) {
  const double alpha = GetParam();
  // A triangle drawable for every α in [−2, 3]: θ_e/θ_d = 0.56.
  const SegmentFit fit = fit_three_point({0, 0}, {100, 0}, {150, 70}, alpha);
  ASSERT_TRUE(fit.ok()) << fit.reason;
  const LcgSlope lcg = estimate_lcg_slope(smooth_fit(*fit.segment, 400));
  ASSERT_EQ(lcg.kind, LcgSlope::Kind::slope);
  EXPECT_NEAR(lcg.alpha, alpha, 0.02);
}

INSTANTIATE_TEST_SUITE_P(AlphaMinus2To3, LcgOfLac, ::testing::Values(-2.0, -1.5, -1.0, -0.5, 0.0, 0.5, 1.0, 1.5, 2.0, 2.5, 3.0),
                         [](const auto& info) { return "alpha_" + std::to_string(static_cast<int>(std::lround(info.param * 10 + 20))); });

TEST(LcgSlope, NearlyConstantCurvatureIsAnArc) {
  // A near-isosceles triangle: the LAC is an arc to 0.1%, and α is undetermined (§4.3).
  const SegmentFit fit = fit_three_point({0, 0}, {100, 0}, {100 + 99.9 * std::cos(0.8), 99.9 * std::sin(0.8)}, 2.0);
  ASSERT_TRUE(fit.ok());
  EXPECT_EQ(estimate_lcg_slope(smooth_fit(*fit.segment, 200)).kind, LcgSlope::Kind::arc);
}

TEST(LcgSlope, StraightLineIsUndetermined) {
  const Segment line = Line{{0, 0}, {5, 5}};
  EXPECT_EQ(estimate_lcg_slope(std::span(&line, 1)).kind, LcgSlope::Kind::undetermined);
}

TEST(BSplineFit, MeetsPointsOfASmoothCurveWithinTheTolerance) {
  const Cubic c{{0, 0}, {10, 30}, {40, 35}, {60, 0}};
  std::vector<Vec2> pts;
  for (int i = 0; i <= 200; ++i) pts.push_back(c.point_at(i / 200.0));
  const BSplineFit fit = fit_cubic_bspline_within(pts, 1e-4);
  EXPECT_LT(fit.max_residual, 1e-4);
  EXPECT_EQ(fit.spans.front().p[0], c.p[0]);  // the ends interpolate
  EXPECT_EQ(fit.spans.back().p[3], c.p[3]);
  EXPECT_EQ(fit.spans.front().p[0], c.p[0]);
  EXPECT_EQ(fit.spans.back().p[3], c.p[3]);
}

}  // namespace
}  // namespace gf
