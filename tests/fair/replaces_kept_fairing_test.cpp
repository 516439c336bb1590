// Which fairing again of a contour replaces the one kept (fair/contour_fairing.hpp): fewer
// faults, and a fairing mended by splits beside its jumps only where its nodes without the
// splits are no more than the kept one's (Accanthis's c: 28 nodes less 1 split against 23).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "fair/contour_fairing.hpp"
#include "test_shapes.hpp"

namespace gf {
namespace {

// A faired contour of `nodes` nodes (a regular polygon), `split_nodes` of them from splits.
ContourFairing fairing_with(int nodes, int split_nodes = 0) {
  std::vector<Vec2> corners;
  for (int k = 0; k < nodes; ++k) {
    const double a = 2.0 * std::numbers::pi * k / nodes;
    corners.push_back({100.0 * std::cos(a), 100.0 * std::sin(a)});
  }
  ContourFairing f;
  f.contour = test::polygon(corners);
  f.faired = true;
  f.split_nodes = split_nodes;
  return f;
}

TEST(ReplacesKeptFairing, ASplitMendIsKeptOnlyWithNoMoreNodesThanTheKeptFairingWithoutItsSplits) {
  const ContourFairing kept = fairing_with(23);
  const OutlineFaults one_jump{1, 0, 0, 0}, none{};
  // Accanthis's c: 28 nodes, one of them a split's, against 23 and a jump.
  EXPECT_FALSE(replaces_kept_fairing(fairing_with(28, 1), none, kept, one_jump));
  // Without the split as many nodes as the kept one, or fewer: the mend is worth its node.
  EXPECT_TRUE(replaces_kept_fairing(fairing_with(24, 1), none, kept, one_jump));
  EXPECT_TRUE(replaces_kept_fairing(fairing_with(22, 2), none, kept, one_jump));
  // A fairing without splits is judged by its faults alone, whatever its nodes.
  EXPECT_TRUE(replaces_kept_fairing(fairing_with(28), none, kept, one_jump));
  // And a split one too needs fewer faults.
  EXPECT_FALSE(replaces_kept_fairing(fairing_with(24, 1), one_jump, kept, one_jump));
}

TEST(ReplacesKeptFairing, SplitsThatLeftNoNodeMoreAreJudgedByFaultsAlone) {
  // Rounding the split outline may merge more short cubics than the splits added (split_nodes
  // then below zero): nothing added, nothing held against it.
  const ContourFairing kept = fairing_with(20);
  EXPECT_TRUE(replaces_kept_fairing(fairing_with(26, -1), OutlineFaults{}, kept, OutlineFaults{1, 0, 0, 0}));
  EXPECT_FALSE(replaces_kept_fairing(fairing_with(26, -1), OutlineFaults{1, 0, 0, 0}, kept, OutlineFaults{1, 0, 0, 0}));
}

}  // namespace
}  // namespace gf
