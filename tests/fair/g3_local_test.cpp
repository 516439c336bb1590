// G3 piece by piece: pieces whose κ(s) is exactly linear (clothoids, written as polynomial
// spirals without bumps) joined G2, each refitted between its own nodes. Oracles: the shared κ′
// rule in closed form, G3 at every node by construction, and a run already G3 given back as it
// was.
#include "fair/g3_local.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace gf {
namespace {

// A clothoid: κ(s) = κ₀ + slope·s on [0, length].
PolynomialSpiral clothoid(const CurvatureEnd& start, double length) {
  return PolynomialSpiral(start, length, start.curvature + start.curvature_slope * length, start.curvature_slope, 0.0, 0.0);
}

// Two clothoids joined G2 at the first one's end, κ′ stepping from `slope_a` to `slope_b` there,
// between corners.
struct TwoClothoids {
  std::vector<PolynomialSpiral> curves;
  RunPieces pieces;
  SmoothRun run;
  std::vector<std::vector<double>> cuts;
};

TwoClothoids two_clothoids(double slope_a, double slope_b) {
  TwoClothoids t;
  const PolynomialSpiral a = clothoid({{0, 0}, 0.0, 2e-3, slope_a}, 200.0);
  const LacPoint e = a.end();
  t.curves = {a, clothoid({e.point, a.tangent_angle_at(a.length()), e.curvature, slope_b}, 150.0)};
  t.pieces.pieces = curve_pieces(t.curves);
  t.pieces.at_inflection = {false, false};
  t.pieces.per_chain = {2};
  const Vec2 end = t.curves.back().end().point;
  t.run.cubics = {Cubic{{0, 0}, {0, 0}, end, end}};
  t.cuts = {{0.0, 200.0}, {0.0, 150.0}};
  return t;
}

TEST(G3Local, TheSharedSlopeIsTheHarmonicMeanOrZero) {
  EXPECT_DOUBLE_EQ(shared_slope(G3NodeKind::smooth, {1e-5, 3e-5}), 2.0 * 1e-5 * 3e-5 / 4e-5);
  EXPECT_DOUBLE_EQ(shared_slope(G3NodeKind::inflection, {-2e-5, -2e-5}), -2e-5);
  EXPECT_EQ(shared_slope(G3NodeKind::smooth, {1e-5, -3e-5}), 0.0);  // an extremum of κ at the node
  EXPECT_EQ(shared_slope(G3NodeKind::corner, {std::nullopt, 4e-5}), 4e-5);
  EXPECT_EQ(shared_slope(G3NodeKind::corner, {4e-5, std::nullopt}), 4e-5);
  EXPECT_EQ(shared_slope(G3NodeKind::line, {std::nullopt, 4e-5}), 0.0);  // G3 with the line
}

TEST(G3Local, ClothoidsJoinedG2ComeOutG3AtTheirNode) {
  const TwoClothoids t = two_clothoids(1e-5, 3e-5);
  const G3Problem problem = g3_problem(t.pieces, t.run, t.cuts, false);
  const LocalTargets targets = local_targets(t.pieces, t.cuts, false);
  ASSERT_EQ(targets.slopes.size(), 3u);
  EXPECT_DOUBLE_EQ(*targets.slopes[1].before, 1e-5);
  EXPECT_DOUBLE_EQ(*targets.slopes[1].after, 3e-5);
  const LocalG3 local = fit_g3_locally(problem, targets, 1e-9);
  ASSERT_TRUE(local.ok());
  const std::vector<PolynomialSpiral> s = local.found();
  // The node: one κ′ both sides, exactly; point, tangent and κ the G2 curve's.
  const LacPoint in = s[0].end(), out = s[1].start();
  EXPECT_EQ(*in.curvature_derivative, *out.curvature_derivative);
  EXPECT_DOUBLE_EQ(*out.curvature_derivative, 1.5e-5);
  EXPECT_EQ(out.point, t.curves[1].start().point);
  EXPECT_EQ(in.curvature, out.curvature);
  EXPECT_LE(distance(in.point, out.point), 1e-9 * 200.0);
  EXPECT_NEAR(cross(in.tangent, out.tangent), 0.0, 1e-10);
  // The corners keep their own κ′, and the far corner is reached.
  EXPECT_DOUBLE_EQ(*s[0].start().curvature_derivative, 1e-5);
  EXPECT_DOUBLE_EQ(*s[1].end().curvature_derivative, 3e-5);
  EXPECT_LE(distance(s[1].end().point, t.curves[1].end().point), 1e-9 * 150.0);
  // κ rises along both, as along the clothoids.
  for (const PolynomialSpiral& spiral : s) EXPECT_TRUE(spiral.curvature_monotone());
}

TEST(G3Local, ARunAlreadyG3IsGivenBackAsItWas) {
  // One κ′ throughout: one clothoid cut in two. The spirals need no bumps and are the clothoid.
  TwoClothoids t = two_clothoids(2e-5, 2e-5);
  t.cuts = {{0.0, 50.0, 200.0}, {0.0, 150.0}};
  const G3Problem problem = g3_problem(t.pieces, t.run, t.cuts, false);
  const LocalG3 local = fit_g3_locally(problem, local_targets(t.pieces, t.cuts, false), 1e-9);
  ASSERT_TRUE(local.ok());
  ASSERT_EQ(local.spirals.size(), 3u);
  const double starts[] = {0.0, 50.0, 200.0};
  for (std::size_t i = 0; i < 3; ++i) {
    const PolynomialSpiral& s = *local.spirals[i];
    EXPECT_NEAR(s.symmetric_bump(), 0.0, 1e-12);
    EXPECT_NEAR(s.odd_bump(), 0.0, 1e-12);
    for (int q = 0; q <= 8; ++q) {
      const double along = starts[i] + s.length() * q / 8;
      const LacPoint truth = along <= 200.0 ? t.curves[0].at(along) : t.curves[1].at(along - 200.0);
      EXPECT_LE(distance(s.at(s.length() * q / 8).point, truth.point), 1e-8) << "segment " << i << " at " << q;
    }
  }
}

TEST(G3Local, AnExtremumOfCurvatureAtTheNodeTakesNoSlopeThere) {
  // κ rises, then falls: κ′ = 0 at the node both sides, and neither spiral turns κ back.
  const TwoClothoids t = two_clothoids(1e-5, -2e-5);
  const G3Problem problem = g3_problem(t.pieces, t.run, t.cuts, false);
  const LocalG3 local = fit_g3_locally(problem, local_targets(t.pieces, t.cuts, false), 1e-9);
  ASSERT_TRUE(local.ok());
  EXPECT_EQ(*local.spirals[0]->end().curvature_derivative, 0.0);
  EXPECT_EQ(*local.spirals[1]->start().curvature_derivative, 0.0);
  for (const std::optional<PolynomialSpiral>& spiral : local.spirals) EXPECT_TRUE(spiral->curvature_monotone());
}

}  // namespace
}  // namespace gf
