// Balanced starting tangents: points on a circle give the circle's own tangents (every
// segment symmetric), open or closed; a κ = 0 start aims the next tangent at twice the chord
// angle; junction tangents outside the wedge between their chords are turned into it, and
// only those.
#include "fair/initial_tangents.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace gf {
namespace {

double diff(double a, double b) { return std::remainder(a - b, 2 * std::numbers::pi); }

TEST(InitialTangents, CircleClosed) {
  std::vector<Vec2> pts;
  const int n = 7;
  for (int i = 0; i < n; ++i) {
    const double t = 2 * std::numbers::pi * i / n + 0.3 * std::sin(i);  // uneven spacing
    pts.push_back({100 * std::cos(t), 100 * std::sin(t)});
  }
  const std::vector<double> phi = balanced_tangents(pts, true, std::nullopt, std::nullopt);
  for (int i = 0; i < n; ++i) {
    const double t = std::atan2(pts[i].y, pts[i].x);
    EXPECT_NEAR(diff(phi[i], t + std::numbers::pi / 2), 0.0, 1e-4) << i;  // the pull to the bisectors is weak
  }
}

TEST(InitialTangents, CircleOpenWithExactEnds) {
  std::vector<Vec2> pts;
  for (int i = 0; i <= 5; ++i) {
    const double t = 0.25 * i * i;
    pts.push_back({80 * std::cos(t), 80 * std::sin(t)});
  }
  const double start = std::numbers::pi / 2, end = 0.25 * 25 + std::numbers::pi / 2;
  const std::vector<double> phi = balanced_tangents(pts, false, start, end);
  for (int i = 0; i <= 5; ++i) EXPECT_NEAR(diff(phi[i], 0.25 * i * i + std::numbers::pi / 2), 0.0, 1e-4) << i;
}

TEST(InitialTangents, ZeroCurvatureStartTurnsTheOtherEndTwiceAsMuch) {
  // Two segments; only the middle tangent is free. Its least-squares value balances
  // (φ1 − c0) = −2 (φ0 − c0) against the second segment's symmetry.
  const std::vector<Vec2> pts{{0, 0}, {100, 10}, {180, 60}};
  const std::vector<double> balanced = balanced_tangents(pts, false, 0.0, 0.9);
  const std::vector<double> zero = balanced_tangents(pts, false, 0.0, 0.9, true, false);
  const double c0 = std::atan2(10.0, 100.0);
  // From a κ = 0 start the end angle of the first segment grows.
  EXPECT_GT(zero[1] - c0, balanced[1] - c0);
}

TEST(InitialTangents, JunctionsOutsideTheirWedgeTurnIntoIt) {
  // An open chain turning left (way > 0) on a circle, with a zigzag at junction 4 (its chords
  // turn right there): angles off by ±0.3 rad at 1 and 2, inside at 3.
  std::vector<Vec2> pts;
  for (int i = 0; i < 7; ++i) {
    const double t = 0.2 * i;
    pts.push_back(Vec2{std::cos(t), std::sin(t)} * 100.0);
  }
  pts[4] = pts[4] * 0.97;  // inside the circle: the chords turn right at 4
  const auto chord = [&](std::size_t i) { return std::atan2(pts[i + 1].y - pts[i].y, pts[i + 1].x - pts[i].x); };
  std::vector<double> angles(7);
  for (std::size_t j = 1; j < 6; ++j) angles[j] = 0.5 * (chord(j - 1) + chord(j));
  angles[0] = chord(0) - 0.5, angles[6] = chord(5) + 0.5;  // the given ends: out of any wedge
  angles[1] = chord(0) - 0.3, angles[2] = chord(2) + 0.3;
  std::vector<double> kept = angles;
  keep_tangents_between_chords(pts, false, 1.0, kept);
  EXPECT_EQ(kept[0], angles[0]);
  EXPECT_EQ(kept[6], angles[6]);
  for (const std::size_t j : {std::size_t{1}, std::size_t{2}}) {  // into the wedge, a tenth in from its side
    const double wedge = diff(chord(j), chord(j - 1)), off = diff(kept[j], chord(j - 1));
    EXPECT_GT(wedge, 0.0);
    EXPECT_NEAR(off, j == 1 ? 0.1 * wedge : 0.9 * wedge, 1e-12);
  }
  EXPECT_EQ(kept[3], angles[3]);  // already inside
  EXPECT_LT(diff(chord(4), chord(3)), 0.0);
  EXPECT_EQ(kept[4], angles[4]);  // turning the other way: no wedge to keep to
  // Next to a κ = 0 start, the aimed junction stays.
  std::vector<double> aimed = angles;
  keep_tangents_between_chords(pts, false, 1.0, aimed, true, false);
  EXPECT_EQ(aimed[1], angles[1]);
  EXPECT_EQ(aimed[2], kept[2]);
}

}  // namespace
}  // namespace gf
