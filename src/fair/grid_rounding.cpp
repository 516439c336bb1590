#include "fair/grid_rounding.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <span>

#include "fair/contour_plan.hpp"
#include "fair/line_rounding.hpp"
#include "geom/curvature.hpp"
#include "geom/g2_hermite.hpp"

namespace gf {

namespace {

// A corner's handle on the grid: its nearest grid point, or, where that is the node's own (a
// handle under about half a unit), the node's grid neighbour nearest its direction. A handle
// on its node leaves the cubic no direction there and a cusp of unbounded curvature (EB
// Garamond's t: a 0.4-unit corner handle on a 2.9-unit cubic, κ·UPM 15,000).
Vec2 corner_handle_on_grid(Vec2 node, Vec2 handle, Vec2 grid_node) {
  const Vec2 nearest = nearest_grid_point(handle);
  if (nearest != grid_node || handle == node) return nearest;
  const Vec2 d = handle - node;
  Vec2 best = nearest;
  double nearest_cosine = -2.0;
  for (int dx = -1; dx <= 1; ++dx)
    for (int dy = -1; dy <= 1; ++dy) {
      const Vec2 step{double(dx), double(dy)};
      if (step == Vec2{}) continue;
      const double cosine = dot(step, d) / (norm(step) * norm(d));
      if (cosine > nearest_cosine) nearest_cosine = cosine, best = grid_node + step;
    }
  return best;
}

// A node's handles along the integer direction d: P − m_in d and P + m_out d.
struct Choice {
  Vec2 point;
  std::optional<Vec2> in, out;
  Vec2 step;  ///< the primitive direction both handles are multiples of
  double cost = 0.0;
};

// A cubic at a node, as far as the choice of the node's grid direction needs it: the
// curvature the fairing gave it where it meets the node (its sign is what counts), and its two
// control points away from the node as they stand on the grid. A direction must not bend it
// the other way there (a near-vertical node a unit off a vertical stem, rounded to (0, 1),
// turns the cubic from the stem into an S).
struct NodeSide {
  double curvature;
  Vec2 far_node, far_handle;
};

// None where rounding decides the sign whatever the direction: κ = (2/3) h / a² at a cubic's
// end (h: the far handle's distance from the tangent, a: the near handle's length), and a
// quarter unit of h gives 1 / (6 a²) (measured: half a unit lost Inter's b).
std::optional<NodeSide> node_side(const Cubic& faired, SegmentEnd end, Vec2 far_node, Vec2 far_handle, double flat) {
  const double k = node_curvature(faired, end);
  const double a = end == SegmentEnd::start ? distance(faired.p[0], faired.p[1]) : distance(faired.p[2], faired.p[3]);
  if (std::abs(k) <= std::max(flat, 1.0 / (6.0 * a * a))) return std::nullopt;
  return NodeSide{k, far_node, far_handle};
}

// Both cubics at a node, where their bend is to be kept.
struct NodeSides {
  std::optional<NodeSide> before, after;

  bool kept_by(const Choice& c) const {
    return (!before || bends_as_faired(*before, Cubic{{before->far_node, before->far_handle, *c.in, c.point}}, SegmentEnd::end)) &&
           (!after || bends_as_faired(*after, Cubic{{c.point, *c.out, after->far_handle, after->far_node}}, SegmentEnd::start));
  }

