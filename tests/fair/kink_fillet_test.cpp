// Kinks between lines filleted G2: the fillet leaves each line along it with κ = 0 (both its
// handles on the vertex), its ends on the grid, within the allowance of the lines; a kink
// whose fillet would bend against its neighbours stays.
#include "fair/kink_fillet.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "geom/curvature.hpp"
#include "point_set_distance.hpp"

namespace gf {
namespace {

Contour polygon(const std::vector<Vec2>& points) {
  Contour c;
  for (std::size_t i = 0; i < points.size(); ++i) {
    c.segments.push_back(Line{points[i], points[(i + 1) % points.size()]});
    c.nodes.push_back({});
  }
  return c;
}

double degrees(Vec2 a, Vec2 b) { return std::abs(turning_angle(a, b)) * 180.0 / std::numbers::pi; }

std::vector<Vec2> dense(const Contour& c) {
  std::vector<Vec2> out;
  for (const Segment& s : c.segments)
    for (int k = 0; k < 200; ++k) out.push_back(point_at(s, k / 200.0));
  return out;
}

TEST(KinkFillet, AKinkBetweenTwoLinesBecomesG2OnTheGrid) {
  // A stroke's side bending by 1.07° at (280, 0) between corners (Cantarell's y).
  const Contour source = polygon({{115, -217}, {200, -217}, {280, 0}, {468, 482}, {388, 482}});
  const double allowance = 1.0;
  const Contour out = fillet_line_kinks(source, allowance, true);
  ASSERT_EQ(out.segments.size(), out.nodes.size());
  int cubics = 0;
  for (std::size_t i = 0; i < out.segments.size(); ++i) {
    const Segment& s = out.segments[i];
    for_each_point(s, [](Vec2 p) { EXPECT_TRUE(p.x == std::round(p.x) && p.y == std::round(p.y)); });
    const Segment& next = out.segments[(i + 1) % out.segments.size()];
    const double turn = degrees(*end_tangent(s, SegmentEnd::end), *end_tangent(next, SegmentEnd::start));
    EXPECT_TRUE(turn == 0.0 || turn >= 3.0) << "join " << i << " turns " << turn << "°";
    if (is_line(s)) continue;
    ++cubics;
    EXPECT_EQ(*end_curvature(s, SegmentEnd::start).curvature, 0.0);
    EXPECT_EQ(*end_curvature(s, SegmentEnd::end).curvature, 0.0);
  }
  EXPECT_EQ(cubics, 1);
  EXPECT_LE(test::directed_to_polyline(dense(out), dense(source)), allowance);
}

TEST(KinkFillet, AKinkAgainstItsNeighboursStays) {
  // A side bending left at one kink and right at the next: a fillet at each would be an S
  // (an inflection the polygon has not got), so neither is filleted.
  const Contour source = polygon({{0, 0}, {1000, 0}, {1000, 100}, {600, 104}, {300, 100}, {0, 104}});
  const Contour out = fillet_line_kinks(source, 2.0, true);
  EXPECT_EQ(out.segments.size(), source.segments.size());
}

TEST(KinkFillet, WithoutAKinkTheContourComesBackAsItWas) {
  const Contour square = polygon({{0, 0}, {100, 0}, {100, 100}, {0, 100}});
  EXPECT_EQ(fillet_line_kinks(square, 1.0, true).segments.size(), 4u);
}

}  // namespace
}  // namespace gf
