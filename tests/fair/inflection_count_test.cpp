// Inflections counted along a run, against cubics whose curvature signs are known: an arch
// bends one way throughout, an S changes sign once (its signs at the ends from B′ × B″ there).
#include "fair/inflection_count.hpp"

#include <gtest/gtest.h>

namespace gf {
namespace {

// κ > 0 throughout (anticlockwise), κ < 0 throughout, and two S curves: from + to − and from − to +.
const CurvatureShape left_arch = curvature_shape(Cubic{{0, 0}, {1, -2}, {2, -2}, {3, 0}}, 0.0);
const CurvatureShape right_arch = curvature_shape(Cubic{{0, 0}, {1, 2}, {2, 2}, {3, 0}}, 0.0);
const CurvatureShape left_then_right = curvature_shape(Cubic{{0, 0}, {1, -1}, {2, 1}, {3, 0}}, 0.0);
const CurvatureShape right_then_left = curvature_shape(Cubic{{0, 0}, {1, 1}, {2, -1}, {3, 0}}, 0.0);

// What inflections_at found at a node: `added` sign changes, the inflection `moved` off it.
void expect_node(const NodeInflections& got, int added, bool moved) {
  EXPECT_EQ(got.added, added);
  EXPECT_EQ(got.moved, moved);
}

TEST(CurvatureShape, TheSignsNearestTheEnds) {
  EXPECT_EQ(left_arch.first_sign, 1);
  EXPECT_EQ(left_arch.last_sign, 1);
  EXPECT_EQ(right_arch.first_sign, -1);
  EXPECT_EQ(left_then_right.first_sign, 1);
  EXPECT_EQ(left_then_right.last_sign, -1);
  EXPECT_EQ(right_then_left.first_sign, -1);
  EXPECT_EQ(right_then_left.last_sign, 1);
  const CurvatureShape line = curvature_shape(Cubic{{0, 0}, {1, 1}, {2, 2}, {3, 3}}, 0.0);
  EXPECT_EQ(line.first_sign, 0);
  EXPECT_EQ(line.last_sign, 0);
}

TEST(InflectionCount, AnInflectionMovedAcrossItsNodeAddsNone) {
  // Unrounded: a left arch, then a right one, an inflection at the node between them. Rounded,
  // the first cubic turns right just before the node: one sign change more inside it, one fewer
  // across the node.
  ASSERT_TRUE(inflection_between(left_arch, right_arch));
  EXPECT_EQ(inflections_added_within(left_then_right, left_arch, false, true), 0);
  expect_node(inflections_at(left_then_right, left_arch, right_arch, right_arch), 0, true);
  // The same flip at the start of the cubic after.
  EXPECT_EQ(inflections_added_within(left_then_right, right_arch, true, false), 0);
  expect_node(inflections_at(left_arch, left_arch, left_then_right, right_arch), 0, true);
  // Neither side flipped: the inflection is where it was.
  expect_node(inflections_at(left_arch, left_arch, right_arch, right_arch), 0, false);
}

TEST(InflectionCount, BothSidesFlippedAtAnInflectionNodeAddTwo) {
  // + → − inside the first, − → + across the node, + → − inside the second: three against one.
  expect_node(inflections_at(left_then_right, left_arch, left_then_right, right_arch), 2, false);
}

TEST(InflectionCount, AFlipWhereKappaKeptItsSignIsTheCubicsOwn) {
  // Two left arches: no inflection at the node, so a flip at the end is an S inside the first
  // cubic, counted there; the node adds nothing of its own.
  ASSERT_FALSE(inflection_between(left_arch, left_arch));
  EXPECT_EQ(inflections_added_within(left_then_right, left_arch, false, false), 1);
  expect_node(inflections_at(left_then_right, left_arch, left_arch, left_arch), 0, false);
  // Nor does the other end being an inflection node take the flip over.
  EXPECT_EQ(inflections_added_within(left_then_right, left_arch, true, false), 1);
}

}  // namespace
}  // namespace gf
