#include "geom/contour.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace gf {
namespace {

TEST(Contour, SignedAreaOfSquareAndItsReverse) {
  Contour c;
  c.segments = {Line{{{0, 0}, {2, 0}}}, Line{{{2, 0}, {2, 2}}}, Line{{{2, 2}, {0, 2}}}, Line{{{0, 2}, {0, 0}}}};
  c.nodes.assign(4, NodeFlags{});
  EXPECT_DOUBLE_EQ(signed_area(c), 4.0);
  Contour r;
  r.segments = {Line{{{0, 0}, {0, 2}}}, Line{{{0, 2}, {2, 2}}}, Line{{{2, 2}, {2, 0}}}, Line{{{2, 0}, {0, 0}}}};
  r.nodes.assign(4, NodeFlags{});
  EXPECT_DOUBLE_EQ(signed_area(r), -4.0);
}

TEST(Contour, SignedAreaIsExactForCurves) {
  // Region under the parabola y = x(2 − x) from 0 to 2 closed by the baseline: area 4/3.
  Contour c;
  c.segments = {Quad{{{2, 0}, {1, 2}, {0, 0}}}, Line{{{0, 0}, {2, 0}}}};
  c.nodes.assign(2, NodeFlags{});
  EXPECT_NEAR(signed_area(c), 4.0 / 3.0, 1e-15);
  Contour cubic = c;
  cubic.segments[0] = to_cubic(std::get<Quad>(c.segments[0]));
  EXPECT_NEAR(signed_area(cubic), 4.0 / 3.0, 1e-15);
}

TEST(Contour, OnIntegerGridLooksAtStoredPointsOnly) {
  // A TrueType circle-ish contour: the on-curve point implied between two off-curve points
  // falls on a half and is not stored.
  Contour c;
  c.segments = {Quad{{{0, 0}, {1, 0}, {1.5, 0.5}}}, Quad{{{1.5, 0.5}, {2, 1}, {0, 0}}}};
  c.nodes = {NodeFlags{}, NodeFlags{true, std::nullopt}};
  EXPECT_TRUE(on_integer_grid(c));
  c.nodes[1].implied = false;
  EXPECT_FALSE(on_integer_grid(c));
  Contour open;
  open.closed = false;
  open.segments = {Cubic{{{0, 0}, {1, 2}, {3, 2}, {4, 0.25}}}};
  open.nodes.assign(2, NodeFlags{});
  EXPECT_FALSE(on_integer_grid(open));
  std::get<Cubic>(open.segments[0]).p[3].y = 0.0;
  EXPECT_TRUE(on_integer_grid(open));
  std::get<Cubic>(open.segments[0]).p[1].x = 58.68;
  EXPECT_FALSE(on_integer_grid(open));
}

TEST(Contour, ThicknessIsAStrokesWidthAndACirclesRadius) {
  // A 100 × 10 bar: 2·1000 / 220.
  Contour bar;
  bar.segments = {Line{{{0, 0}, {100, 0}}}, Line{{{100, 0}, {100, 10}}}, Line{{{100, 10}, {0, 10}}}, Line{{{0, 10}, {0, 0}}}};
  bar.nodes.assign(4, NodeFlags{});
  EXPECT_NEAR(thickness(bar), 2000.0 / 220.0, 1e-12);
  // A circle of radius 50 in four cubics (handles 0.5523 r: area and length within 3e-4 of the
  // circle's): 2·πr² / 2πr = r.
  const double r = 50.0, h = 0.5523 * r;
  Contour circle;
  circle.segments = {Cubic{{{r, 0}, {r, h}, {h, r}, {0, r}}}, Cubic{{{0, r}, {-h, r}, {-r, h}, {-r, 0}}},
                     Cubic{{{-r, 0}, {-r, -h}, {-h, -r}, {0, -r}}}, Cubic{{{0, -r}, {h, -r}, {r, -h}, {r, 0}}}};
  circle.nodes.assign(4, NodeFlags{});
  EXPECT_NEAR(thickness(circle), r, 3e-4 * r);
  // Its reverse is as thick; a contour of no length has none.
  Contour reversed;
  for (auto it = circle.segments.rbegin(); it != circle.segments.rend(); ++it)
    reversed.segments.push_back(std::get<Cubic>(*it).reversed());
  reversed.nodes.assign(4, NodeFlags{});
  EXPECT_NEAR(thickness(reversed), thickness(circle), 1e-9);
  Contour point;
  point.segments = {Line{{{5, 5}, {5, 5}}}};
  point.nodes.assign(1, NodeFlags{});
  EXPECT_EQ(thickness(point), 0.0);
}

}  // namespace
}  // namespace gf
