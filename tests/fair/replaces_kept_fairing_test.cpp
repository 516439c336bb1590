// Which fairing again of a contour replaces the one kept (fair/contour_fairing.hpp): fewer
// faults, and a fairing mended by splits beside its jumps only where its nodes without the
// splits are no more than the kept one's (Accanthis's c: 28 nodes less 1 split against 23);
// one whose joins were mended on the grid only with a node more per join mended or within the
// bar's 1.3 times the source's nodes.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "fair/contour_fairing.hpp"
#include "test_shapes.hpp"

namespace gf {
namespace {

// Source contours whose node count leaves the mended-joins rule (below) out of these tests.
constexpr std::size_t any_source = 1000;

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
  EXPECT_FALSE(replaces_kept_fairing(fairing_with(28, 1), none, kept, one_jump, any_source));
  // Without the split as many nodes as the kept one, or fewer: the mend is worth its node.
  EXPECT_TRUE(replaces_kept_fairing(fairing_with(24, 1), none, kept, one_jump, any_source));
  EXPECT_TRUE(replaces_kept_fairing(fairing_with(22, 2), none, kept, one_jump, any_source));
  // A fairing without splits is judged by its faults alone, whatever its nodes.
  EXPECT_TRUE(replaces_kept_fairing(fairing_with(28), none, kept, one_jump, any_source));
  // And a split one too needs fewer faults.
  EXPECT_FALSE(replaces_kept_fairing(fairing_with(24, 1), one_jump, kept, one_jump, any_source));
}

TEST(ReplacesKeptFairing, SplitsThatLeftNoNodeMoreAreJudgedByFaultsAlone) {
  // Rounding the split outline may merge more short cubics than the splits added (split_nodes
  // then below zero): nothing added, nothing held against it.
  const ContourFairing kept = fairing_with(20);
  EXPECT_TRUE(replaces_kept_fairing(fairing_with(26, -1), OutlineFaults{}, kept, OutlineFaults{1, 0, 0, 0}, any_source));
  EXPECT_FALSE(replaces_kept_fairing(fairing_with(26, -1), OutlineFaults{1, 0, 0, 0}, kept, OutlineFaults{1, 0, 0, 0}, any_source));
}

TEST(ReplacesKeptFairing, AMendedFairingMayTakeANodePerJoinMendedOrStayWithinTheBarOfTheSourcesNodes) {
  const OutlineFaults one_jump{1, 0, 0, 0}, none{};
  const auto mended = [](int nodes) {
    ContourFairing f = fairing_with(nodes);
    f.mended_joins = 1;
    return f;
  };
  // Accanthis's c: a fairing of 30 nodes mended against 21 and a jump, of 10 in the source.
  EXPECT_FALSE(replaces_kept_fairing(mended(30), none, fairing_with(21), one_jump, 10));
  // Junicode's z: a node more for the jump mended, though past 1.3 times its source's 24.
  EXPECT_TRUE(replaces_kept_fairing(mended(32), none, fairing_with(31), one_jump, 24));
  EXPECT_FALSE(replaces_kept_fairing(mended(33), none, fairing_with(31), one_jump, 24));
  // TeX Gyre Schola's X: three nodes more, within 1.3 times its source's 40.
  EXPECT_TRUE(replaces_kept_fairing(mended(50), none, fairing_with(47), one_jump, 40));
  // Unmended, the fairing is judged by its faults alone, as before.
  EXPECT_TRUE(replaces_kept_fairing(fairing_with(30), none, fairing_with(21), one_jump, 10));
}

}  // namespace
}  // namespace gf
