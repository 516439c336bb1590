#include "fair/corner_end_lobes.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include "fair/cubic_change.hpp"
#include "geom/critical_points.hpp"
#include "geom/curvature.hpp"
#include "geom/g2_hermite.hpp"
#include "geom/outline_move.hpp"

namespace gf {

namespace {

constexpr double sample_spacing = 2.0;  // units, at most, between the points a move is measured on
constexpr int tangent_steps = 30;       // corner tangents tried each way, up to most_turn_deg
constexpr int handle_steps = 24;        // corner handles tried: 1/24 … 24/24 of the chord
constexpr double flat_bend = 1e-9;      // κ·chord below which an end is flat (an inflection node's)
constexpr double shortest_piece = 8.0;  // units: the writeback's shortest span on the grid
constexpr double end_parameter = 1e-6;  // an inflection this near a cubic's end (in t) is the end's
constexpr double end_share = 0.005;     // of a cubic's length: an H/V extremum this near an end needs no node

// The cubic's inflections off its ends: a lobe cut at its inflection node ends there with
// κ = 0, which the roots may place a rounding error inside.
std::vector<double> inner_inflections(const Cubic& c) {
  std::vector<double> out;
  for (const double t : inflections(c))
    if (std::min(t, 1.0 - t) > end_parameter) out.push_back(t);
  return out;
}

// The way a cubic bends at t (1 left, −1 right), or 0 where it is straight there.
int bend_at(const Cubic& c, double t) {
  const std::optional<double> k = curvature(derivatives_at(c, t));
  return !k || *k == 0.0 ? 0 : (*k > 0.0 ? 1 : -1);
}

// The way a cubic bends, or 0 where it bends both ways or not at all.
int bend_of(const Cubic& c) { return inner_inflections(c).empty() ? bend_at(c, 0.5) : 0; }

// The cubic's H/V extrema that need a node: those farther along it from both ends than
// end_share of its length (the check's margin is twice that; half is left for rounding).
std::vector<AxisExtremum> inner_extrema(const Cubic& c) { return axis_extrema_inside(c, end_share); }

// Whether cutting the cubic at its inner extrema leaves no piece shorter than shortest_piece:
// shorter, the grid can only make it straight or fold it.
bool pieces_long_enough(const Cubic& c) {
  Vec2 last = c.p[0];
  for (const AxisExtremum& e : inner_extrema(c)) {
    const Vec2 q = c.point_at(e.t);
    if (distance(last, q) < shortest_piece) return false;
    last = q;
  }
  return last == c.p[0] || distance(last, c.p[3]) >= shortest_piece;
}

struct Replacement {
  Cubic cubic;
  double move;
};

// The cubic from the corner c, leaving it within most_turn_deg of `drawn`, to `far` (its
// tangent and curvature met) that bends `way`, its H/V extrema far enough apart to be nodes,
// and moves the outline least from `old` within `room`, curvature monotone where any such
// cubic is; none where no cubic does. `arriving`: the direction the outline arrives at the
// corner in, which it still turns from by least_corner_deg and half what it did.
std::optional<Replacement> one_way_cubic(Vec2 c, Vec2 drawn, Vec2 arriving, const HermiteEnd& far, int way,
                                         std::initializer_list<Segment> old, double room,
                                         const CornerLobeLimits& limits) {
  if (way == 0 || far.curvature * way < 0.0) return std::nullopt;
  const double corner = turning_angle(arriving, drawn);
  const double least_corner = std::max(radians(limits.least_corner_deg), 0.5 * std::abs(corner));
  if (std::abs(corner) < least_corner) return std::nullopt;
  const double chord = distance(c, far.point);
  std::optional<Replacement> best, best_monotone;
  for (int k = -tangent_steps; k <= tangent_steps; ++k) {
    const Vec2 t0 = direction_of(angle_of(drawn) + radians(limits.most_turn_deg) * k / tangent_steps);
    const double turned = turning_angle(arriving, t0);
    // Still a corner the same way round, and the chord on the side the cubic bends to.
    if (turned * corner <= 0.0 || std::abs(turned) < least_corner || way * cross(t0, far.point - c) <= 0.0) continue;
    for (int j = 1; j <= handle_steps; ++j) {
      // A flat end (an inflection node's) fixes the corner's handle and leaves its own to choose.
      const double handle = chord * j / handle_steps;
      const std::optional<Cubic> cubic =
          far.curvature == 0.0 ? g2_hermite_cubic_from_flat_end({c, t0, 0.0}, far, SegmentEnd::start, handle)
                               : g2_hermite_cubic_with_free_end({c, t0, 0.0}, far, SegmentEnd::start, handle);
      if (!cubic || bend_of(*cubic) != way || !pieces_long_enough(*cubic) || crowds_a_node(*cubic)) continue;
      // Curvature monotone where any candidate has it: a peak inside is an extremum more.
      const bool monotone = critical_points(*cubic).curvature_extrema.empty();
      std::optional<Replacement>& slot = monotone ? best_monotone : best;
      const double limit = slot ? std::min(slot->move, room) : room;
      const double move = outline_move(old, {*cubic}, sample_spacing, limit);
      if (move < limit) slot = Replacement{*cubic, move};
    }
  }
  return best_monotone ? best_monotone : best;
}

// Where the cubic ends: its point, tangent and curvature (0 where it ends flat, as at an
// inflection node or into a line, to rounding error); none where it has no direction there.
std::optional<HermiteEnd> end_frame(const Cubic& c) {
  const std::optional<double> k = end_curvature(c, SegmentEnd::end).curvature;
  const std::optional<Vec2> t = end_tangent(c, SegmentEnd::end);
  if (!k || !t) return std::nullopt;
  const bool flat = std::abs(*k) * distance(c.p[0], c.p[3]) < flat_bend;
  return HermiteEnd{c.p[3], *t, flat ? 0.0 : *k};
}

// The replacement's pieces: cut at its H/V extrema, where the outline keeps a node (snapped
// exactly onto the axis there).
std::vector<OutlineNode> extremum_nodes(const Cubic& cubic, std::vector<Cubic>& pieces) {
  std::vector<OutlineNode> out;
  Cubic rest = cubic;
  double done = 0.0;
  for (const AxisExtremum& e : inner_extrema(cubic)) {
    const auto halves = rest.split((e.t - done) / (1.0 - done));
    done = e.t;
    pieces.push_back(halves[0]);
    rest = halves[1];
    OutlineNode node{halves[1].p[0], halves[0].p[2], halves[1].p[1], true, std::nullopt};
    const Vec2 d = halves[1].p[1] - halves[1].p[0];
    if (e.tangent == Axis::horizontal) {
      node.in_handle->y = node.out_handle->y = node.point.y;
      node.grid_step = Vec2{d.x > 0.0 ? 1.0 : -1.0, 0.0};
    } else {
      node.in_handle->x = node.out_handle->x = node.point.x;
      node.grid_step = Vec2{0.0, d.y > 0.0 ? 1.0 : -1.0};
    }
    out.push_back(node);
  }
  pieces.push_back(rest);
  return out;
}

// The corner at node 0 leaves along `r` up to node `far`: the nodes between replaced by the
// replacement's extremum nodes, each of its pieces left `left` of the tolerance.
void put_in(std::vector<OutlineNode>& nodes, std::vector<double>& allowance, std::size_t far, const Replacement& r,
            double left) {
  std::vector<Cubic> pieces;
  const std::vector<OutlineNode> inner = extremum_nodes(r.cubic, pieces);
  nodes.front().out_handle = pieces.front().p[1];
  nodes[far].in_handle = pieces.back().p[2];
  nodes.erase(nodes.begin() + 1, nodes.begin() + static_cast<std::ptrdiff_t>(far));
  nodes.insert(nodes.begin() + 1, inner.begin(), inner.end());
  allowance.erase(allowance.begin(), allowance.begin() + static_cast<std::ptrdiff_t>(far));
  allowance.insert(allowance.begin(), pieces.size(), left);
}

// The way the cubic bends after its only inflection, or 0 where it has none or more.
int bend_after_inflection(const Cubic& c) {
  const std::vector<double> roots = inner_inflections(c);
  return roots.size() == 1 ? bend_at(c, 0.5 * (roots[0] + 1.0)) : 0;
}

// The first curve after the line that starts at node k (nodes[k] has no out-handle): the cubic
// from the line's far node, or none where a corner or another line comes first.
std::optional<Cubic> curve_after_line(const std::vector<OutlineNode>& nodes, std::size_t k) {
  const std::size_t far = (k + 1) % nodes.size();
  const OutlineNode& e = nodes[far];
  if (!e.smooth || !e.out_handle || !nodes[(far + 1) % nodes.size()].in_handle) return std::nullopt;
  return outline_cubic(nodes, far);
}

// A lobe from the corner at node 0 into a line (node 1 starts it) that the curve beyond the
// line bends away from: no cubic from the corner can meet the line there bending the other way
// (its end and end tangent are the line's), so the corner moves onto the line's extension and
// the line runs from it, within the allowance: the corner's arriving segment follows it (a line
// from a corner, or a cubic whose last handle moves with it). Dropped.
bool straighten_into_line(std::vector<OutlineNode>& nodes, std::vector<double>& allowance,
                          const CornerLobeLimits& limits) {
  const std::size_t last = nodes.size() - 1;
  OutlineNode &corner = nodes[0], &join = nodes[1];
  if (corner.smooth || !corner.out_handle || !join.in_handle || join.out_handle || !join.smooth) return false;
  const Cubic lobe = outline_cubic(nodes, 0);
  const std::optional<Cubic> beyond = curve_after_line(nodes, 1);
  const int way = beyond ? bend_of(*beyond) : 0;
  if (way == 0 || bend_at(lobe, 0.75) != -way) return false;
  const Vec2 e = nodes[2].point, along = (e - join.point) / norm(e - join.point);
  const Vec2 moved = join.point + along * dot(corner.point - join.point, along);
  if (dot(e - moved, along) <= 0.0) return false;
  // The segment arriving at the corner, moved with it.
  const OutlineNode& before = nodes[last];
  const bool arriving_cubic = corner.in_handle.has_value();
  if (!arriving_cubic && before.smooth) return false;
  const Segment was = arriving_cubic ? Segment{outline_cubic(nodes, last)} : Segment{Line{{before.point, corner.point}}};
  const Vec2 shift = moved - corner.point;
  const Segment now = arriving_cubic ? Segment{Cubic{{before.point, *before.out_handle, *corner.in_handle + shift, moved}}}
                                     : Segment{Line{{before.point, moved}}};
  // A cubic moved so must keep its shape: no H/V extremum or inflection it did not have.
  if (arriving_cubic) {
    const Cubic& c = std::get<Cubic>(now);
    const Cubic& c0 = std::get<Cubic>(was);
    if (inner_extrema(c).size() > inner_extrema(c0).size() || inner_inflections(c).size() > inner_inflections(c0).size())
      return false;
  }
  const std::optional<Vec2> arrives = end_tangent(now, SegmentEnd::end);
  const double drawn = turning_angle(arriving_direction(nodes, 0), leaving_direction(nodes, 0));
  if (!arrives) return false;
  const double turned = turning_angle(*arrives, along);
  if (turned * drawn <= 0.0 || std::abs(turned) < std::max(radians(limits.least_corner_deg), 0.5 * std::abs(drawn)))
    return false;
  const double room = std::min({allowance[last], allowance[0], allowance[1]});
  const double move = outline_move({was, lobe, Line{{join.point, e}}}, {now, Line{{moved, e}}}, sample_spacing, room);
  if (move >= room) return false;
  if (arriving_cubic) corner.in_handle = *corner.in_handle + shift;
  corner.point = moved;
  corner.out_handle.reset();
  nodes.erase(nodes.begin() + 1);
  allowance.erase(allowance.begin() + 1);
  allowance[0] = allowance.back() = room - move;
  return true;
}

// The lobe after the corner at node 0, if there is one to drop: dropped. The lobe bends
// against the way the outline goes on, and ends inside the first cubic, at its end, or inside
// the second; the cubics up to there become one, ending as the last of them ends (so what
// follows meets it as before).
bool drop_after_corner(std::vector<OutlineNode>& nodes, std::vector<double>& allowance,
                       const CornerLobeLimits& limits) {
  if (straighten_into_line(nodes, allowance, limits)) return true;
  if (nodes[0].smooth || !nodes[0].out_handle || !nodes[1].in_handle) return false;
  const Cubic first = outline_cubic(nodes, 0);
  const std::optional<Vec2> drawn = end_tangent(first, SegmentEnd::start);
  if (!drawn) return false;
  const Vec2 arriving = arriving_direction(nodes, 0);
  // The lobe ends inside the first cubic.
  if (const int way = bend_after_inflection(first); way != 0) {
    const std::optional<HermiteEnd> far = end_frame(first);
    const auto r = far ? one_way_cubic(first.p[0], *drawn, arriving, *far, way, {first}, allowance[0], limits)
                       : std::nullopt;
    if (r) put_in(nodes, allowance, 1, *r, allowance[0] - r->move);
    return r.has_value();
  }
  // The lobe is the first cubic and ends at its end or inside the second.
  if (!nodes[1].smooth || !nodes[1].out_handle || !nodes[2].in_handle) return false;
  const Cubic second = outline_cubic(nodes, 1);
  const int lobe = bend_of(first);
  const int way = lobe != 0 && (bend_of(second) == -lobe || bend_after_inflection(second) == -lobe) ? -lobe : 0;
  const std::optional<HermiteEnd> far = end_frame(second);
  if (way == 0 || !far) return false;
  const double room = std::min(allowance[0], allowance[1]);
  const auto r = one_way_cubic(first.p[0], *drawn, arriving, *far, way, {first, second}, room, limits);
  if (r) put_in(nodes, allowance, 2, *r, room - r->move);
  return r.has_value();
}

// The pass one way round the closed outline: each node in turn brought to the front.
int drop_after_corners(std::vector<OutlineNode>& nodes, std::vector<double>& allowance,
                       const CornerLobeLimits& limits) {
  int dropped = 0;
  const std::size_t visits = nodes.size();
  for (std::size_t v = 0; v < visits && nodes.size() >= 4; ++v) {
    dropped += drop_after_corner(nodes, allowance, limits);
    std::rotate(nodes.begin(), nodes.begin() + 1, nodes.end());
    std::rotate(allowance.begin(), allowance.begin() + 1, allowance.end());
  }
  return dropped;
}

// The outline read the other way round: segment j joins nodes j and j + 1 both ways.
void reverse_outline(std::vector<OutlineNode>& nodes, std::vector<double>& allowance) {
  const std::size_t n = nodes.size();
  std::reverse(nodes.begin(), nodes.end());
  for (OutlineNode& q : nodes) {
    std::swap(q.in_handle, q.out_handle);
    if (q.grid_step) q.grid_step = -*q.grid_step;
  }
  std::vector<double> reversed(allowance.size());
  for (std::size_t j = 0; j < reversed.size(); ++j) reversed[j] = allowance[(2 * n - 2 - j) % n];
  allowance = std::move(reversed);
}

}  // namespace

int drop_corner_end_lobes(std::vector<OutlineNode>& nodes, bool closed, std::vector<double>& allowance,
                          const CornerLobeLimits& limits) {
  if (!closed || allowance.size() != nodes.size() || nodes.empty()) return 0;
  const Vec2 start = nodes.front().point;
  int dropped = drop_after_corners(nodes, allowance, limits);
  reverse_outline(nodes, allowance);
  dropped += drop_after_corners(nodes, allowance, limits);
  reverse_outline(nodes, allowance);
  // The passes leave the outline rotated: it starts again at the node nearest where it did.
  const auto first = std::min_element(nodes.begin(), nodes.end(), [&](const OutlineNode& a, const OutlineNode& b) {
    return distance(a.point, start) < distance(b.point, start);
  });
  const auto k = first - nodes.begin();
  std::rotate(nodes.begin(), first, nodes.end());
  std::rotate(allowance.begin(), allowance.begin() + k, allowance.end());
  return dropped;
}

}  // namespace gf
