#include "fair/grid_rounding.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "fair/contour_plan.hpp"
#include "fair/line_rounding.hpp"
#include "geom/curvature.hpp"
#include "geom/g2_hermite.hpp"

namespace gf {

namespace {

// A node's handles along the integer direction d: P − m_in d and P + m_out d.
struct Choice {
  Vec2 point;
  std::optional<Vec2> in, out;
  Vec2 step;  ///< the primitive direction both handles are multiples of
  double cost = 1e300;
};

// The cubics on either side of a node as the fairing drew them, with the far ends they have on
// the grid so far: a direction for the node's handles must not bend either of them the other
// way where it meets the node (a near-vertical node a unit off a vertical stem, rounded to
// (0, 1), turns the cubic from the stem into an S).
struct NodeSides {
  std::optional<Cubic> before, after;          ///< as faired
  std::optional<Vec2> before_from, before_far;  ///< the previous node and its out-handle, rounded
  std::optional<Vec2> after_far, after_to;      ///< the next node's in-handle and that node, rounded
  double flat_curvature = 0.0;

  bool keeps_bend(const Choice& c) const {
    return (!before || same_bend(*before, Cubic{{*before_from, *before_far, *c.in, c.point}}, SegmentEnd::end)) &&
           (!after || same_bend(*after, Cubic{{c.point, *c.out, *after_far, *after_to}}, SegmentEnd::start));
  }

