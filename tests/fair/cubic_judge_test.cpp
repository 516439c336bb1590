// A candidate cubic judged against its unrounded self: what the choice of handles asks for
// (weighed) and what the other passes ask for (traits) agree with a judge asked afresh.
#include "fair/cubic_judge.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace gf {
namespace {

// A circle of radius 100 drawn with four cubics, its nodes at the extrema.
std::vector<OutlineNode> circle() {
  const double h = 100.0 * 0.5522847498;
  const Vec2 at[] = {{100, 0}, {0, 100}, {-100, 0}, {0, -100}};
  const Vec2 tangent[] = {{0, 1}, {-1, 0}, {0, -1}, {1, 0}};
  std::vector<OutlineNode> nodes;
  for (int k = 0; k < 4; ++k) {
    OutlineNode node;
    node.point = at[k], node.in_handle = at[k] - tangent[k] * h, node.out_handle = at[k] + tangent[k] * h;
    nodes.push_back(node);
  }
  return nodes;
}

void expect_same_shape(const CubicTraits& a, const CubicTraits& b) {
  EXPECT_EQ(a.within, b.within);
  EXPECT_EQ(a.moved, b.moved);
  EXPECT_EQ(a.k_start, b.k_start);
  EXPECT_EQ(a.k_end, b.k_end);
  EXPECT_EQ(a.shape.turns, b.shape.turns);
  EXPECT_EQ(a.shape.sign_changes, b.shape.sign_changes);
  EXPECT_EQ(a.shape.variation, b.shape.variation);
  EXPECT_EQ(a.shape.largest, b.shape.largest);
  EXPECT_EQ(a.shape.head, b.shape.head);
  EXPECT_EQ(a.extrema.all, b.extrema.all);
  EXPECT_EQ(a.overreach, b.overreach);
  EXPECT_EQ(a.turning, b.turning);
}

TEST(CubicJudge, WhatTheChoiceWeighsAgreesWithTheWholeTraits) {
  const std::vector<OutlineNode> nodes = circle();
  const OutlineJoins joins{nodes, true};
  const HandleStepLimits limits;  // half a unit's allowance, no band
  const Cubic unrounded = outline_cubic(nodes, 0);
  Cubic near = unrounded, far = unrounded;
  near.p[1].x += 0.2;  // within the allowance
  far.p[1].x -= 30.0;  // far past it

  CubicJudge judge(nodes, nodes, joins, limits);
  EXPECT_TRUE(judge.weighed(0, near).within);
  EXPECT_FALSE(judge.weighed(0, far).within);
  // A candidate weighed first, asked for whole later: the same entry, its shape measured then,
  // as a judge that never weighed it measures it.
  const CubicTraits& weighed = judge.weighed(0, far);
  const CubicTraits& whole = judge.traits(0, far);
  EXPECT_EQ(&weighed, &whole);
  CubicJudge other(nodes, nodes, joins, limits);
  expect_same_shape(whole, other.traits(0, far));
  EXPECT_GT(whole.moved, limits.allowance);
  EXPECT_GT(whole.shape.largest, 0.0);  // its shape measured (an arc's κ is nowhere 0)
  // Within, what the choice weighs is the whole.
  expect_same_shape(judge.weighed(0, near), other.traits(0, near));
}

}  // namespace
}  // namespace gf
