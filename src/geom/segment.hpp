// One piece of a contour between two on-curve nodes: a line, a quadratic or a cubic Bézier.
#pragma once

#include <variant>

#include "geom/bezier.hpp"

namespace gf {

using Segment = std::variant<Line, Quad, Cubic>;

inline Vec2 start_point(const Segment& s) {
  return std::visit([](const auto& b) { return b.start(); }, s);
}
inline Vec2 end_point(const Segment& s) {
  return std::visit([](const auto& b) { return b.end(); }, s);
}
inline Vec2 point_at(const Segment& s, double t) {
  return std::visit([t](const auto& b) { return b.point_at(t); }, s);
}
/// C′(t), from the hodograph.
inline Vec2 derivative_at(const Segment& s, double t) {
  return std::visit([t](const auto& b) { return b.hodograph().point_at(t); }, s);
}
inline int degree_of(const Segment& s) {
  return std::visit([](const auto& b) { return b.degree; }, s);
}
inline bool is_line(const Segment& s) { return std::holds_alternative<Line>(s); }
/// The segment as the cubic that draws it (a line's and a quadratic's exact cubics).
inline Cubic to_cubic(const Segment& s) {
  return std::visit([](const auto& b) { return to_cubic(b); }, s);
}
inline PolynomialCurve polynomial_of(const Segment& s) {
  return std::visit([](const auto& b) { return b.polynomial(); }, s);
}
/// All points of the segment, on- and off-curve, in order.
template <typename F>
void for_each_point(const Segment& s, F&& f) {
  std::visit([&](const auto& b) { for (const Vec2& q : b.p) f(q); }, s);
}
/// The length of the control polygon: at least the segment's arc length, so points spread
/// by it along the parameter are at most that far apart on a gently parametrised curve.
inline double control_polygon_length(const Segment& s) {
  double length = 0.0;
  Vec2 last = start_point(s);
  for_each_point(s, [&](Vec2 q) { length += distance(last, q), last = q; });
  return length;
}
/// How far the control polygon turns, each bend by its size (radians): at least how far a
/// planar Bézier segment turns.
inline double control_polygon_turning(const Segment& s) {
  double turning = 0.0;
  Vec2 last_point = start_point(s), last_leg{};
  for_each_point(s, [&](Vec2 q) {
    if (q == last_point) return;
    const Vec2 leg = q - last_point;
    if (last_leg != Vec2{}) turning += std::abs(turning_angle(last_leg, leg));
    last_leg = leg, last_point = q;
  });
  return turning;
}
/// Every point the same: no length and no direction.
inline bool is_degenerate(const Segment& s) {
  bool same = true;
  const Vec2 p0 = start_point(s);
  for_each_point(s, [&](Vec2 q) { same = same && q == p0; });
  return same;
}
}  // namespace gf
