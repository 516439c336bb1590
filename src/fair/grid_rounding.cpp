#include "fair/grid_rounding.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "geom/curvature.hpp"
#include "geom/g2_hermite.hpp"

namespace gf {

namespace {

// node + sign·m·d: the handle m ≥ 1 whole grid steps from the node on its side (sign −1 for
// an in-handle), m nearest to how far `handle` lies from `from` along d.
Vec2 stepped_handle(Vec2 node, Vec2 d, double sign, Vec2 from, Vec2 handle) {
  const double m = std::max(1.0, whole_steps(from, handle, d, sign));
  return node + d * (sign * m);
}

// A node's handles along the integer direction d: P − m_in d and P + m_out d.
struct Choice {
  Vec2 point;
  std::optional<Vec2> in, out;
  Vec2 step;  ///< the primitive direction both handles are multiples of
  double cost = 1e300;
};

// The exact collinear choice nearest to (point, in, out): directions d = (dx, dy) primitive,
// near the handles' direction, no longer than the shorter handle; the node itself may move by
// one unit from its nearest grid point.
Choice collinear_choice(Vec2 point, std::optional<Vec2> in, std::optional<Vec2> out) {
  const Vec2 dir = out ? *out - point : point - *in;
  const double shortest = std::min(in ? norm(point - *in) : 1e300, out ? norm(*out - point) : 1e300);
  const int reach = std::clamp(static_cast<int>(shortest), 1, 64);
  const bool steep = std::abs(dir.y) > std::abs(dir.x);
  const Vec2 base = nearest_grid_point(point);
  Choice best;
  for (int major = 1; major <= reach; ++major) {
    const double minor_exact = major * (steep ? dir.x / std::abs(dir.y) : dir.y / std::abs(dir.x));
    for (int delta = -1; delta <= 1; ++delta) {
      const double minor = std::round(minor_exact) + delta;
      const double sx = steep ? minor : (dir.x < 0 ? -major : major);
      const double sy = steep ? (dir.y < 0 ? -major : major) : minor;
      if (std::gcd(static_cast<long long>(std::abs(sx)), static_cast<long long>(std::abs(sy))) != 1) continue;
      const Vec2 d{sx, sy};
      if (dot(d, dir) <= 0.0) continue;
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
          if (c.cost < best.cost) best = c;
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
    const Choice c = collinear_choice(src.point, src.in_handle, src.out_handle);
    dst.point = c.point, dst.in_handle = c.in, dst.out_handle = c.out;
    steps[i] = c.step;
  }
  // Lines with a curve meeting them tangentially: the curve's handle must lie on the line, in
  // whole steps of the line's primitive direction. A diagonal line between nearest grid points
  // may have a long primitive step (DejaVu's S spine: (122, −25)), so both ends may move to a
  // neighbouring grid point where the step is short; the choice that moves least wins. An end
  // an earlier line already placed stays (moving it would turn that line off its curve's handle).
  std::vector<bool> placed(n, false);
  for (std::size_t i = 0; i < (closed ? n : n - 1); ++i) {
    const std::size_t j = (i + 1) % n;
    if (nodes[i].out_handle || nodes[j].in_handle) continue;  // not a line
    const bool at_start = nodes[i].smooth && nodes[i].in_handle && !open_end(i);
    const bool at_end = nodes[j].smooth && nodes[j].out_handle && !open_end(j);
    if (!at_start && !at_end) continue;
    const Vec2 a0 = r[i].point, b0 = r[j].point;
    // The curve meeting the line at `end` with its near handle `near` on the line: its far
    // handle (node k's out-handle when the curve arrives, its in-handle when it leaves) at the
    // whole step nearest the line. Cost: how far that handle moves, or a unit when even there
    // the curvature at the join stays visible.
    auto far_handle_cost = [&](std::size_t k, bool out, Vec2 end, Vec2 near, Vec2 d) {
      k %= n;
      const std::optional<Vec2> wanted = out ? nodes[k].out_handle : nodes[k].in_handle;
      if (!steps[k] || !wanted) return 0.0;
      double best = 1.0;
      for (const Vec2 h : handles_near_line(r[k].point, *steps[k], out ? 1.0 : -1.0, end, d)) {
        const Cubic c = out ? Cubic{r[k].point, h, near, end} : Cubic{end, near, h, r[k].point};
        const double kappa = node_curvature(c, out ? SegmentEnd::end : SegmentEnd::start);
        if (std::abs(kappa) <= 0.05 * limits.flat_curvature) best = std::min(best, 0.3 * distance(h, *wanted));
      }
      return best;
    };
    double best_cost = 1e300;
    Vec2 best_a = a0, best_b = b0, best_d;
    std::optional<Vec2> best_in, best_out;
    for (int k = 0; k < 81; ++k) {
      const Vec2 da{double(k % 3 - 1), double(k / 3 % 3 - 1)}, db{double(k / 9 % 3 - 1), double(k / 27 % 3 - 1)};
      if ((placed[i] && da != Vec2{}) || (placed[j] && db != Vec2{})) continue;
      const Vec2 a = a0 + da, b = b0 + db;
      const Vec2 along = b - a;
      const long long g = std::gcd(static_cast<long long>(std::abs(along.x)), static_cast<long long>(std::abs(along.y)));
      if (g == 0) continue;
      const Vec2 d = along / static_cast<double>(g);
      // A long step leaves whole steps too coarse to give the curve κ = 0 at the join: each
      // unit of |d| counts as a tenth of a unit moved.
      double cost = std::max(distance(a, nodes[i].point), distance(b, nodes[j].point)) + 0.1 * norm(d);
      std::optional<Vec2> in, out;
      if (at_start) {  // the curve arrives at a along d
        in = stepped_handle(a, d, -1.0, nodes[i].point, *nodes[i].in_handle);
        cost = std::max(cost, distance(*in, *nodes[i].in_handle));
      }
      if (at_end) {  // the curve leaves b along d
        out = stepped_handle(b, d, 1.0, nodes[j].point, *nodes[j].out_handle);
        cost = std::max(cost, distance(*out, *nodes[j].out_handle));
      }
      // κ = 0 at the join needs the curve's far handle on the line: prefer ends where it can be.
      if (at_start) cost += far_handle_cost(i + n - 1, true, a, *in, d);
      if (at_end) cost += far_handle_cost(j + 1, false, b, *out, d);
      if (cost < best_cost) best_cost = cost, best_a = a, best_b = b, best_d = d, best_in = in, best_out = out;
    }
    r[i].point = best_a;
    r[j].point = best_b;
    placed[i] = placed[j] = true;
    if (best_in) r[i].in_handle = best_in, steps[i] = best_d;
    if (best_out) r[j].out_handle = best_out, steps[j] = best_d;
  }
  resolve_handle_lengths(r, nodes, steps, closed);
  choose_handle_steps(r, nodes, steps, closed, limits);
  return r;
}

}  // namespace gf
