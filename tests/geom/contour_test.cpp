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

}  // namespace
}  // namespace gf
