// Corners that came out of the fairing turning by less than the kink limit are found at the
// faired node nearest where their pieces met, or, where rounding left a smooth node there at
// the end of a short line, at the corner across that line.
#include "fair/kinked_corners.hpp"

#include <gtest/gtest.h>

namespace gf {
namespace {

// dkg Bold's p under G3, as rounded: a curve arriving at (328, 227) 47.1° up, a 1-unit line on
// at 45° to the smooth node (329, 228), and a curve leaving along the line; closed by a curve
// back round. `arriving_deg`: the direction of the arriving curve's last handle.
Contour after_rounding(double arriving_deg) {
  const double a = arriving_deg * 3.14159265358979323846 / 180.0;
  const Vec2 corner{328, 227}, smooth_end{329, 228};
  Contour c;
  c.segments = {Cubic{{{250, 180}, {280, 190}, corner - 19.0 * Vec2{std::cos(a), std::sin(a)}, corner}},
                Line{{corner, smooth_end}}, Cubic{{{smooth_end}, {333, 232}, {345, 250}, {345, 260}}},
                Cubic{{{345, 260}, {345, 300}, {250, 300}, {250, 180}}}};
  c.nodes.assign(4, NodeFlags{});
  for (NodeFlags& f : c.nodes) f.smooth = false;
  c.nodes[2].smooth = true;
  return c;
}

TEST(KinkedCorners, ACornerBehindAShortLinesSmoothEndIsFound) {
  // The plan's corner met where the line's smooth end now is.
  const std::vector<CornerJoin> corners{{7, {329, 228}}};
  EXPECT_EQ(kinked_corners(after_rounding(47.1), corners), std::vector<std::size_t>{7});
  // Turning 4°, it is a corner.
  EXPECT_TRUE(kinked_corners(after_rounding(49.0), corners).empty());
}

TEST(KinkedCorners, ASmoothNodeAtTheEndOfALongLineIsNoCorner) {
  Contour c = after_rounding(47.1);
  // The line 14 units long: the smooth node at its end is too far from the corner (a kink of
  // 2.1°) to stand for it. At 6 units (dkg Bold's j under G3), it stands for it.
  c.segments[1] = Line{{{328, 227}, {338, 237}}};
  std::get<Cubic>(c.segments[2]).p[0] = {338, 237};
  EXPECT_TRUE(kinked_corners(c, std::vector<CornerJoin>{{7, {338, 237}}}).empty());
  c.segments[1] = Line{{{328, 227}, {332, 231}}};
  std::get<Cubic>(c.segments[2]).p[0] = {332, 231};
  EXPECT_EQ(kinked_corners(c, std::vector<CornerJoin>{{7, {332, 231}}}), std::vector<std::size_t>{7});
}

}  // namespace
}  // namespace gf
