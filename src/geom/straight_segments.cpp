#include "geom/straight_segments.hpp"

#include <cmath>
#include <optional>

namespace gf {

bool is_straight(const Cubic& c) {
  const Vec2 d = c.p[3] - c.p[0];
  const double len = norm(d);
  if (len == 0.0) return false;
  for (const Vec2 q : {c.p[1], c.p[2]})
    if (std::abs(cross(d, q - c.p[0])) > 1e-9 * len * len) return false;
  // Along the chord the cubic moves with speed 3·B(t), B the quadratic Bernstein form of the
  // steps a, b, c between its control points; B ≥ 0 on [0, 1] (it never runs back) iff a ≥ 0,
  // c ≥ 0 and b ≥ −√(ac).
  const double a = dot(d, c.p[1] - c.p[0]), b = dot(d, c.p[2] - c.p[1]), e = dot(d, c.p[3] - c.p[2]);
  return a >= 0.0 && e >= 0.0 && (b >= 0.0 || b * b <= a * e);
}

bool is_straight_segment(const Segment& s) {
  return is_line(s) || is_straight(to_cubic(s));
}

Contour with_straight_segments_as_lines(const Contour& contour) {
  Contour out = contour;
  for (Segment& s : out.segments)
    if (!is_line(s) && is_straight_segment(s)) s = Line{start_point(s), end_point(s)};
  return out;
}

namespace {

// The one segment `a` then `b` draw, where both are straight and b runs on along a's line.
std::optional<Segment> joined(const Segment& a, const Segment& b) {
  if (!is_straight_segment(a) || !is_straight_segment(b)) return std::nullopt;
  const Vec2 p = start_point(a), q = end_point(b), d = end_point(a) - p, e = q - start_point(b);
  if (!(dot(d, e) > 0.0)) return std::nullopt;
  const Vec2 chord = q - p;
  if (std::abs(cross(d, chord)) > 1e-9 * norm(d) * norm(chord)) return std::nullopt;
  if (is_line(a) || is_line(b)) return Segment{Line{p, q}};
  // Each may reach far past its ends where its other step is short, so the two outer handles
  // can run back though neither cubic does: (0, 130, 65, 100) and (100, 100.3, 99.7, 101).
  const Cubic one{p, to_cubic(a).p[1], to_cubic(b).p[2], q};
  return is_straight(one) ? Segment{one} : Segment{Line{p, q}};
}

}  // namespace

Contour with_straight_runs_joined(const Contour& contour) {
  Contour out = contour;
  // Node k joins segments k − 1 and k; a closed contour's node 0 stays.
  for (std::size_t k = 1; k < out.segments.size();) {
    const std::optional<Segment> one =
        out.nodes[k].smooth.value_or(false) ? joined(out.segments[k - 1], out.segments[k]) : std::nullopt;
    if (!one) {
      ++k;
      continue;
    }
    out.segments[k - 1] = *one;
    out.segments.erase(out.segments.begin() + static_cast<std::ptrdiff_t>(k));
    out.nodes.erase(out.nodes.begin() + static_cast<std::ptrdiff_t>(k));
  }
  return out;
}

}  // namespace gf
