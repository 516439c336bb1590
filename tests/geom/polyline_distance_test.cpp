// Directed Hausdorff distances to polylines: closed forms, the brute-force definition on
// random curves (the early exit, the pruning by boxes and the grid must change nothing), and
// the stop_above promise.
#include "geom/polyline_distance.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "point_set_distance.hpp"

namespace gf {
namespace {

// A wobbly open curve: n + 1 points along a random walk that turns a little at each step.
std::vector<Vec2> wobbly(std::mt19937& rng, int n, Vec2 start) {
  std::normal_distribution<double> turn(0.0, 0.4);
  std::vector<Vec2> out{start};
  double heading = 0.0;
  for (int k = 0; k < n; ++k) {
    heading += turn(rng);
    out.push_back(out.back() + Vec2{std::cos(heading), std::sin(heading)} * 5.0);
  }
  return out;
}

TEST(PolylineDistance, ClosedForms) {
  const std::vector<Vec2> segment{{-1, 0}, {1, 0}};
  EXPECT_DOUBLE_EQ(directed_hausdorff(std::vector<Vec2>{{0, 3}}, segment), 3.0);           // above the middle
  EXPECT_DOUBLE_EQ(directed_hausdorff(std::vector<Vec2>{{2, 1}}, segment), std::sqrt(2.0));  // past an end
  EXPECT_DOUBLE_EQ(directed_hausdorff(std::vector<Vec2>{{0, 3}, {2, 1}, {0.5, 0}}, segment), 3.0);
}

TEST(PolylineDistance, EarlyExitAndGridMatchTheDefinition) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> offset(-3.0, 3.0);
  for (int trial = 0; trial < 200; ++trial) {
    const std::vector<Vec2> a = wobbly(rng, 40, {0, 0});
    std::vector<Vec2> b = a;  // a nearby curve traced the same way, sampled differently
    for (Vec2& p : b) p = p + Vec2{offset(rng), offset(rng)};
    if (trial % 2) b = wobbly(rng, 25, {offset(rng), offset(rng)});  // or another curve entirely
    const double exact = test::directed_to_polyline(a, b);
    EXPECT_NEAR(directed_hausdorff(a, b), exact, 1e-12 * (1.0 + exact));
    EXPECT_NEAR(directed_hausdorff(a, PolylineGrid(b, 4.0)), exact, 1e-12 * (1.0 + exact));
    // One point alone takes every segment without the search's boxes: the same distance.
    const std::vector<Vec2> middle{a[a.size() / 2]};
    EXPECT_NEAR(directed_hausdorff(middle, b), test::directed_to_polyline(middle, b), 1e-12 * (1.0 + exact));
  }
}

TEST(PolylineDistance, TheGridNamesTheNearestSegment) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-20.0, 60.0);
  for (int trial = 0; trial < 50; ++trial) {
    const std::vector<Vec2> line = wobbly(rng, 30, {0, 0});
    const PolylineGrid grid(line, 4.0);
    for (int k = 0; k < 40; ++k) {
      const Vec2 p{u(rng), u(rng)};
      const double exact = test::directed_to_polyline({p}, line);
      const PolylineGrid::Nearest n = grid.nearest(p);
      ASSERT_LT(n.segment + 1, line.size());
      EXPECT_NEAR(n.distance, exact, 1e-12 * (1.0 + exact));
      // The segment named is one at that distance.
      EXPECT_NEAR(test::directed_to_polyline({p}, {line[n.segment], line[n.segment + 1]}), exact, 1e-12 * (1.0 + exact));
    }
  }
}

TEST(PolylineDistance, StopAboveIsExactBelowAndSaysPastAbove) {
  std::mt19937 rng(8);
  for (int trial = 0; trial < 100; ++trial) {
    const std::vector<Vec2> a = wobbly(rng, 30, {0, 0}), b = wobbly(rng, 30, {1, 1});
    const double exact = test::directed_to_polyline(a, b);
    EXPECT_NEAR(directed_hausdorff(a, b, 1.5 * exact), exact, 1e-12 * (1.0 + exact));
    EXPECT_GT(directed_hausdorff(a, b, 0.5 * exact), 0.5 * exact);
    EXPECT_LE(directed_hausdorff(a, b, 0.5 * exact), exact * (1.0 + 1e-12));  // never more than the truth
    // The same promise against the grid.
    const PolylineGrid grid(b, 4.0);
    EXPECT_NEAR(directed_hausdorff(a, grid, 1.5 * exact), exact, 1e-12 * (1.0 + exact));
    EXPECT_GT(directed_hausdorff(a, grid, 0.5 * exact), 0.5 * exact);
    EXPECT_LE(directed_hausdorff(a, grid, 0.5 * exact), exact * (1.0 + 1e-12));
  }
}

