#include "fair/line_splits.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "fair/curve_line_joins.hpp"
#include "fair/kink_fillet.hpp"
#include "geom/outline_move.hpp"

namespace gf {

namespace {

constexpr double sample_spacing = 1.0;  // units, at most, between the points the move is measured on
constexpr double most_along = 1.5;      // units the curve's end may move along its line
// Units: legs of a fillet this long turn it gently enough (κ·UPM under 0.4 for a degree's turn
// at 1,000 units), and past them shorter steps count for more.
constexpr double longest_leg = 64.0;
// Of a radian per unit of leg, what a unit of step costs: ties between legs at longest_leg.
constexpr double step_weight = 1e-5;
// Units: K–F's step no longer, so that the fillet's leg on it (a whole step at least) leaves
// the stroke a line beyond it.
constexpr double longest_on_step = 2.0 * longest_leg;
// A curve split beside its line (split_curve_beside_line) at a node whose tangent runs along a
// grid direction of components up to this.
constexpr int most_cut_step = 3;

// A split: the curve's end moved to `join`, the line turned there onto `step` and on at `vertex`.
struct Split {
  Vec2 join, vertex, step;
};

// The curve's handle at the split's join, `length` long: behind the join along the step.
Vec2 handle_on_step(const Split& split, double length) { return split.join - split.step / norm(split.step) * length; }

// Whether `a` turns onto `b` the way `bend` says (+1 left) and by no more than `most` radians.
bool turns_gently(Vec2 a, Vec2 b, double bend, double most) {
  const double angle = turning_angle(a, b);
  return angle * bend > 0.0 && std::abs(angle) <= most;
}

// The grid points within `off` of the line from a along the unit direction u, from a to
// `length` along it (both ends' stretches included), visited along the line's major axis.
template <class Visit>
void grid_points_near_line(Vec2 a, Vec2 u, double length, double off, Visit&& visit) {
  const bool by_x = std::abs(u.x) >= std::abs(u.y);
  const double major_a = by_x ? a.x : a.y, minor_a = by_x ? a.y : a.x;
  const double du = by_x ? u.x : u.y, dv = by_x ? u.y : u.x;
  const double major_b = major_a + du * length, across = off / std::abs(du);
  for (double major = std::ceil(std::min(major_a, major_b)); major <= std::max(major_a, major_b); major += 1.0) {
    const double minor = minor_a + (major - major_a) * dv / du;
    for (double m = std::ceil(minor - across); m <= minor + across; m += 1.0)
      visit(by_x ? Vec2{major, m} : Vec2{m, major});
  }
}

// The best split of the line from the curve's end j to `far` for the cubic `curve` ending at j.
std::optional<Split> best_split(const Cubic& curve, Vec2 far, const LineSplitLimits& limits) {
  const Vec2 j = curve.p[3];
  const double handle = distance(curve.p[2], j), length = distance(j, far);
  if (!(handle > 0.0) || !(length > 0.0)) return std::nullopt;
  const std::optional<Vec2> rounded_step = primitive_step(nearest_grid_point(far) - nearest_grid_point(j));
  const double line_step = rounded_step ? norm(*rounded_step) : 0.0;
  if (line_step <= handle) return std::nullopt;  // the handle can take a whole step of the line
  const double bend = end_bend(curve);
  if (bend == 0.0) return std::nullopt;
  const Vec2 u = (far - j) / length, to = nearest_grid_point(far);
  const double turn = radians(limits.max_turn_deg), off = limits.max_move_units;
  // Every split the limits allow, with the least its cost can be (its legs as long as they may
  // be); then the fillets measured cheapest first, until no cost left can be lower.
  struct Candidate {
    Split split;
    double bent, most_back, most_on, steps, bound;
  };
  std::vector<Candidate> candidates;
  const Vec2 base = nearest_grid_point(j);
  grid_points_near_line(j, u, 0.5 * length, off, [&](Vec2 k) {
    const std::optional<Vec2> on = primitive_step(to - k);
    if (!on || norm(*on) >= line_step || norm(*on) > longest_on_step) return;
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy) {
        const Vec2 join = base + Vec2{double(dx), double(dy)};
        if (std::abs(cross(join - j, u)) > off || std::abs(dot(join - j, u)) > most_along) continue;
        const std::optional<Vec2> step = primitive_step(k - join);
        if (!step || norm(*step) > handle) continue;
        if (std::abs(turning_angle(u, *step)) > turn || !turns_gently(*step, *on, bend, turn)) continue;
        // The fillet at K turns most gently where its shorter leg is longest for its turn: its
        // curvature goes as the turn over that leg, up to legs of longest_leg (or one step),
        // past which the shorter steps win. Half of K–F at most: the far end may be a kink too.
        const double bent = std::abs(turning_angle(*step, *on));
        const double most_back = std::min(distance(join, k), std::max(longest_leg, norm(*step)));
        const double most_on = std::min(0.5 * distance(k, to), std::max(longest_leg, norm(*on)));
        const double steps = step_weight * (norm(*on) + norm(*step));
        const double bound = bent / std::min(most_back, most_on) + steps;
        candidates.push_back({{join, k, *step}, bent, most_back, most_on, steps, bound});
      }
  });
  std::sort(candidates.begin(), candidates.end(),
            [](const Candidate& a, const Candidate& b) { return a.bound < b.bound; });
  // How far the outline moves: the curve's end to the split's join, its handle turned onto the
  // step, the line through the vertex.
  const auto moves = [&](const Split& split) {
    Cubic moved = curve;
    moved.p[3] = split.join;
    moved.p[2] = handle_on_step(split, handle);
    return outline_move({curve, Line{{j, far}}}, {moved, Line{{split.join, split.vertex}}, Line{{split.vertex, far}}},
                        sample_spacing, off);
  };
  std::optional<Split> best;
  double best_cost = std::numeric_limits<double>::infinity();
  for (const Candidate& c : candidates) {
    if (c.bound >= best_cost) break;
    const Vec2 k = c.split.vertex;
    const std::optional<FilletLegs> legs =
        fillet_legs(Line{{c.split.join, k}}, Line{{k, to}}, c.most_back, c.most_on, off, true);
    if (!legs) continue;
    const double cost = c.bent / std::min(norm(legs->back), norm(legs->on)) + c.steps;
    if (cost < best_cost && moves(c.split) <= off) best = c.split, best_cost = cost;
  }
  return best;
}

}  // namespace