 private:
  bool same_bend(const Cubic& faired, const Cubic& rounded, SegmentEnd end) const {
    const double k = node_curvature(faired, end);
    // κ = (2/3) h / a² at a cubic's end (h: the far handle's distance from the tangent, a: the
    // near handle's length): where a quarter unit of h, 1 / (6 a²), bends it as much, rounding
    // decides the sign whatever the direction (measured: half a unit lost Inter's b).
    const double a = end == SegmentEnd::start ? distance(faired.p[0], faired.p[1]) : distance(faired.p[2], faired.p[3]);
    if (std::abs(k) <= std::max(flat_curvature, 1.0 / (6.0 * a * a))) return true;
    return node_curvature(rounded, end) * k >= 0.0;
  }
};

// The exact collinear choice nearest to (point, in, out): directions d = (dx, dy) primitive,
// near the handles' direction, no longer than the shorter handle; the node itself may move by
// one unit from its nearest grid point. A choice that keeps both cubics bent as they were,
// turning the tangent by less than the kink limit, beats any that does not (a wider turn is a
// visible change of its own: a brush font's half-unit handles would swing by 30–45°).
Choice collinear_choice(Vec2 point, std::optional<Vec2> in, std::optional<Vec2> out, const NodeSides& sides) {
  const Vec2 dir = out ? *out - point : point - *in;
  const double shortest = std::min(in ? norm(point - *in) : 1e300, out ? norm(*out - point) : 1e300);
  const int reach = std::clamp(static_cast<int>(shortest), 1, 64);
  const bool steep = std::abs(dir.y) > std::abs(dir.x);
  const Vec2 base = nearest_grid_point(point);
  const double most_turn = kink_limit_deg * std::numbers::pi / 180.0;
  Choice best;
  bool best_keeps = false;
  for (int major = 1; major <= reach; ++major) {
    const double minor_exact = major * (steep ? dir.x / std::abs(dir.y) : dir.y / std::abs(dir.x));
    for (int delta = -1; delta <= 1; ++delta) {
      const double minor = std::round(minor_exact) + delta;
      const double sx = steep ? minor : (dir.x < 0 ? -major : major);
      const double sy = steep ? (dir.y < 0 ? -major : major) : minor;
      const Vec2 d{sx, sy};
      if (!is_primitive(d) || dot(d, dir) <= 0.0) continue;
      for (int ox = -1; ox <= 1; ++ox)
        for (int oy = -1; oy <= 1; ++oy) {
          const Vec2 p = base + Vec2{double(ox), double(oy)};
          Choice c;
          c.point = p;
          c.step = d;
          c.cost = distance(p, point);
          if (in) {
            c.in = stepped_handle(p, d, -1.0, point, *in);
            c.cost = std::max(c.cost, distance(*c.in, *in));
          }
          if (out) {
            c.out = stepped_handle(p, d, 1.0, point, *out);
            c.cost = std::max(c.cost, distance(*c.out, *out));
          }
          const bool keeps = std::abs(turning_angle(dir, d)) <= most_turn && sides.keeps_bend(c);
          if (keeps > best_keeps || (keeps == best_keeps && c.cost < best.cost)) best = c, best_keeps = keeps;
        }
    }
  }
  return best;
}

// Rounding moved the nodes and turned the handle directions onto grid vectors; for each cubic
// the handle lengths that give back the curvature the fairing had at both ends (G2 Hermite on
// the rounded ends), then rounded to whole steps along each handle's grid direction.
void resolve_handle_lengths(std::vector<OutlineNode>& nodes, const std::vector<OutlineNode>& ideal,
                            const std::vector<std::optional<Vec2>>& steps, bool closed) {
  const std::size_t n = nodes.size();
  std::vector<OutlineNode> updated = nodes;
  for (std::size_t i = 0; i < (closed ? n : n - 1); ++i) {
    const std::size_t j = (i + 1) % n;
    const OutlineNode &a = nodes[i], &b = nodes[j], &fa = ideal[i], &fb = ideal[j];
    if (!a.out_handle || !b.in_handle) continue;
    const Vec2 ta = *a.out_handle - a.point, tb = b.point - *b.in_handle;
    if (norm(ta) == 0.0 || norm(tb) == 0.0) continue;
    const Cubic ideal_cubic = outline_cubic(ideal, i);
    const double ka = node_curvature(ideal_cubic, SegmentEnd::start), kb = node_curvature(ideal_cubic, SegmentEnd::end);
    const HermiteEnd start{a.point, ta / norm(ta), ka}, end{b.point, tb / norm(tb), kb};
    const double want_a = norm(*fa.out_handle - fa.point), want_b = norm(fb.point - *fb.in_handle);
    // Only a small correction: each handle within 10 % (and 2 units) of its length.
    std::optional<Cubic> best;
    double closest = 1e300;
    for (const Cubic& c : g2_hermite_cubics(start, end)) {
      const double da = std::abs(norm(c.p[1] - c.p[0]) - want_a), db = std::abs(norm(c.p[3] - c.p[2]) - want_b);
      if (da > 0.1 * want_a + 2.0 || db > 0.1 * want_b + 2.0) continue;
      if (da + db < closest) closest = da + db, best = c;
    }
    if (!best) continue;
    // Along the grid step where the node has one (G1 stays exact); a corner's handle rounds
    // freely; a handle that must stay on a line keeps the rounding it has.
    auto place = [&](std::size_t node, Vec2 exact, double sign) -> std::optional<Vec2> {
      const OutlineNode& q = nodes[node];
      if (steps[node]) return stepped_handle(q.point, *steps[node], sign, q.point, exact);
      if (!q.smooth) return nearest_grid_point(exact);
      return std::nullopt;
    };
    if (const auto h = place(i, best->p[1], 1.0)) updated[i].out_handle = h;
    if (const auto h = place(j, best->p[2], -1.0)) updated[j].in_handle = h;
  }
  nodes = std::move(updated);
}

}  // namespace

std::vector<OutlineNode> round_to_grid(const std::vector<OutlineNode>& nodes, bool closed,
                                       const HandleStepLimits& limits) {
  std::vector<OutlineNode> r = nodes;
  const std::size_t n = nodes.size();
  auto open_end = [&](std::size_t i) { return !closed && (i == 0 || i + 1 == n); };
  std::vector<std::optional<Vec2>> steps(n);  // smooth nodes: the grid direction of their handles
  for (std::size_t i = 0; i < n; ++i) {
    const OutlineNode& src = nodes[i];
    OutlineNode& dst = r[i];
    dst.point = nearest_grid_point(src.point);
    const bool both = src.in_handle && src.out_handle;
    if (src.smooth && both && src.grid_step) {
      // Steps along the exact direction: G1 exact on the grid, lengths within half a step.
      const Vec2 d = *src.grid_step;
      dst.in_handle = stepped_handle(dst.point, d, -1.0, src.point, *src.in_handle);
      dst.out_handle = stepped_handle(dst.point, d, 1.0, src.point, *src.out_handle);
      steps[i] = d;
    } else {
      if (src.in_handle) dst.in_handle = nearest_grid_point(*src.in_handle);
      if (src.out_handle) dst.out_handle = nearest_grid_point(*src.out_handle);
    }
  }
  // Smooth nodes between two curves without a grid direction: the nearest exact collinear choice.
  for (std::size_t i = 0; i < n; ++i) {
    const OutlineNode& src = nodes[i];
    OutlineNode& dst = r[i];
    if (!src.smooth || steps[i] || open_end(i)) continue;
    if (!src.in_handle || !src.out_handle) continue;
    const std::size_t before = (i + n - 1) % n, after = (i + 1) % n;
    NodeSides sides;
    sides.flat_curvature = limits.flat_curvature;
    if ((closed || i > 0) && nodes[before].out_handle) {
      sides.before = outline_cubic(nodes, before);
      sides.before_from = r[before].point, sides.before_far = r[before].out_handle;
    }
    if ((closed || i + 1 < n) && nodes[after].in_handle) {
      sides.after = outline_cubic(nodes, i);
      sides.after_far = r[after].in_handle, sides.after_to = r[after].point;
    }
    const Choice c = collinear_choice(src.point, src.in_handle, src.out_handle, sides);
    dst.point = c.point, dst.in_handle = c.in, dst.out_handle = c.out;
    steps[i] = c.step;
  }
  place_lines_on_grid(nodes, r, steps, closed, limits);
  resolve_handle_lengths(r, nodes, steps, closed);
  choose_handle_steps(r, nodes, steps, closed, limits);
  return r;
}

}  // namespace gf