TEST(PolylineDistance, DistancePastIsExactPastTheFloorAndWithinItBelow) {
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> u(-20.0, 60.0), floors(0.0, 10.0);
  for (int trial = 0; trial < 50; ++trial) {
    const std::vector<Vec2> line = wobbly(rng, 30, {0, 0});
    const PolylineGrid grid(line, 4.0);
    for (int k = 0; k < 40; ++k) {
      const Vec2 p{u(rng), u(rng)};
      const double exact = grid.nearest(p).distance, f = floors(rng);
      const double past = grid.distance_past(p, f);
      if (exact > f) EXPECT_EQ(past, exact);  // bit for bit: the largest over many points is the same
      else EXPECT_LE(past, f);
      EXPECT_GE(past, exact);  // a segment's distance, never less than the nearest's
    }
  }
}

TEST(PolylineDistance, BoxesBuiltOnceGiveTheSameDistanceFromAnyFirstSegment) {
  // Against a polyline whose boxes are built once, wherever the search for the first point
  // starts: the definition below a stop, past it above one, and one point alone too.
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> offset(-3.0, 3.0);
  for (int trial = 0; trial < 100; ++trial) {
    const std::vector<Vec2> a = wobbly(rng, 30, {0, 0});
    std::vector<Vec2> b = a;
    for (Vec2& p : b) p = p + Vec2{offset(rng), offset(rng)};
    if (trial % 2) b = wobbly(rng, 45, {offset(rng), offset(rng)});
    const BoxedPolyline boxed(b);
    const double exact = test::directed_to_polyline(a, b);
    for (const std::size_t first : {std::size_t{0}, b.size() / 3, b.size() - 2, b.size() + 5}) {
      EXPECT_NEAR(directed_hausdorff(a, boxed, 1.5 * exact, first), exact, 1e-12 * (1.0 + exact));
      const double stopped = directed_hausdorff(a, boxed, 0.5 * exact, first);
      EXPECT_GT(stopped, 0.5 * exact);
      EXPECT_LE(stopped, exact * (1.0 + 1e-12));
      const std::vector<Vec2> middle{a[a.size() / 2]};
      const double alone = test::directed_to_polyline(middle, b);
      EXPECT_NEAR(directed_hausdorff(middle, boxed, std::numeric_limits<double>::infinity(), first), alone,
                  1e-12 * (1.0 + alone));
    }
  }
}

TEST(PolylineDistance, ByPieceIsTheHausdorffDistanceSharedOut) {
  // A curve of 3 pieces against a random other: the largest share is the two-sided distance
  // (brute force), and each piece's share bounds its own points' distance to the other.
  std::mt19937 rng(9);
  for (int trial = 0; trial < 50; ++trial) {
    const std::vector<Vec2> curve = wobbly(rng, 30, {0, 0}), other = wobbly(rng, 40, {0.5, 0.5});
    std::vector<std::size_t> piece_of;
    for (std::size_t k = 0; k < curve.size(); ++k) piece_of.push_back(std::min<std::size_t>(k / 10, 2));
    const std::vector<double> d = distance_by_piece(PolylineGrid(curve, 0.5), piece_of, PolylineGrid(other, 0.5));
    ASSERT_EQ(d.size(), 3u);
    const double exact = std::max(test::directed_to_polyline(curve, other), test::directed_to_polyline(other, curve));
    EXPECT_NEAR(*std::max_element(d.begin(), d.end()), exact, 1e-12 * (1.0 + exact));
    for (std::size_t k = 0; k < curve.size(); ++k)
      EXPECT_LE(test::directed_to_polyline({curve[k]}, other), d[piece_of[k]] * (1.0 + 1e-12));
  }
}

}  // namespace
}  // namespace gf
