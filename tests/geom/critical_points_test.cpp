// Inflections, curvature extrema and cusps against an mpmath oracle (60 digits, complex root
// finding on the exact polynomials: tests/oracles/critical_points_oracle.py).
#include "geom/critical_points.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "geom/curvature.hpp"

namespace gf {
namespace {

struct OracleCase {
  std::string name;
  std::vector<Vec2> points;
  std::vector<double> inflections, extrema, cusps;
};

void PrintTo(const OracleCase& c, std::ostream* os) { *os << c.name; }

const std::vector<OracleCase> oracle = {
#include "geom/critical_points_oracle.inc"
};

Segment segment_of(const std::vector<Vec2>& p) {
  if (p.size() == 3) return Quad{{p[0], p[1], p[2]}};
  return Cubic{{p[0], p[1], p[2], p[3]}};
}

void expect_same(const std::vector<double>& got, const std::vector<double>& want, const std::string& what) {
  ASSERT_EQ(got.size(), want.size()) << what;
  for (std::size_t i = 0; i < got.size(); ++i) EXPECT_NEAR(got[i], want[i], 1e-9) << what << " #" << i;
}

class AgainstOracle : public ::testing::TestWithParam<OracleCase> {};

TEST_P(AgainstOracle, InflectionsExtremaAndCuspsAgreeTo1e9InT) {
  const OracleCase& c = GetParam();
  const CriticalPoints cp = critical_points(segment_of(c.points));
  expect_same(cp.inflections, c.inflections, c.name + " inflections");
  std::vector<double> extrema;
  for (const auto& e : cp.curvature_extrema) extrema.push_back(e.t);
  expect_same(extrema, c.extrema, c.name + " curvature extrema");
  expect_same(cp.cusps, c.cusps, c.name + " cusps");
}

INSTANTIATE_TEST_SUITE_P(Oracle, AgainstOracle, ::testing::ValuesIn(oracle), [](const auto& info) {
  std::string n = info.param.name;
  for (char& ch : n)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return n;
});

TEST(CriticalPoints, MaximumAndMinimumOfCurvatureAreTold) {
  // The standard quarter-circle cubic: |κ| has maxima near t = 0.19 and 0.81, a minimum at 0.5.
  const Cubic arc{{{1, 0}, {1, 0.5522847498307936}, {0.5522847498307936, 1}, {0, 1}}};
  const auto e = critical_points(arc).curvature_extrema;
  ASSERT_EQ(e.size(), 3u);
  EXPECT_TRUE(e[0].maximum);
  EXPECT_FALSE(e[1].maximum);
  EXPECT_TRUE(e[2].maximum);
  EXPECT_NEAR(e[1].curvature, 1.0, 1e-2);  // the cubic's curvature is within 1% of the circle's
}

TEST(CriticalPoints, AxisExtremaOfAnArch) {
  const Cubic arch{{{0, 0}, {0, 2}, {4, 2}, {4, 0}}};
  const auto a = axis_extrema(arch);
  ASSERT_EQ(a.size(), 1u);
  EXPECT_EQ(a[0].tangent, Axis::horizontal);
  EXPECT_DOUBLE_EQ(a[0].t, 0.5);
  // A circle's quarter from (1,0) to (0,1) has its extrema at the ends only.
  EXPECT_TRUE(axis_extrema(Cubic{{{1, 0}, {1, 0.55}, {0.55, 1}, {0, 1}}}).empty());
}

TEST(CriticalPoints, ScaleAndTranslationDoNotChangeTheAnswer) {
  const Cubic small{{{0, 0}, {1, 1}, {2, -1}, {3, 0}}};
  Cubic big = small;
  for (Vec2& p : big.p) p = p * 1e4 + Vec2{-5e5, 3e5};
  EXPECT_EQ(critical_points(small).inflections, critical_points(big).inflections);
}

TEST(CriticalPoints, ACubicLeavingALineOnTheGridHasNoInflectionInside) {
  // Gentium Plus's W: a curve leaving its stroke of step (−11, −34) with its far handle on the
  // stroke too, so κ = 0 at t = 0 exactly and one sign after (the curve bends the one way all
  // along: its curvature sampled). The inflection polynomial vanishes at t = 0; rounding left its
  // constant term as noise, and a change of sign a hair inside counted as an inflection. The
  // cubic reversed has the zero at t = 1.
  const Cubic leaving{{{581, 96}, {559, 28}, {548, -6}, {419, -31}}};
  for (int k = 1; k <= 100; ++k) EXPECT_LT(*curvature(derivatives_at(Segment{leaving}, k / 100.0)), 0.0);
  EXPECT_TRUE(inflections(leaving).empty());
  EXPECT_TRUE(inflections(leaving.reversed()).empty());
  // A real inflection near the end is still one: the far handle a unit across the stroke, κ > 0
  // at t = 0 and < 0 by the middle.
  const Cubic across{{{581, 96}, {559, 28}, {549, -3}, {419, -31}}};
  EXPECT_GT(*curvature(derivatives_at(Segment{across}, 0.0)), 0.0);
  EXPECT_LT(*curvature(derivatives_at(Segment{across}, 0.5)), 0.0);
  EXPECT_EQ(inflections(across).size(), 1u);
}

TEST(CriticalPoints, LinesHaveNone) {
  const CriticalPoints cp = critical_points(Line{{{0, 0}, {10, 3}}});
  EXPECT_TRUE(cp.inflections.empty());
  EXPECT_TRUE(cp.curvature_extrema.empty());
  EXPECT_TRUE(cp.axis_extrema.empty());
}

}  // namespace
}  // namespace gf
