// The curvature the writeback gives a chain's nodes: the path's where every span fits whole or
// nothing is gained; elsewhere a free node moves as far as lets both its spans fit, keeping its
// sign, and never where a span beside it stays cut. The spans' fit is given here as a rule on
// the end curvatures, the oracle each test checks the choice against.
#include "fair/node_curvatures.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <optional>
#include <vector>

namespace gf {
namespace {

// Three nodes of an open chain: its ends bound (the path's curvature), the extremum between free.
std::vector<NodeCurvature> open_chain(double middle) {
  return {{.path = 0.5}, {.path = middle, .free = true}, {.path = 0.25}};
}

// No span has a nearest cubic to seed from.
std::optional<std::array<double, 2>> no_seeds(std::size_t) { return std::nullopt; }

TEST(NodeCurvatures, WhereEverySpanFitsTheyAreThePaths) {
  int asked = 0;
  const auto fits = [&](std::size_t, double, double) {
    ++asked;
    return true;
  };
  int seeded = 0;
  const auto seeds = [&](std::size_t) -> std::optional<std::array<double, 2>> {
    ++seeded;
    return std::nullopt;
  };
  const std::vector<double> k = choose_node_curvatures(open_chain(1.0), false, fits, seeds);
  EXPECT_EQ(k, (std::vector<double>{0.5, 1.0, 0.25}));
  EXPECT_EQ(asked, 2);  // each span once, as the path has it
  EXPECT_EQ(seeded, 0);
}

// The first span fits only with the extremum's curvature between 1.3 and 1.6 times the path's,
// the second only up to 1.5: the node moves into [1.3, 1.5], and no farther than it must.
TEST(NodeCurvatures, AFreeNodeMovesWhereBothItsSpansThenFitWhole) {
  const auto fits = [](std::size_t i, double k_start, double k_end) {
    return i == 0 ? k_end >= 1.3 && k_end <= 1.6 : k_start <= 1.5;
  };
  const std::vector<double> k = choose_node_curvatures(open_chain(1.0), false, fits, no_seeds);
  ASSERT_EQ(k.size(), 3u);
  EXPECT_EQ(k[0], 0.5);
  EXPECT_EQ(k[2], 0.25);
  EXPECT_TRUE(fits(0, k[0], k[1]) && fits(1, k[1], k[2])) << k[1];
  EXPECT_LT(k[1], 1.5);
}

// Where the span after it fits whole with no curvature there, the node keeps the path's: moved,
// the first span would take one cubic and the second as many as before or more.
TEST(NodeCurvatures, ANodeBesideASpanThatStaysCutKeepsThePaths) {
  const auto fits = [](std::size_t i, double, double k_end) { return i == 0 && k_end >= 1.3; };
  EXPECT_EQ(choose_node_curvatures(open_chain(1.0), false, fits, no_seeds)[1], 1.0);
}

// A curvature of the other sign would make the node an inflection.
TEST(NodeCurvatures, ANodeKeepsItsSign) {
  const auto fits = [](std::size_t i, double k_start, double k_end) { return (i == 0 ? k_end : k_start) < 0.0; };
  const auto seeds = [](std::size_t i) { return std::optional(i == 0 ? std::array{0.5, -1.0} : std::array{-1.0, 0.25}); };
  EXPECT_EQ(choose_node_curvatures(open_chain(1.0), false, fits, seeds)[1], 1.0);
}

// A chain's end (not free) keeps the path's curvature whatever would fit.
TEST(NodeCurvatures, ABoundNodeKeepsThePaths) {
  const auto fits = [](std::size_t i, double k_start, double) { return i != 0 || k_start >= 1.0; };
  EXPECT_EQ(choose_node_curvatures(open_chain(1.0), false, fits, no_seeds)[0], 0.5);
}

// Three times the path's curvature lies past the ladder tried around it; a seed (the curvature
// the best-fitting cubic with free ends has there) reaches it.
TEST(NodeCurvatures, ASeedReachesPastTheLadder) {
  const auto near3 = [](double k) { return std::abs(k - 3.0) < 1e-3; };
  const auto fits = [&](std::size_t i, double k_start, double k_end) { return near3(i == 0 ? k_end : k_start); };
  EXPECT_EQ(choose_node_curvatures(open_chain(1.0), false, fits, no_seeds)[1], 1.0);
  const auto seeds = [](std::size_t i) { return std::optional(i == 0 ? std::array{0.5, 3.0} : std::array{3.0, 0.25}); };
  EXPECT_EQ(choose_node_curvatures(open_chain(1.0), false, fits, seeds)[1], 3.0);
}

// A closed chain of two free nodes whose two spans both fit only with both curvatures at 1.2 or
// more: both move, and its last span, back to the first node, fits too.
TEST(NodeCurvatures, AClosedChainsLastSpanReturnsToItsFirstNode) {
  const std::vector<NodeCurvature> nodes{{.path = 1.0, .free = true}, {.path = 1.0, .free = true}};
  const auto fits = [](std::size_t, double k_start, double k_end) { return k_start >= 1.2 && k_end >= 1.2; };
  const std::vector<double> k = choose_node_curvatures(nodes, true, fits, no_seeds);
  ASSERT_EQ(k.size(), 2u);
  EXPECT_TRUE(fits(0, k[0], k[1]) && fits(1, k[1], k[0])) << k[0] << ' ' << k[1];
}

}  // namespace
}  // namespace gf
