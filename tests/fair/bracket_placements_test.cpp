// Placements of a serif's bracket on the grid, against their defining invariants: every point
// on the grid, G1 exact at the three joins (each join's handles along its line or the node's
// direction, whole steps of it), κ from the closed form at a cubic's end, (2/3)·(P1 − P0) ×
// (P2 − P1) / |P1 − P0|³, within the target of 0 at the joins and of itself across the node.
#include "fair/bracket_placements.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace gf {
namespace {

constexpr double flat = 5e-4;  // 0.5 / UPM at 1000 units per em
constexpr double target = 0.03;
constexpr double most_turn = 0.1;

// κ where a cubic leaves p0 towards p1, p2 (closed form).
double start_curvature(Vec2 p0, Vec2 p1, Vec2 p2) {
  const Vec2 a = p1 - p0, b = p2 - p1;
  return 2.0 / 3.0 * (a.x * b.y - a.y * b.x) / std::pow(std::hypot(a.x, a.y), 3);
}

bool on_grid(Vec2 p) { return p.x == std::round(p.x) && p.y == std::round(p.y); }

// Whether `to − from` is a whole number (at least one) of `step`s.
bool whole_steps_of(Vec2 from, Vec2 to, Vec2 step) {
  const Vec2 d = to - from;
  if (d.x * step.y - d.y * step.x != 0.0) return false;
  const double m = (d.x * step.x + d.y * step.y) / (step.x * step.x + step.y * step.y);
  return m >= 1.0 && m == std::round(m);
}

// TeX Gyre Pagella's H, its bottom left serif as the fairing leaves it before rounding: the
// serif's top (a line of step (−16, 1) from its corner at (315, 27)), the bracket's two cubics,
// the stem (x = 216); rounded, the line took (−12, 1) from (279, 30), and the join kept κ·UPM
// 0.13 however the node's handle went.
Bracket pagella_serif() {
  Bracket b;
  b.first = BracketLine{{315, 27}, std::nullopt, {279, 30}, {-12, 1}, {315, 27}, {267, 30}, true};
  b.last = BracketLine{{216, 343}, std::nullopt, {216, 120}, {0, 1}, {216, 343}, {216, 120}, false};
  b.exact = {Vec2{267, 30}, {252.19, 30.93}, {237.6, 31.84}, {229.14, 40.3}, {216, 53.44}, {216, 86.4}, {216, 120}};
  return b;
}

std::vector<Vec2> node_points() {
  std::vector<Vec2> out;
  for (int dy = -2; dy <= 2; ++dy)
    for (int dx = -2; dx <= 2; ++dx) out.push_back({229.0 + dx, 40.0 + dy});
  return out;
}

TEST(BracketPlacements, MeetG2AtAllThreeJoinsWithG1Exact) {
  const Bracket bracket = pagella_serif();
  const std::vector<Vec2> steps{{-1, 1}, {-4, 5}, {-5, 4}, {-5, 6}, {-6, 5}};
  const std::vector<BracketPlacement> found =
      bracket_placements(bracket, node_points(), steps, flat, target, most_turn, 48);
  ASSERT_FALSE(found.empty());
  EXPECT_LE(found.size(), 48u);
  for (std::size_t k = 0; k < found.size(); ++k) {
    const BracketPlacement& p = found[k];
    for (const Vec2 q : {p.join1, p.handle1, p.handle2, p.node, p.handle3, p.handle4, p.join2}) EXPECT_TRUE(on_grid(q));
    // The serif's top turns about its corner onto the join's step; the stem stays upright.
    EXPECT_EQ(p.far1, (Vec2{315, 27}));
    EXPECT_TRUE(whole_steps_of(p.far1, p.join1, p.step1));
    EXPECT_TRUE(whole_steps_of(p.join1, p.handle1, p.step1));
    EXPECT_LE(std::abs(std::atan2(p.step1.y, p.step1.x) - std::atan2(1.0, -16.0)), most_turn);
    EXPECT_EQ(p.join2.x, 216.0);
    EXPECT_EQ(p.step2, (Vec2{0, 1}));
    EXPECT_TRUE(whole_steps_of(p.handle4, p.join2, p.step2));
    // The node's handles along its direction, whole steps either side.
    EXPECT_TRUE(whole_steps_of(p.handle2, p.node, p.node_step));
    EXPECT_TRUE(whole_steps_of(p.node, p.handle3, p.node_step));
    // κ = 0 leaving the serif's top and reaching the stem; the same either side of the node.
    EXPECT_LE(std::abs(start_curvature(p.join1, p.handle1, p.handle2)), target * flat);
    EXPECT_LE(std::abs(start_curvature(p.join2, p.handle4, p.handle3)), target * flat);
    const double before = -start_curvature(p.node, p.handle2, p.handle1);  // reversed: the sign turns
    const double after = start_curvature(p.node, p.handle3, p.handle4);
    EXPECT_LE(std::abs(before - after), target * std::max({std::abs(before), std::abs(after), flat}));
    if (k > 0) {
      EXPECT_LE(found[k - 1].spread, p.spread);
    }
  }
  // The nearest keeps within a unit of the unrounded bracket at its quarter points.
  EXPECT_LT(found.front().spread, 1.0);
}

TEST(BracketPlacements, ALineThatMayNotTurnOnlySlides) {
  Bracket bracket = pagella_serif();
  BracketLine& top = std::get<BracketLine>(bracket.first);
  top.may_turn = false;
  const std::vector<Vec2> steps{{-1, 1}, {-4, 5}, {-5, 4}};
  for (const BracketPlacement& p : bracket_placements(bracket, node_points(), steps, flat, target, most_turn, 48)) {
    EXPECT_EQ(p.step1, (Vec2{-12, 1}));
    EXPECT_TRUE(p.join1 == top.join || whole_steps_of(top.join, p.join1, p.step1) ||
                whole_steps_of(p.join1, top.join, p.step1));
  }
}

TEST(BracketPlacements, ACornerMayGoBackToItsNearestGridPoint) {
  // Pagella's i: rounding put the serif's top corner a unit up its side, (271, 28), where every
  // grid point near the top's unrounded line lies a long step from it; from (271, 27) the line
  // of step (−15, 1) carries the bracket.
  Bracket bracket;
  bracket.first = BracketLine{{271, 28}, Vec2{271, 27}, {245, 28}, {-1, 0}, {271, 27}, {225, 30}, true};
  bracket.last = BracketLine{{188, 465}, std::nullopt, {188, 102}, {0, 1}, {188, 465}, {188, 102}, false};
  bracket.exact = {Vec2{225, 30}, {214.75, 30.67}, {204.04, 31.37}, {197.87, 37.54}, {188, 47.41}, {188, 72.98}, {188, 102}};
  std::vector<Vec2> points;
  for (int dy = -2; dy <= 2; ++dy)
    for (int dx = -2; dx <= 2; ++dx) points.push_back({198.0 + dx, 38.0 + dy});
  const std::vector<Vec2> steps{{-1, 1}, {-4, 5}, {-5, 4}, {-6, 5}, {-5, 6}};
  const std::vector<BracketPlacement> found = bracket_placements(bracket, points, steps, flat, target, most_turn, 48);
  ASSERT_FALSE(found.empty());
  for (const BracketPlacement& p : found) {
    EXPECT_TRUE(p.far1 == Vec2(271, 27) || p.far1 == Vec2(271, 28));
    EXPECT_TRUE(whole_steps_of(p.far1, p.join1, p.step1));
  }
  EXPECT_EQ(found.front().far1, (Vec2{271, 27}));
}

TEST(BracketPlacements, AnEndInsideARunKeepsItsNodeAndMeetsItsCurvature) {
  // The serif's bracket seen from a longer run: its stem end is a node at (216, 120) going up,
  // beyond which the run's next cubic starts with κ = −0.004; the node stays, its in-handle
  // takes whole steps up the stem, and κ there meets the next cubic's.
  Bracket bracket = pagella_serif();
  const double beyond = -0.004;
  bracket.last = BracketNode{{216, 120}, {0, 1}, beyond};
  const std::vector<Vec2> steps{{-1, 1}, {-4, 5}, {-5, 4}, {-5, 6}, {-6, 5}};
  const std::vector<BracketPlacement> found =
      bracket_placements(bracket, node_points(), steps, flat, target, most_turn, 48);
  ASSERT_FALSE(found.empty());
  for (const BracketPlacement& p : found) {
    EXPECT_EQ(p.join2, (Vec2{216, 120}));
    EXPECT_EQ(p.far2, (Vec2{216, 120}));
    EXPECT_TRUE(whole_steps_of(p.handle4, p.join2, Vec2{0, 1}));
    EXPECT_TRUE(whole_steps_of(p.node, p.handle3, p.node_step));
    // κ reaching the node (216, 120): the reversed cubic leaves it with the opposite sign.
    const double at_end = -start_curvature(p.join2, p.handle4, p.handle3);
    EXPECT_LE(std::abs(at_end - beyond), target * std::max(std::abs(at_end), std::abs(beyond)));
    EXPECT_LE(std::abs(start_curvature(p.join1, p.handle1, p.handle2)), target * flat);
  }
}

TEST(BracketPlacements, ACornerEndKeepsItsHandlesDirectionAndAnyCurvature) {
  // The bracket ending at a corner on the stem instead: the corner stays, its handle whole
  // steps down the stem from it, κ there free; the joins at the line and the node still meet.
  Bracket bracket = pagella_serif();
  bracket.last = BracketNode{{216, 120}, {0, 1}, std::nullopt};
  const std::vector<Vec2> steps{{-1, 1}, {-4, 5}, {-5, 4}};
  const std::vector<BracketPlacement> found =
      bracket_placements(bracket, node_points(), steps, flat, target, most_turn, 48);
  ASSERT_FALSE(found.empty());
  for (const BracketPlacement& p : found) {
    EXPECT_EQ(p.join2, (Vec2{216, 120}));
    EXPECT_TRUE(whole_steps_of(p.handle4, p.join2, Vec2{0, 1}));
    EXPECT_LE(std::abs(start_curvature(p.join1, p.handle1, p.handle2)), target * flat);
    const double before = -start_curvature(p.node, p.handle2, p.handle1);
    const double after = start_curvature(p.node, p.handle3, p.handle4);
    EXPECT_LE(std::abs(before - after), target * std::max({std::abs(before), std::abs(after), flat}));
  }
}

}  // namespace
}  // namespace gf
