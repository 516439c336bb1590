// The last pass over a faired contour's line kinks: merged where one line stays within the
// tolerance, else filleted; every kink taken where the passes can, the contour on the grid
// and within the tolerance of the source.
#include "fair/line_kinks.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "geom/join.hpp"
#include "point_set_distance.hpp"
#include "test_shapes.hpp"

namespace gf {
namespace {

using test::polygon;

std::size_t kinks_in(const Contour& c) {
  const std::vector<Join> joins = joins_of(c);
  return static_cast<std::size_t>(
      std::count_if(joins.begin(), joins.end(), [](const Join& j) { return j.kind == JoinKind::kink; }));
}

void expect_on_grid_within(const LineKinksTaken& taken, const Contour& source, double tolerance) {
  for (const Segment& s : taken.contour.segments) for_each_point(s, [](Vec2 p) { EXPECT_TRUE(test::on_grid(p)); });
  const std::vector<Vec2> a = test::contour_points(taken.contour, 200), b = test::contour_points(source, 200);
  const double d = std::max(test::directed_to_polyline(a, b), test::directed_to_polyline(b, a));
  EXPECT_LE(d, tolerance);
  EXPECT_GE(taken.deviation + 0.05, d);
}

TEST(LineKinks, KinksOneLineTakesAreMerged) {
  // A base bent 1.15° at (100, 1), a unit off its chord: one line again, no fillet.
  const Contour bent = polygon({{0, 0}, {100, 1}, {200, 0}, {200, 100}, {0, 100}});
  const LineKinksTaken taken = without_line_kinks(bent, 0.0, bent, 1.25, true);
  EXPECT_TRUE(taken.changed);
  EXPECT_EQ(taken.contour.segments, polygon({{0, 0}, {200, 0}, {200, 100}, {0, 100}}).segments);
  expect_on_grid_within(taken, bent, 1.25);
}

TEST(LineKinks, AKinkTheMergesLeaveIsFilletedWithTheRestMergedOnlyWhereNoFilletMayGo) {
  // URW P052's Z, its top: four lines sagging three units, bent 1.1° and 0.63° one way and
  // 0.28° back, in a glyph faired 1.06 units from its source elsewhere. Merged wherever one
  // line stays within the tolerance, the top is two lines bent 1.33° at (427, 689), on steps
  // (206, 3) and (347, 3): no fillet has whole legs there, nor at a vertex moved within what
  // the tolerance leaves. Merged only at the bend back (a fillet there would bend against the
  // others), the two first bends take fillets.
  const Contour top = polygon({{633, 692}, {477, 689}, {427, 689}, {245, 691}, {80, 692}, {80, 530}, {637, 530}});
  const double tolerance = 1.25;
  ASSERT_EQ(kinks_in(top), 3u);
  const LineKinksTaken taken = without_line_kinks(top, 1.06, top, tolerance, true);
  EXPECT_EQ(kinks_in(taken.contour), 0u);
  const auto curves = std::count_if(taken.contour.segments.begin(), taken.contour.segments.end(),
                                    [](const Segment& s) { return !is_line(s); });
  EXPECT_EQ(curves, 2);
  expect_on_grid_within(taken, top, tolerance);
}

TEST(LineKinks, WithoutAKinkTheContourComesBackAsItWas) {
  const Contour square = polygon({{0, 0}, {100, 0}, {100, 100}, {0, 100}});
  const LineKinksTaken taken = without_line_kinks(square, 0.5, square, 1.25, true);
  EXPECT_FALSE(taken.changed);
  EXPECT_EQ(taken.contour, square);
  EXPECT_EQ(taken.deviation, 0.5);
}

}  // namespace
}  // namespace gf