 private:
  static bool bends_as_faired(const NodeSide& side, const Cubic& rounded, SegmentEnd end) {
    return node_curvature(rounded, end) * side.curvature >= 0.0;
  }
};

// A flat node's direction within this of its tangent is left to the handle steps, which seat
// such a node themselves (Lato's S spine: (49, 15), 0.45° off its tangent and a far handle 2.6
// units off it; the direction chosen for its far handles, (19, 6), left κ·UPM 0.059 against
// 0.003 there, a jump the check counts).
constexpr double flat_node_turn = radians(0.5);

// A flat node's direction chosen for its far handles may be this much longer than its shorter
// handle (that handle then lengthened to a step): Open Sans's s, an inflection node with a
// 7.7-unit handle whose tangent only (8, 3) follows closely enough; FreeSerif's W took (16, 43)
// against a 21-unit handle where it might be as long as the longer, and gained two inflections.
constexpr double flat_node_handle_share = 1.25;

// How far the farthest of `far_handles` lies off the tangent line of choice c.
double farthest_off_tangent(const Choice& c, std::span<const Vec2> far_handles) {
  const Vec2 u = c.step / norm(c.step);
  double off = 0.0;
  for (const Vec2 f : far_handles) off = std::max(off, std::abs(cross(u, f - c.point)));
  return off;
}

// The exact collinear choice nearest to (point, in, out): directions d = (dx, dy) primitive,
// near the handles' direction, no longer than the shorter handle (or the longer, where none so
// short keeps the cubics bent within the kink limit); the node itself may move by
// one unit from its nearest grid point. A choice that keeps both cubics bent as they were,
// turning the tangent by less than the kink limit, beats any that does not (a wider turn is a
// visible change of its own: a brush font's half-unit handles would swing by 30–45°). The
// direction is the out-handle's, or the in-handle's where that lies on the node; none where
// both do (the cubics of no extent a segment's overrun of its arc length leaves at a chain's
// end: dkg Bold's G had four, and such a node went to the origin). With `far_handles` (a node
// flat on both sides: HandleStepLimits::flat_node_reach), nearest counts the node's move, its
// handles' moves across its tangent (their lengths are solved again) and how far the far
// handles lie off its tangent line: where they lie on it, κ = 0 on both sides.
std::optional<Choice> collinear_choice(Vec2 point, std::optional<Vec2> in, std::optional<Vec2> out,
                                       const NodeSides& sides, double chord_in, double chord_out,
                                       std::span<const Vec2> far_handles = {}) {
  Vec2 dir = out ? *out - point : Vec2{};
  if (norm(dir) == 0.0 && in) dir = point - *in;
  if (norm(dir) == 0.0) return std::nullopt;
  const double in_length = in ? norm(point - *in) : 0.0, out_length = out ? norm(*out - point) : 0.0;
  const double shortest = std::min(in ? in_length : 1e300, out ? out_length : 1e300);
  const double longest = std::max(in_length, out_length);
  const bool steep = std::abs(dir.y) > std::abs(dir.x);
  const Vec2 base = nearest_grid_point(point);
  const double most_turn = radians(kink_limit_deg);
  std::optional<Choice> best;
  bool best_keeps = false;
  // Directions no longer than the shorter handle first; where none of them keeps the cubics
  // bent within the kink limit, longer ones up to the longer handle and a quarter of the
  // shorter handle's cubic (Open Sans's g: a node 5.9° off the horizontal with a 4.6-unit
  // handle on a 110-unit cubic took (1, 0), and the cubic became an S with κ·UPM 382 at the
  // node; (10, 1) lengthens that handle to 10 units instead; DejaVu Sans's ʑ: a handle
  // lengthened to 6 units on an 11-unit cubic turned it past the vertical).
  const bool in_shorter = in && (!out || in_length <= out_length);
  const double room = 0.25 * (in_shorter ? chord_in : chord_out);
  const int short_reach = std::clamp(static_cast<int>(shortest), 1, 64);
  const int long_reach = std::clamp(static_cast<int>(std::min(longest, room)), short_reach, 64);
  const int far_reach = std::clamp(static_cast<int>(flat_node_handle_share * shortest), short_reach, long_reach);
  for (int major = 1; major <= long_reach; ++major) {
    if (major > (far_handles.empty() ? short_reach : far_reach) && best_keeps) break;
    const double minor_exact = major * (steep ? dir.x / std::abs(dir.y) : dir.y / std::abs(dir.x));
    for (int delta = -1; delta <= 1; ++delta) {
      const double minor = std::round(minor_exact) + delta;
      const double sx = steep ? minor : (dir.x < 0 ? -major : major);
      const double sy = steep ? (dir.y < 0 ? -major : major) : minor;
      const Vec2 d{sx, sy};
      if (!is_primitive(d) || dot(d, dir) <= 0.0) continue;
      const bool near = std::abs(turning_angle(dir, d)) <= most_turn;
      for (int ox = -1; ox <= 1; ++ox)
        for (int oy = -1; oy <= 1; ++oy) {
          const Vec2 p = base + Vec2{double(ox), double(oy)};
          Choice c;
          c.point = p;
          c.step = d;
          c.cost = distance(p, point);
          if (in) c.in = stepped_handle(p, d, -1.0, point, *in);
          if (out) c.out = stepped_handle(p, d, 1.0, point, *out);
          if (far_handles.empty()) {
            if (in) c.cost = std::max(c.cost, distance(*c.in, *in));
            if (out) c.cost = std::max(c.cost, distance(*c.out, *out));
          } else {
            const Vec2 t = dir / norm(dir);
            if (in) c.cost = std::max(c.cost, std::abs(cross(t, *c.in - *in)));
            if (out) c.cost = std::max(c.cost, std::abs(cross(t, *c.out - *out)));
            c.cost = std::max(c.cost, farthest_off_tangent(c, far_handles));
          }
          const bool keeps = near && sides.kept_by(c);
          if (!best || keeps > best_keeps || (keeps == best_keeps && c.cost < best->cost)) best = c, best_keeps = keeps;
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
      if (!q.smooth) return corner_handle_on_grid(q.point, exact, q.point);
      return std::nullopt;
    };
    if (const auto h = place(i, best->p[1], 1.0)) updated[i].out_handle = h;
    if (const auto h = place(j, best->p[2], -1.0)) updated[j].in_handle = h;
  }
  nodes = std::move(updated);
}

// Nodes that rounding put on one grid point, with nothing between them but a line of no length
// or a cubic whose handles stay within `collapse_reach` (dkg Bold's C: a curve over an extremum
// and the line after it, two units apart, became a loop of a unit with its ends together): one
// node, arriving as the first did and leaving as the second does, smooth only where both were
// and those directions stay exactly collinear.
constexpr double collapse_reach = 2.0;

void merge_coincident_nodes(std::vector<OutlineNode>& nodes, bool closed) {
  const auto within = [](const std::optional<Vec2>& h, Vec2 p) { return !h || distance(*h, p) <= collapse_reach; };
  for (std::size_t i = 0; nodes.size() > (closed ? 3u : 2u) && i < nodes.size();) {
    const std::size_t n = nodes.size(), j = (i + 1) % n;
    if (!closed && j == 0) break;
    const OutlineNode &a = nodes[i], &b = nodes[j];
    if (a.point != b.point || bool(a.out_handle) != bool(b.in_handle) || !within(a.out_handle, a.point) ||
        !within(b.in_handle, b.point)) {
      ++i;
      continue;
    }
    // The earlier node stays, but for the contour's first node, which stays where it is.
    const std::size_t keep = j == 0 ? j : i, drop = j == 0 ? i : j;
    OutlineNode merged = nodes[keep];
    merged.in_handle = a.in_handle, merged.out_handle = b.out_handle;
    const bool was_smooth = a.smooth && b.smooth;
    nodes[keep] = merged;
    nodes.erase(nodes.begin() + static_cast<std::ptrdiff_t>(drop));  // after keep: keep's index stands
    nodes[keep].smooth = was_smooth && exactly_collinear(arriving_direction(nodes, keep), leaving_direction(nodes, keep));
  }
}

// A cubic that the grid laid flat along the line it leaves or arrives from (every control point
// on the line, none turning back) is more of the line: the line takes it over, and its far node
// becomes a line's end, whose curve the handle steps then bring to κ = 0. The fairing's
// transition from the line, a few units before an extremum where the line leaned a degree or
// two off the axis, rounds flat once `place_lines_on_grid` stood the line on the axis, and the
// curve beyond kept its curvature at the extremum (Liberation Serif's Q, Roboto's y, Heros's j).
// Removes the node between them from the parallel arrays (`limits`' per-cubic allowances and
// band pieces made explicit first): the merged line has the smaller allowance of the two, and
// each cubic keeps its band piece.
void merge_flat_cubics_into_lines(std::vector<OutlineNode>& ideal, std::vector<OutlineNode>& rounded,
                                  std::vector<std::optional<Vec2>>& steps, HandleStepLimits& limits, bool closed) {
  std::vector<double>& allowances = limits.allowance_by_cubic;
  std::vector<std::size_t>& pieces = limits.band_piece_by_cubic;
  const std::size_t count = rounded.size();
  allowances.resize(count, limits.allowance);
  for (std::size_t i = pieces.size(); i < count; ++i) pieces.push_back(i);
  const auto on_line = [](Vec2 a, Vec2 d, Vec2 p) { return cross(d, p - a) == 0.0; };
  const auto forward = [](Vec2 d, Vec2 from, Vec2 to) { return dot(d, to - from) >= 0.0; };
  for (std::size_t i = 0; rounded.size() > (closed ? 3u : 2u) && i < rounded.size();) {
    const std::size_t n = rounded.size(), before = (i + n - 1) % n, after = (i + 1) % n;
    const OutlineNode& node = rounded[i];
    // The line arrives at node i and the cubic leaves it (`line_in`), or the cubic arrives and
    // the line leaves; `far` is the cubic's other node, `line_far` the line's.
    const bool interior = closed || (i > 0 && i + 1 < n);
    const bool line_in = !node.in_handle && node.out_handle, line_out = node.in_handle && !node.out_handle;
    if (!interior || !node.smooth || !(line_in || line_out)) {
      ++i;
      continue;
    }
    const std::size_t far = line_in ? after : before, line_far = line_in ? before : after;
    const OutlineNode& f = rounded[far];
    const std::optional<Vec2>& near_handle = line_in ? node.out_handle : node.in_handle;
    const std::optional<Vec2>& far_handle = line_in ? f.in_handle : f.out_handle;
    const Vec2 d = line_in ? node.point - rounded[line_far].point : rounded[line_far].point - node.point;
    const Vec2 a = rounded[line_far].point;
    bool flat = far_handle && f.smooth && norm(d) > 0.0;
    if (flat) {
      // Along the line in order: the line's far end, node, handles, far node (reversed when
      // the cubic comes first).
      const std::array<Vec2, 5> run = line_in ? std::array{a, node.point, *near_handle, *far_handle, f.point}
                                              : std::array{f.point, *far_handle, *near_handle, node.point, a};
      for (std::size_t k = 0; k < run.size(); ++k) flat = flat && on_line(a, d, run[k]) && (k == 0 || forward(d, run[k - 1], run[k]));
      flat = flat && dot(d, f.point - node.point) * (line_in ? 1.0 : -1.0) > 0.0;
      // The far node then a line's end: its other side leaves along the line (G1 exact).
      const std::optional<Vec2>& beyond = line_in ? f.out_handle : f.in_handle;
      if (beyond) flat = flat && exactly_collinear(d, line_in ? *beyond - f.point : f.point - *beyond);
    }
    if (!flat) {
      ++i;
      continue;
    }
    // Segments start at their first node: the merged line at node `before`, whichever came first.
    allowances[before] = std::min(allowances[before], allowances[i]);
    for (std::vector<OutlineNode>* v : {&ideal, &rounded}) {
      OutlineNode& kept = (*v)[far];
      (line_in ? kept.in_handle : kept.out_handle) = std::nullopt;
    }
    const auto at = static_cast<std::ptrdiff_t>(i);
    ideal.erase(ideal.begin() + at), rounded.erase(rounded.begin() + at), steps.erase(steps.begin() + at);
    allowances.erase(allowances.begin() + at), pieces.erase(pieces.begin() + at);
  }
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
    } else if (!src.smooth) {
      if (src.in_handle) dst.in_handle = corner_handle_on_grid(src.point, *src.in_handle, dst.point);
      if (src.out_handle) dst.out_handle = corner_handle_on_grid(src.point, *src.out_handle, dst.point);
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
    const double flat = limits.flat_curvature;
    NodeSides sides;
    if (nodes[before].out_handle)
      sides.before = node_side(outline_cubic(nodes, before), SegmentEnd::end, r[before].point, *r[before].out_handle, flat);
    if (nodes[after].in_handle)
      sides.after = node_side(outline_cubic(nodes, i), SegmentEnd::start, r[after].point, *r[after].in_handle, flat);
    const double chord_in = distance(nodes[before].point, src.point), chord_out = distance(src.point, nodes[after].point);
    std::optional<Choice> c = collinear_choice(src.point, src.in_handle, src.out_handle, sides, chord_in, chord_out);
    // A node flat on both sides whose direction turns its tangent by flat_node_turn or more and
    // leaves a far handle beyond the reach off its tangent line: the direction whose tangent
    // line passes nearest both far handles instead.
    const bool flat_node = !sides.before && !sides.after && r[before].out_handle && r[after].in_handle;
    if (c && flat_node && limits.flat_node_reach > 0.0 &&
        std::abs(turning_angle(c->step, *src.out_handle - src.point)) >= flat_node_turn) {
      const std::array<Vec2, 2> far_handles{*r[before].out_handle, *r[after].in_handle};
      if (farthest_off_tangent(*c, far_handles) > limits.flat_node_reach)
        c = collinear_choice(src.point, src.in_handle, src.out_handle, sides, chord_in, chord_out, far_handles);
    }
    if (!c) continue;  // as plainly rounded
    dst.point = c->point, dst.in_handle = c->in, dst.out_handle = c->out;
    steps[i] = c->step;
  }
  place_lines_on_grid(nodes, r, steps, closed, limits);
  std::vector<OutlineNode> ideal = nodes;
  HandleStepLimits merged_limits = limits;
  merge_flat_cubics_into_lines(ideal, r, steps, merged_limits, closed);
  resolve_handle_lengths(r, ideal, steps, closed);
  choose_handle_steps(r, ideal, steps, closed, merged_limits);
  merge_coincident_nodes(r, closed);
  return r;
}

}  // namespace gf