bool split_line_at(std::vector<OutlineNode>& nodes, bool closed, std::size_t k, const LineSplitLimits& limits) {
  const std::optional<CurveLineJoin> join = curve_line_join(nodes, closed, k);
  if (!join) return false;
  const std::optional<Split> s = best_split(join->curve, nodes[join->far].point, limits);
  if (!s) return false;
  OutlineNode& node = nodes[k];
  // The handle keeps its length.
  const Vec2 handle = handle_on_step(*s, distance(join->curve.p[2], join->curve.p[3]));
  node.point = s->join;
  node.pinned = true;  // rounding moving it would turn J–K's step
  (join->arrives ? node.in_handle : node.out_handle) = handle;
  node.grid_step = join->arrives ? s->step : -s->step;
  OutlineNode vertex;
  vertex.point = s->vertex;
  vertex.smooth = false;
  vertex.pinned = true;
  // After the join where the line leaves it; else before it, or after the last node where the
  // join is the first (the contour keeps its start).
  const std::size_t at = join->arrives ? k + 1 : k == 0 ? nodes.size() : k;
  nodes.insert(nodes.begin() + static_cast<std::ptrdiff_t>(at), vertex);
  return true;
}

bool split_curve_beside_line(std::vector<OutlineNode>& nodes, bool closed, std::size_t k) {
  const std::optional<CurveLineJoin> join = curve_line_join(nodes, closed, k);
  if (!join) return false;
  const Vec2 j = join->curve.p[3], far = nodes[join->far].point;
  const double step = shortest_line_step(j, far);
  if (step <= distance(join->curve.p[2], j) || 2.0 * step > distance(j, far)) return false;
  // N's direction: the shortest grid direction turned from J's tangent between a third and two
  // thirds of the way the cubic turns (the piece from J then bends the way the cubic does, on
  // the grid too); N where the tangent, turning from J, reaches it.
  const Cubic& c = join->curve;
  const auto velocity = c.hodograph();
  const Vec2 at_j = c.p[3] - c.p[2];
  const double whole = turning_angle(velocity.point_at(0.0), at_j);
  std::optional<Vec2> direction;
  double turn = 0.0;
  for (int dx = -most_cut_step; dx <= most_cut_step; ++dx)
    for (int dy = -most_cut_step; dy <= most_cut_step; ++dy) {
      const Vec2 d{double(dx), double(dy)};
      if (!is_primitive(d) || dot(d, at_j) <= 0.0) continue;
      const double a = turning_angle(d, at_j);
      if (a * whole <= 0.0 || std::abs(a) < std::abs(whole) / 3.0 || std::abs(a) > 2.0 * std::abs(whole) / 3.0) continue;
      if (!direction || norm(d) < norm(*direction)) direction = d, turn = std::abs(a);
    }
  if (!direction) return false;
  double lo = 0.0, hi = 1.0;  // turned from J's tangent by more than `turn` at lo, by less at hi
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (std::abs(turning_angle(velocity.point_at(mid), at_j)) > turn ? lo : hi) = mid;
  }
  const double t = 0.5 * (lo + hi);
  // A cubic that turns back somewhere has its tangent elsewhere than on the direction there.
  if (std::abs(turning_angle(velocity.point_at(t), *direction)) > 1e-6) return false;
  // The cubic as it ends at J: from its other node B to N, then N to J.
  const auto [b_to_n, n_to_j] = c.split(t);
  const std::size_t n = nodes.size(), other = join->arrives ? (k + n - 1) % n : (k + 1) % n;
  OutlineNode cut;
  cut.point = n_to_j.p[0];
  cut.grid_step = join->arrives ? *direction : -*direction;
  if (join->arrives) {
    nodes[other].out_handle = b_to_n.p[1];
    cut.in_handle = b_to_n.p[2], cut.out_handle = n_to_j.p[1];
    nodes[k].in_handle = n_to_j.p[2];
  } else {
    nodes[k].out_handle = n_to_j.p[2];
    cut.in_handle = n_to_j.p[1], cut.out_handle = b_to_n.p[2];
    nodes[other].in_handle = b_to_n.p[1];
  }
  // Between J and B: before J where the cubic arrives (after the last node where J is the
  // first, so that the contour keeps its start), else after it.
  const std::size_t at = join->arrives ? (k == 0 ? n : k) : k + 1;
  nodes.insert(nodes.begin() + static_cast<std::ptrdiff_t>(at), cut);
  return true;
}

}  // namespace gf
