// Shapes tests build by hand: a closed contour of given segments, a closed polygon of lines,
// the usual four-cubic circle, a node of an unrounded outline, a stem with round ends (upright,
// or leaning as Comic Neue's i stem does), and DejaVu Sans Bold's u; and whether a point a test
// reads back lies on the integer grid.
#pragma once

#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

#include "fair/outline_nodes.hpp"
#include "geom/contour.hpp"

namespace gf::test {

/// Whether both coordinates of `p` are whole units.
inline bool on_grid(Vec2 p) { return p.x == std::round(p.x) && p.y == std::round(p.y); }

/// The closed contour of `segments`, in order, no node flagged.
inline Contour closed(std::vector<Segment> segments) {
  Contour c;
  c.nodes.assign(segments.size(), NodeFlags{});
  c.segments = std::move(segments);
  return c;
}

/// The usual circle of four cubics (handles (4/3)·tan(π/8) of the radius) about `centre`, its
/// first node `turned` radians round from the +x axis, anticlockwise.
inline Contour circle(Vec2 centre, double radius, double turned = 0.0) {
  const double h = (4.0 / 3.0) * std::tan(std::numbers::pi / 8.0) * radius;
  std::vector<Segment> quarters;
  for (int q = 0; q < 4; ++q) {
    const double a = turned + q * 0.5 * std::numbers::pi, b = a + 0.5 * std::numbers::pi;
    const Vec2 ua{std::cos(a), std::sin(a)}, ub{std::cos(b), std::sin(b)};
    const Vec2 p0 = centre + ua * radius, p3 = centre + ub * radius;
    quarters.push_back(Cubic{{p0, p0 + Vec2{-ua.y, ua.x} * h, p3 - Vec2{-ub.y, ub.x} * h, p3}});
  }
  return closed(std::move(quarters));
}

/// The closed contour of lines through `corners`, in order, no node flagged.
inline Contour polygon(const std::vector<Vec2>& corners) {
  Contour c;
  for (std::size_t k = 0; k < corners.size(); ++k) c.segments.push_back(Line{{corners[k], corners[(k + 1) % corners.size()]}});
  c.nodes.assign(c.segments.size(), NodeFlags{});
  return c;
}

/// A node of an unrounded outline: its handles where it has them, a corner unless smooth.
inline OutlineNode node(Vec2 point, std::optional<Vec2> in, std::optional<Vec2> out, bool smooth = true,
                        std::optional<Vec2> grid_step = std::nullopt) {
  return OutlineNode{point, in, out, smooth, grid_step};
}

/// A stem 65 units wide (1000 units per em) with semicircular ends, each drawn as two cubics
/// whose handles are 0.52 of the radius: curvature 0.028–0.034 about a mean of 0.031, and it
/// meets the lines with that curvature. Its top `lean` units right of its foot; the caps stay
/// upright, so a leaning stem meets them at kinks.
inline Contour round_ended_stem(double lean = 0.0) {
  const Vec2 up{lean, 0};
  Contour c;
  c.segments = {Cubic{{{111, -6}, {128, -6}, {143, 9}, {143, 26}}}, Line{{Vec2{143, 26}, Vec2{143, 460} + up}},
                Cubic{{Vec2{143, 460} + up, Vec2{143, 478} + up, Vec2{129, 493} + up, Vec2{111, 493} + up}},
                Cubic{{Vec2{111, 493} + up, Vec2{94, 493} + up, Vec2{78, 478} + up, Vec2{78, 460} + up}},
                Line{{Vec2{78, 460} + up, Vec2{78, 26}}}, Cubic{{{78, 26}, {78, 9}, {93, -6}, {111, -6}}}};
  c.nodes.assign(6, NodeFlags{});
  return c;
}

/// Comic Neue's i stem (1000 units per em): two lines 0.8° off the vertical, each meeting a
/// round cap tangentially.
inline Contour comic_neue_i_stem() { return round_ended_stem(6.0); }

/// DejaVu Sans Bold's u (2048 units per em) as its TrueType quadratics, implied nodes made
/// explicit: the inner stem's line (520, 1120)–(520, 1008), then a flat S two units over to
/// (518, 596), then the bowl.
inline Contour dejavu_sans_bold_u() {
  Contour c;
  c.segments = {Line{{{160, 436}, {160, 1120}}}, Line{{{160, 1120}, {520, 1120}}}, Line{{{520, 1120}, {520, 1008}}},
                Quad{{{520, 1008}, {520, 917}, {519, 779.5}}}, Quad{{{519, 779.5}, {518, 642}, {518, 596}}},
                Quad{{{518, 596}, {518, 461}, {525, 401.5}}}, Quad{{{525, 401.5}, {532, 342}, {549, 315}}},
                Quad{{{549, 315}, {571, 280}, {606.5, 261}}}, Quad{{{606.5, 261}, {642, 242}, {688, 242}}},
                Quad{{{688, 242}, {800, 242}, {864, 328}}}, Quad{{{864, 328}, {928, 414}, {928, 567}}},
                Line{{{928, 567}, {928, 1120}}}, Line{{{928, 1120}, {1286, 1120}}}, Line{{{1286, 1120}, {1286, 0}}},
                Line{{{1286, 0}, {928, 0}}}, Line{{{928, 0}, {928, 162}}}, Quad{{{928, 162}, {847, 64}, {756.5, 17.5}}},
                Quad{{{756.5, 17.5}, {666, -29}, {557, -29}}}, Quad{{{557, -29}, {363, -29}, {261.5, 90}}},
                Quad{{{261.5, 90}, {160, 209}, {160, 436}}}};
  c.nodes.assign(c.segments.size(), NodeFlags{});
  for (const std::size_t implied : {4u, 6u, 8u, 10u, 17u, 19u}) c.nodes[implied].implied = true;
  return c;
}

}  // namespace gf::test
