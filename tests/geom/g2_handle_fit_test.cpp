// Handle lengths of a chain of cubics with fixed nodes and tangents, fitted to points under
// curvature continuity: a G2 chain's own points give it back, also closed and from nodes slid
// along their tangents; points whose curvature jumps give a chain that does not; a frame that
// cannot bend as asked gives none.
#include "geom/g2_handle_fit.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

#include "geom/curvature.hpp"

namespace gf {
namespace {

double start_kappa(const Cubic& c) { return *end_curvature(c, SegmentEnd::start).curvature; }
double end_kappa(const Cubic& c) { return *end_curvature(c, SegmentEnd::end).curvature; }

std::vector<Vec2> points_of(const Cubic& c, int n) {
  std::vector<Vec2> out;
  // Unevenly in the parameter, so chord lengths alone would not do.
  for (int k = 0; k <= n; ++k) out.push_back(c.point_at(std::pow(static_cast<double>(k) / n, 1.3)));
  return out;
}

TEST(G2HandleFit, TheClosedFormsAreTheCubicsEndCurvatures) {
  const Cubic c{{0.0, 0.0}, {60.0, 10.0}, {150.0, 80.0}, {170.0, 200.0}};
  const CubicFrame f = *frame_of(c);
  const double a = distance(c.p[0], c.p[1]), b = distance(c.p[2], c.p[3]);
  EXPECT_NEAR(f.start_curvature(a, b), start_kappa(c), 1e-15);
  EXPECT_NEAR(f.end_curvature(a, b), end_kappa(c), 1e-15);
}

TEST(G2HandleFit, PointsOfAG2ChainGiveItBack) {
  // One cubic split in two: a chain whose join is G2 (and more).
  const std::array<Cubic, 2> halves = Cubic{{0.0, 0.0}, {60.0, 10.0}, {150.0, 80.0}, {170.0, 200.0}}.split(0.4);
  const std::vector<CubicFrame> frames{*frame_of(halves[0]), *frame_of(halves[1])};
  const std::vector<std::vector<Vec2>> points{points_of(halves[0], 40), points_of(halves[1], 60)};
  std::vector<std::pair<double, double>> initial;
  for (const Cubic& h : halves) initial.emplace_back(1.3 * distance(h.p[0], h.p[1]), 0.7 * distance(h.p[2], h.p[3]));
  const auto fit = fit_g2_handles(frames, points, initial, start_kappa(halves[0]), end_kappa(halves[1]));
  ASSERT_TRUE(fit);
  for (std::size_t i = 0; i < 2; ++i)
    for (std::size_t k = 0; k < 4; ++k) EXPECT_NEAR(distance((*fit)[i].p[k], halves[i].p[k]), 0.0, 1e-6) << i << " " << k;
}

TEST(G2HandleFit, CurvatureJumpingInThePointsIsContinuousInTheChain) {
  // A quarter circle of radius 100 and then one of 150, tangent where they meet: κ jumps from
  // 1/100 to 1/150 there. The chain meets 1/100 at its start and 1/150 at its end, and its
  // join takes one curvature on both sides.
  std::vector<Vec2> first, second;
  for (int k = 0; k <= 100; ++k) {
    const double a = 0.5 * std::numbers::pi * k / 100.0;
    first.push_back({100.0 * std::cos(a), 100.0 * std::sin(a)});
    second.push_back({150.0 * std::cos(a + 0.5 * std::numbers::pi) + 0.0, 150.0 * std::sin(a + 0.5 * std::numbers::pi) - 50.0});
  }
  const std::vector<CubicFrame> frames{{{100.0, 0.0}, {0.0, 1.0}, {0.0, 100.0}, {-1.0, 0.0}},
                                       {{0.0, 100.0}, {-1.0, 0.0}, {-150.0, -50.0}, {0.0, -1.0}}};
  const std::vector<std::vector<Vec2>> points{first, second};
  const std::vector<std::pair<double, double>> initial{{55.0, 55.0}, {83.0, 83.0}};
  const auto fit = fit_g2_handles(frames, points, initial, 0.01, 1.0 / 150.0);
  ASSERT_TRUE(fit);
  const Cubic &a = (*fit)[0], &b = (*fit)[1];
  EXPECT_NEAR(start_kappa(a), 0.01, 1e-11);
  EXPECT_NEAR(end_kappa(b), 1.0 / 150.0, 1e-11);
  EXPECT_NEAR(end_kappa(a), start_kappa(b), 1e-9 * std::abs(start_kappa(b)));
  // Between the two radii there.
  EXPECT_GT(start_kappa(b), 1.0 / 150.0);
  EXPECT_LT(start_kappa(b), 0.01);
  // Nodes and tangents where the frames put them.
  EXPECT_EQ(a.p[0], (Vec2{100.0, 0.0}));
  EXPECT_EQ(b.p[3], (Vec2{-150.0, -50.0}));
  EXPECT_NEAR(a.p[1].x, 100.0, 1e-12);
  EXPECT_NEAR(b.p[2].x, -150.0, 1e-12);
}

// The usual four-cubic circle stretched into an ellipse of half-axes 300 and 180: each node on
// an axis joins two mirror images, so κ is continuous all round (a closed G2 chain).
std::vector<Cubic> ellipse() {
  const double h = (4.0 / 3.0) * std::tan(std::numbers::pi / 8.0);
  const std::array<Vec2, 4> axis{Vec2{1.0, 0.0}, Vec2{0.0, 1.0}, Vec2{-1.0, 0.0}, Vec2{0.0, -1.0}};
  const auto stretch = [](Vec2 p) { return Vec2{300.0 * p.x, 180.0 * p.y}; };
  std::vector<Cubic> out;
  for (std::size_t q = 0; q < 4; ++q) {
    const Vec2 a = axis[q], b = axis[(q + 1) % 4];
    out.push_back({stretch(a), stretch(a + b * h), stretch(b + a * h), stretch(b)});
  }
  return out;
}

// The ellipse, its points, and frames whose nodes sit 4 units along their tangents from its,
// the handles starting at a third of each chord.
struct SlidEllipse {
  std::vector<Cubic> chain = ellipse();
  std::vector<CubicFrame> frames;
  std::vector<std::vector<Vec2>> points;
  std::vector<std::pair<double, double>> initial;
  SlidEllipse() {
    for (const Cubic& c : chain) {
      CubicFrame f = *frame_of(c);
      f.start = f.start + f.start_tangent * 4.0, f.end = f.end + f.end_tangent * 4.0;
      frames.push_back(f), points.push_back(points_of(c, 50));
      const double chord = distance(f.start, f.end);
      initial.emplace_back(chord / 3.0, chord / 3.0);
    }
  }
  std::optional<std::vector<Cubic>> fit(const G2FitFreedom& freedom) const {
    return fit_g2_handles(frames, points, initial, std::nullopt, std::nullopt, freedom);
  }
};

TEST(G2HandleFit, AClosedChainComesBackFromNodesSlidAlongTheirTangents) {
  // With the nodes free to slide and κ continuous round the seam too, the fit finds the
  // ellipse itself, with full steps and with each round's step capped alike.
  const SlidEllipse e;
  ASSERT_NEAR(end_kappa(e.chain[3]), start_kappa(e.chain[0]), 1e-12);
  for (const double step_share : {0.0, 0.01}) {
    const auto fit = e.fit({{true, true, true, true}, 20.0, true, step_share});
    ASSERT_TRUE(fit) << step_share;
    for (std::size_t i = 0; i < 4; ++i) {
      for (std::size_t k = 0; k < 4; ++k)
        EXPECT_NEAR(distance((*fit)[i].p[k], e.chain[i].p[k]), 0.0, 1e-6) << step_share << " " << i << " " << k;
      EXPECT_NEAR(end_kappa((*fit)[i]), start_kappa((*fit)[(i + 1) % 4]), 1e-9 * start_kappa((*fit)[(i + 1) % 4]));
    }
    // Fixed where they were, the nodes keep the fit off the ellipse.
    const auto fixed = e.fit({{false, false, false, false}, 0.0, true, step_share});
    ASSERT_TRUE(fixed);
    EXPECT_NEAR(distance((*fixed)[0].p[0], e.chain[0].p[0]), 4.0, 1e-12);
  }
}

TEST(G2HandleFit, ASlideBeyondItsReachGivesNone) {
  // Slides of at most 1 unit allowed against the nodes' 4 units off: the rounds stop where a
  // node reaches that, short of a G2 chain, and the fit gives none. Allowed 5 units, it finds
  // the ellipse.
  const SlidEllipse e;
  EXPECT_FALSE(e.fit({{true, true, true, true}, 1.0, true, 0.01}));
  const auto fit = e.fit({{true, true, true, true}, 5.0, true, 0.01});
  ASSERT_TRUE(fit);
  EXPECT_NEAR(distance((*fit)[0].p[0], e.chain[0].p[0]), 0.0, 1e-6);
}

TEST(G2HandleFit, AFrameThatCannotBendAsAskedGivesNone) {
  // Both tangents along the chord: κ at its start is 0 for every pair of handles.
  const std::vector<CubicFrame> frames{{{0.0, 0.0}, {1.0, 0.0}, {100.0, 0.0}, {1.0, 0.0}}};
  std::vector<Vec2> line;
  for (int k = 0; k <= 10; ++k) line.push_back({10.0 * k, 0.0});
  const std::vector<std::vector<Vec2>> points{line};
  const std::vector<std::pair<double, double>> initial{{30.0, 30.0}};
  EXPECT_FALSE(fit_g2_handles(frames, points, initial, 0.01, std::nullopt));
  EXPECT_TRUE(fit_g2_handles(frames, points, initial, 0.0, std::nullopt));
}

}  // namespace
}  // namespace gf
