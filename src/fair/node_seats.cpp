#include "fair/node_seats.hpp"

#include <array>
#include <cmath>
#include <utility>

#include "fair/node_change.hpp"
#include "fair/run_steps.hpp"
#include "fair/step_costs.hpp"

namespace gf {

namespace {

constexpr double moved_inflection_cost = 1.0;  // an inflection moved off its node, in seat_flat_nodes

// How far a line join may slide back along its line (slide_line_joins), in chords of its cubic
// from where the passes found it. a–z A–Z rounded, g2-jumps at 1, 1.5, 2 and 3: Lato 7, 6, 6,
// 8; Carlito 14, 13, 12, 12; TeX Gyre Pagella 82, 78, 78, 78; Noto Serif 13, 12, 12, 12.
constexpr double slide_reach = 2.0;

// The longest side of the primitive directions a flat node may turn to (seat_flat_nodes): on a
// serif's top cupped by a unit or two, an inflection between two level extrema seats both far
// handles on its tangent line only along a direction a degree or three off the level, (16, 1)
// or longer (EB Garamond's V, W and Y, Pagella's B, D and R). a–z A–Z rounded, g2-jumps at 16,
// 32 and 64: EB Garamond 83, 81, 81; Pagella 26, 23, 22; Comic Neue 36, 36, 35; EB Garamond's
// time 15, 15 and 20 s.
constexpr int flat_node_longest = 32;

// The handle of `node` (an out-handle when sign is +1) exactly on the line through p along d,
// on the side of p that handle faces (behind p for an out-handle of the node before it): for a
// smooth node a whole number m ≥ 1 of its steps from it, where the line crosses its handle line
// there; for a corner, the grid point of the line nearest where its handle is.
std::optional<Vec2> handle_on_line(const OutlineNode& node, std::optional<Vec2> step, double sign, Vec2 p, Vec2 d) {
  std::optional<Vec2> h;
  if (!node.smooth) {
    const Vec2 now = sign > 0.0 ? *node.out_handle : *node.in_handle;
    h = p + d * whole_steps(p, now, d, 1.0);
  } else if (step) {
    if (const std::optional<double> m = whole_steps_to_line(node.point, *step, sign, p, d))
      h = node.point + *step * (sign * *m);
  }
  if (h && -sign * dot(*h - p, d) <= 0.0) return std::nullopt;
  return h;
}

// Whether node i (joining cubics h and i) is to be flat on the grid: it was before rounding (an
// inflection), or rounding left one side of it flat (that cubic's far handle on the node's
// tangent line) and the other not. A curvature of κ·UPM 5 (UPM 1000) at a 5-unit handle wants
// its far handle a fifth of a unit off the tangent; whole units give 0 there, and the other
// side, its far handle a unit off, some multiple of it (EB Garamond a–z A–Z: 221 of its 486
// jumps were so).
// `rounded`: its two curvatures on the grid now (curvatures_at).
bool flat_node(const CubicJudge& judge, std::size_t h, std::size_t i, std::pair<double, double> rounded, double flat) {
  if (std::abs(judge.unrounded(h).k_end) < flat && std::abs(judge.unrounded(i).k_start) < flat) return true;
  return std::min(std::abs(rounded.first), std::abs(rounded.second)) < flat;
}

// Which neighbour of node i is a line join still jumping past the target, across a cubic from
// i: the one before (the cubic arriving at i starts on the line; that first) or the one after.
// None where neither is (a corner with a line on one side has its line join, if any, across
// that line, not across a cubic).
struct JumpingLineJoin {
  std::size_t at;  ///< the join's node
  bool before;     ///< whether it is node i's neighbour before
};

std::optional<JumpingLineJoin> jumping_line_join(const OutlineJoins& joins, std::size_t i, double flat) {
  const std::size_t n = joins.size(), h = (i + n - 1) % n, j = (i + 1) % n;
  if (joins.is_cubic(h) && joins.meets_line(h) && join_jump(joins, h, flat) > target_jump) return JumpingLineJoin{h, true};
  if (joins.is_cubic(i) && joins.meets_line(j) && join_jump(joins, j, flat) > target_jump) return JumpingLineJoin{j, false};
  return std::nullopt;
}

}  // namespace

std::vector<std::size_t> nudge_jumping_nodes(std::vector<OutlineNode>& nodes, const std::vector<OutlineNode>& ideal,
                                             std::vector<std::optional<Vec2>>& steps, const OutlineJoins& joins,
                                             std::span<const std::size_t> candidates, CubicJudge& judge, double flat) {
  std::vector<std::size_t> nudged;
  for (const std::size_t i : candidates) {
    if (!joins.joins_cubics(i) || !steps[i]) continue;
    const NodeChange change(nodes, joins, judge, flat, i);
    if (!change.needs_change()) continue;
    const OutlineNode kept = nodes[i];
    const OutlineNode& target = ideal[i];
    const std::vector<Vec2> directions = node_directions(*steps[i], target);
    OutlineNode best = kept;
    Vec2 best_step = *steps[i];
    double best_cost = change.cost();
    for (const Vec2 d : directions) {
      if (d != *steps[i] && best_cost <= 3.0 * target_jump * target_jump) break;  // turned only while still jumping
      const OutlineNode& from = d == *steps[i] ? kept : target;  // a turned node's handles as long as unrounded
      const double m_in = handle_steps_along(from, d, false), m_out = handle_steps_along(from, d, true);
      // Still on a grid point next to the nearest one, as rounding placed every node.
      for (const Vec2 p : node_places(kept.point, target.point))
        for_each_handle_pair(nodes[i], p, d, m_in, m_out, [&] {
          if (const std::optional<double> c = change.cost_under(best_cost)) best_cost = *c, best = nodes[i], best_step = d;
        });
    }
    nodes[i] = best;
    steps[i] = best_step;
    if (best != kept) nudged.push_back(i);
  }
  return nudged;
}

std::vector<std::size_t> seat_flat_nodes(std::vector<OutlineNode>& nodes, const std::vector<OutlineNode>& ideal,
                                         std::vector<std::optional<Vec2>>& steps, const OutlineJoins& joins,
                                         std::span<const std::size_t> candidates, CubicJudge& judge, double flat) {
  const std::size_t n = nodes.size();
  std::vector<std::size_t> seated;
  for (const std::size_t i : candidates) {
    const std::size_t h = (i + n - 1) % n, j = (i + 1) % n;
    if (!joins.joins_cubics(i) || !steps[i]) continue;
    const std::pair<double, double> rounded = curvatures_at(nodes, i);
    // An inflection the choices moved off the node (a flip at one side's end, no jump) is
    // seated too, weighed as a jump just over the target: its places on the grid come before
    // a hair of the other bend (each is κ = 0 from both sides).
    const CubicTraits& before = judge.traits(h, outline_cubic(nodes, h));
    const CubicTraits& after = judge.traits(i, outline_cubic(nodes, i));
    const bool moved_off = judge.inflections_at_node(h, before, i, after).moved;
    const bool jumps = relative_jump(rounded.first, rounded.second, flat) > target_jump;
    if (!(jumps || moved_off) || !flat_node(judge, h, i, rounded, flat)) continue;
    const NodeChange change(nodes, joins, judge, flat, i);
    const OutlineNode kept = nodes[i], kept_h = nodes[h], kept_j = nodes[j];
    const OutlineNode& target = ideal[i];
    double best_cost = change.cost() + (moved_off ? moved_inflection_cost : 0.0);
    std::optional<std::array<OutlineNode, 3>> best;
    std::optional<Vec2> best_step;
    for (const Vec2 d : directions_near(*target.out_handle - *target.in_handle, grid_turn, flat_node_longest))
      for (const Vec2 p : node_places(kept.point, target.point)) {
        const std::optional<Vec2> far_in = handle_on_line(kept_h, steps[h], 1.0, p, d);
        const std::optional<Vec2> far_out = handle_on_line(kept_j, steps[j], -1.0, p, d);
        if (!far_in || !far_out) continue;
        nodes[h].out_handle = far_in, nodes[j].in_handle = far_out;
        // A corner's handle turned onto the line: not under the kink limit, or the kink pass
        // makes it smooth (EB Garamond's W: a 3.5° corner at its left leg turned to 0.6°).
        if (judge.turned_under_limit(nodes, h) || judge.turned_under_limit(nodes, j)) continue;
        const double m_in = handle_steps_along(target, d, false), m_out = handle_steps_along(target, d, true);
        for_each_handle_pair(nodes[i], p, d, m_in, m_out, [&] {
          if (const std::optional<double> c = change.cost_under(best_cost))
            best_cost = *c, best = {nodes[h], nodes[i], nodes[j]}, best_step = d;
        });
      }
    nodes[h] = kept_h, nodes[i] = kept, nodes[j] = kept_j;
    if (!best) continue;
    nodes[h] = (*best)[0], nodes[i] = (*best)[1], nodes[j] = (*best)[2];
    steps[i] = best_step;
    seated.push_back(i);
  }
  return seated;
}

std::vector<std::size_t> seat_line_joins(std::vector<OutlineNode>& nodes, const std::vector<OutlineNode>& ideal,
                                         std::vector<std::optional<Vec2>>& steps, const OutlineJoins& joins,
                                         std::span<const std::size_t> candidates, CubicJudge& judge, double flat,
                                         bool beside_lines) {
  std::vector<std::size_t> seated;
  for (const std::size_t i : candidates) {
    if (!joins.joins_cubics(i) || !steps[i]) continue;
    // The join on the line: before i (its cubic arrives at i) or after it; sign is i's handle's.
    const std::optional<JumpingLineJoin> line_join = jumping_line_join(joins, i, flat);
    if (!line_join) continue;
    const bool before = line_join->before;
    const OutlineNode& join = nodes[line_join->at];
    // The join's tangent, in the contour's direction (h → i → j).
    const Vec2 into = before ? *join.out_handle - join.point : join.point - *join.in_handle;
    const double sign = before ? -1.0 : 1.0;
    const NodeChange change(nodes, joins, judge, flat, i);
    const OutlineNode kept = nodes[i];
    const OutlineNode& target = ideal[i];
    // The far handle of the cubic on i's other side, a step or three either way along its own
    // node's direction (a corner's stays): moved across its tangent, node i changes that cubic's
    // curvature at i as much as the line join's (Lato's c: its cap's top two units down).
    const std::size_t far = before ? (i + 1) % nodes.size() : (i + nodes.size() - 1) % nodes.size();
    std::optional<Vec2>& far_handle = before ? nodes[far].in_handle : nodes[far].out_handle;
    const Vec2 kept_far = *far_handle;
    const std::vector<Vec2> fars =
        steps[far] ? handle_candidates(nodes[far], steps[far], !before) : std::vector<Vec2>{kept_far};
    double best_cost = change.cost();
    std::optional<std::pair<OutlineNode, Vec2>> best;
    std::optional<Vec2> best_step;
    // Sides up to 16: only a step that lands on the line (or beside it) is taken, not one set
    // by curvature.
    const auto line_handles = [&](Vec2 p, Vec2 d) {
      if (beside_lines) return handles_near_line(p, d, sign, join.point, into);
      const std::optional<double> m = whole_steps_to_line(p, d, sign, join.point, into);
      return m ? std::vector<Vec2>{p + d * (sign * *m)} : std::vector<Vec2>{};
    };
    for (const Vec2 d : node_directions(*steps[i], target, 16))
      for (const Vec2 p : node_places(kept.point, target.point, 2))
        for (const Vec2 on_line : line_handles(p, d)) {
          if (sign * dot(on_line - join.point, into) >= 0.0) continue;  // on i's side of the join
          const double m_other = handle_steps_along(target, d, before);
          nodes[i].point = p;
          (before ? nodes[i].in_handle : nodes[i].out_handle) = on_line;
          for (int b = -handle_reach; b <= handle_reach; ++b) {
            if (m_other + b < 1.0) continue;
            (before ? nodes[i].out_handle : nodes[i].in_handle) = p - d * (sign * (m_other + b));
            for (const Vec2 f : fars) {
              far_handle = f;
              if (const std::optional<double> c = change.cost_under(best_cost))
                best_cost = *c, best = {nodes[i], f}, best_step = d;
            }
          }
        }
    nodes[i] = best ? best->first : kept;
    far_handle = best ? best->second : kept_far;
    if (!best) continue;
    steps[i] = best_step;
    seated.push_back(i);
  }
  return seated;
}

std::vector<std::size_t> slide_line_joins(std::vector<OutlineNode>& nodes, std::span<const OutlineNode> entry,
                                          std::span<const std::optional<Vec2>> steps, const OutlineJoins& joins,
                                          CubicJudge& judge, double flat) {
  const std::size_t n = nodes.size();
  std::vector<std::size_t> slid;
  if (n < 4) return slid;
  for (std::size_t at = 0; at < n; ++at) {
    if (!joins.meets_line(at) || !steps[at]) continue;
    const bool leaves = joins.is_cubic(at);  // the cubic leaves the join, the line arrives
    const std::size_t far = leaves ? (at + 1) % n : (at + n - 1) % n;  // the cubic's other node
    // The join jumps, or the far node does where the handle's tip lies on its tangent (κ = 0
    // at that end whatever the length of the far node's own handle).
    const Vec2 tip = *(leaves ? nodes[at].out_handle : nodes[at].in_handle);
    const std::optional<Vec2> far_near = leaves ? nodes[far].in_handle : nodes[far].out_handle;
    const bool flat_far = far_near && cross(nodes[far].point - *far_near, tip - nodes[far].point) == 0.0;
    if (join_jump(joins, at, flat) <= target_jump && !(flat_far && join_jump(joins, far, flat) > target_jump)) continue;
    const std::size_t first = leaves ? at : far;                        // the cubic's first node
    const NodeChange change(nodes, joins, judge, flat, far);
    const Vec2 line_end = nodes[leaves ? (at + n - 1) % n : (at + 1) % n].point;
    const Vec2 kept = nodes[at].point, back = *steps[at] * (leaves ? -1.0 : 1.0);
    const double line_length = distance(kept, line_end);
    const Vec2 start = entry[at].point;
    const double chord = distance(start, entry[far].point);
    double best_cost = change.cost();
    // The handle's tip kept (the handle grows), or the handle slid along with the join: where
    // its tip lies on the far node's tangent (κ = 0 there whatever that node's handle), only
    // a handle starting farther back lies across it (Gentium Plus's w: a 17-unit curve from a
    // (3, 11) line to an x-extremum, its one-step handle's tip on the extremum's vertical).
    std::optional<Vec2>& handle = leaves ? nodes[at].out_handle : nodes[at].in_handle;
    std::optional<OutlineNode> best;
    for (int k = 1; k <= 3; ++k) {
      const Vec2 p = kept + back * static_cast<double>(k);
      if (distance(p, start) > slide_reach * chord || distance(p, line_end) < 0.5 * line_length ||
          dot(p - line_end, kept - line_end) <= 0.0)
        break;
      nodes[at].point = p;
      for (const Vec2 h : {tip, tip + back * static_cast<double>(k)}) {
        handle = h;
        if (const std::optional<double> c = change.cost_under(best_cost)) best_cost = *c, best = nodes[at];
      }
    }
    if (best) {
      nodes[at] = *best;
      slid.push_back(first);
    } else {
      nodes[at].point = kept, handle = tip;
    }
  }
  return slid;
}

std::vector<std::size_t> seat_line_joins_at_corners(std::vector<OutlineNode>& nodes, const std::vector<OutlineNode>& ideal,
                                                    std::span<const std::optional<Vec2>> steps, const OutlineJoins& joins,
                                                    std::vector<std::size_t>& corners, CubicJudge& judge, double flat) {
  const std::size_t n = nodes.size();
  std::vector<std::size_t> seated;
  if (n < 3) return seated;
  std::vector<std::size_t> untried;
  for (const std::size_t i : corners) {
    const std::size_t h = (i + n - 1) % n, j = (i + 1) % n;
    // The join on the line: at the start of the cubic arriving at i, or at the end of the one leaving it.
    const std::optional<JumpingLineJoin> line_join = jumping_line_join(joins, i, flat);
    if (!line_join || !steps[line_join->at]) {
      untried.push_back(i);
      continue;
    }
    const bool before = line_join->before;
    const std::size_t at = line_join->at;
    const Vec2 join = nodes[at].point, line_far = nodes[before ? (h + n - 1) % n : (j + 1) % n].point;
    const NodeChange change(nodes, joins, judge, flat, i);
    const OutlineNode kept = nodes[i];
    double best_cost = change.cost();
    std::optional<OutlineNode> best;
    std::optional<Vec2>& handle = before ? nodes[i].in_handle : nodes[i].out_handle;
    const double nearest = whole_steps(join, before ? *kept.in_handle : *kept.out_handle, *steps[at], 1.0);
    // A corner at a line is that line's end too: it stays where the line's other end is smooth,
    // whose G1 a turned line would break.
    const bool line_before = !joins.is_cubic(h), line_after = !joins.is_cubic(i);
    const bool held = (line_before && nodes[h].smooth) || (line_after && nodes[j].smooth);
    for (const Vec2 p : held ? std::vector<Vec2>{kept.point} : node_places(kept.point, ideal[i].point, 2))
      for (double m = nearest - 2.0; m <= nearest + 2.0; ++m) {
        const Vec2 on_line = join + *steps[at] * m;
        if (dot(on_line - join, line_far - join) >= 0.0) continue;  // on the cubic's side of the join
        nodes[i].point = p;
        handle = on_line;
        if (turns_less_than_it_did(nodes, ideal, joins.closed, i)) continue;
        if (const std::optional<double> c = change.cost_under(best_cost)) best_cost = *c, best = nodes[i];
      }
    nodes[i] = best ? *best : kept;
    if (best) seated.push_back(i);
  }
  corners = std::move(untried);
  return seated;
}

}  // namespace gf
