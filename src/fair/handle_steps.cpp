#include "fair/handle_steps.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "fair/bracket_choice.hpp"
#include "fair/cubic_judge.hpp"
#include "fair/lone_cubic.hpp"
#include "fair/node_change.hpp"
#include "fair/node_seats.hpp"
#include "fair/outline_joins.hpp"
#include "fair/run_steps.hpp"
#include "fair/step_costs.hpp"

namespace gf {

namespace {

constexpr int max_passes = 16;  // of choosing steps and nudging nodes in turn (a corner's
                                // handle moves a unit a pass: DejaVu's Q tail took 9)

// The handles node + sign·m·step at the whole counts m either side of `steps` (one where it is
// whole), none under one step.
std::vector<Vec2> whole_steps_around(Vec2 node, Vec2 step, double sign, double steps) {
  std::vector<Vec2> handles;
  for (const double whole : {std::floor(steps), std::ceil(steps)})
    if (whole >= 1.0 && (handles.empty() || whole != std::floor(steps))) handles.push_back(node + step * (sign * whole));
  return handles;
}

// CubicJudge::turns_too_often at node i of the outline as it stands.
bool turns_too_often(const std::vector<OutlineNode>& nodes, const OutlineJoins& joins, CubicJudge& judge, std::size_t i) {
  if (!judge.node_turns() || !joins.joins_cubics(i)) return false;
  const std::size_t h = (i + nodes.size() - 1) % nodes.size();
  return judge.turns_too_often(h, judge.traits(h, outline_cubic(nodes, h)), i, judge.traits(i, outline_cubic(nodes, i)));
}

// Whether dκ/ds jumps at node i of the outline as it stands by more than the target (under
// HandleStepLimits::slope_jump_weight; never otherwise).
bool slope_jumps(const std::vector<OutlineNode>& nodes, const OutlineJoins& joins, CubicJudge& judge, std::size_t i) {
  if (!judge.match_slopes() || !joins.joins_cubics(i)) return false;
  const std::size_t h = (i + nodes.size() - 1) % nodes.size();
  return judge.slope_cost(judge.traits(h, outline_cubic(nodes, h)), judge.traits(i, outline_cubic(nodes, i))) > 0.0;
}

// Where a run still jumps once the passes end, or turns where it should not (turns_too_often):
// each node at a jump, or next to one (unless `only_at_jumps`: then only the far node of a
// line join that jumps, and only where its handle lands on the line), or turning so, moved to
// the grid points next to it and turned to the primitive directions near its tangent (its
// handles as many steps long as they were), with the handles of the cubics around it chosen
// again for each place (choose_window), so that a move which needs its neighbours' handles to
// follow is seen at its worth. The cheapest stands. Returns whether any node moved.
bool polish_jumping_run(std::vector<OutlineNode>& nodes, const std::vector<OutlineNode>& ideal,
                        std::vector<std::optional<Vec2>>& steps, const OutlineJoins& joins,
                        std::span<const std::size_t> cubics, bool cycle, CubicJudge& judge, double flat,
                        bool only_at_jumps) {
  bool moved = false;
  const std::size_t n = nodes.size();
  for (std::size_t q = 0; q < cubics.size(); ++q) {
    const std::size_t i = cubics[q];
    if (!joins.joins_cubics(i) || !steps[i]) continue;
    // Beside a jump; when `only_at_jumps`, only beside a line join that jumps, and then only to
    // where its handle lands on the line (the join itself, κ = 0 wanted where the curve leaves
    // the line, is no node to move: its far node is).
    const std::size_t next = (i + 1) % n, prev = (i + n - 1) % n;
    const bool next_jumps = join_jump(joins, next, flat) > target_jump, prev_jumps = join_jump(joins, prev, flat) > target_jump;
    const bool beside = !only_at_jumps && (next_jumps || prev_jumps);
    std::optional<std::size_t> line_join;
    if (only_at_jumps && next_jumps && joins.meets_line(next) && steps[next]) line_join = next;
    if (only_at_jumps && prev_jumps && joins.meets_line(prev) && steps[prev]) line_join = prev;
    const bool own = join_jump(joins, i, flat) > target_jump || turns_too_often(nodes, joins, judge, i) ||
                     slope_jumps(nodes, joins, judge, i);
    if (!own && !beside && !line_join) continue;
    const bool only_on_line = !own && !beside;
    const RunWindow window = window_around(cubics, cycle, q);
    const RunSteps now = choose_window(nodes, steps, joins, window, judge, flat, i);
    double best_cost = now.best.cost;
    const OutlineNode kept = nodes[i];
    const Vec2 kept_step = *steps[i];
    OutlineNode best = kept;
    Vec2 best_step = kept_step;
    std::optional<RunSteps> best_window;
    for (const Vec2 d : node_directions(kept_step, ideal[i])) {
      // Turned only while its own direction leaves a jump in the window (each costs at least 1).
      if (d != kept_step && best_cost < 1.0) break;
      const OutlineNode& from = d == kept_step ? kept : ideal[i];
      const double m_in = handle_steps_along(from, d, false), m_out = handle_steps_along(from, d, true);
      // Under G3, two units: dκ/ds at a cubic's end moves by tens of per cent a unit, and the
      // places a unit off left DejaVu Sans's median jump at 0.076 (0.049 with two, for 2.3 times
      // the time of a–z A–Z).
      std::vector<Vec2> places = node_places(kept.point, ideal[i].point, judge.match_slopes() ? 2 : 1);
      // Along its own direction by a step longer than a unit: both handles' tips can stay, and
      // with them a far handle seated on a line (TeX Gyre Heros's S).
      if (d == kept_step && std::max(std::abs(d.x), std::abs(d.y)) > 1.0)
        for (const double sign : {-1.0, 1.0}) places.push_back(kept.point + d * sign);
      for (const Vec2 p : places) {
        if (p == kept.point && d == kept_step) continue;
        // Its handle towards the join (+1 after the node) landing on the line.
        if (only_on_line &&
            !whole_steps_to_line(p, d, *line_join == next ? 1.0 : -1.0, nodes[*line_join].point, *steps[*line_join]))
          continue;
        nodes[i].point = p;
        nodes[i].in_handle = p - d * m_in;
        nodes[i].out_handle = p + d * m_out;
        steps[i] = d;
        RunSteps tried = choose_window(nodes, steps, joins, window, judge, flat, i, &now);
        if (tried.best.cost < best_cost)
          best_cost = tried.best.cost, best = nodes[i], best_step = d, best_window = std::move(tried);
      }
    }
    nodes[i] = best;
    steps[i] = best_step;
    if (!best_window) continue;
    moved = true;
    apply_steps(nodes, *best_window);
  }
  return moved;
}

}  // namespace

std::optional<double> steps_to_line(Vec2 node, Vec2 step, double sign, Vec2 line_point, Vec2 line_dir) {
  const double across = sign * cross(line_dir, step);
  if (across == 0.0) return std::nullopt;
  return -cross(line_dir, node - line_point) / across;
}

std::optional<double> whole_steps_to_line(Vec2 node, Vec2 step, double sign, Vec2 line_point, Vec2 line_dir) {
  const std::optional<double> m = steps_to_line(node, step, sign, line_point, line_dir);
  if (!m || *m < 1.0 || *m != std::round(*m)) return std::nullopt;
  return m;
}

std::vector<Vec2> handles_near_line(Vec2 node, Vec2 step, double sign, Vec2 line_point, Vec2 line_dir) {
  const std::optional<double> m = steps_to_line(node, step, sign, line_point, line_dir);
  return m ? whole_steps_around(node, step, sign, *m) : std::vector<Vec2>{};
}

std::vector<Vec2> handles_for_curvature(Vec2 node, Vec2 step, bool out, Vec2 far, Vec2 other_end, double target) {
  const double length = norm(step);
  const Vec2 t = step / length;
  const double d = out ? cross(t, far - node) : cross(node - far, t);
  if (d * target <= 0.0) return {};
  const double m = std::sqrt(2.0 * d / (3.0 * target)) / length;
  if (m * length > 2.0 * distance(node, other_end)) return {};
  return whole_steps_around(node, step, out ? 1.0 : -1.0, m);
}

std::vector<Vec2> far_handles_for_curvature(Vec2 node, Vec2 step, bool out, Vec2 near, Vec2 far_node, Vec2 far_step,
                                            double target) {
  const double h = distance(near, node);
  if (h == 0.0 || target == 0.0) return {};
  const Vec2 t = step / norm(step);
  // d(m) = d0 + m·d1, the far handle far_node ∓ m·far_step (an in-handle when `out`).
  const double far_sign = out ? -1.0 : 1.0;
  const auto offset = [&](Vec2 far) { return out ? cross(t, far - node) : cross(node - far, t); };
  const double d0 = offset(far_node), d1 = offset(far_node + far_step * far_sign) - d0;
  if (d1 == 0.0) return {};
  const double m = (1.5 * target * h * h - d0) / d1;
  if (m * norm(far_step) > 2.0 * distance(node, far_node)) return {};
  return whole_steps_around(far_node, far_step, far_sign, m);
}

void choose_handle_steps(std::vector<OutlineNode>& nodes, const std::vector<OutlineNode>& ideal,
                         std::span<const std::optional<Vec2>> grid_steps, bool closed, const HandleStepLimits& limits) {
  // The grid steps as rounding left them; a node turned or seated here takes a new one.
  const std::size_t n = nodes.size();
  if (n < 2) return;
  const OutlineJoins joins{nodes, closed};

  // The runs of cubics joined at smooth nodes, each by the nodes starting its cubics.
  std::vector<std::vector<std::size_t>> runs;
  for (std::size_t i = 0; i < n; ++i)
    if (joins.is_cubic(i) && !joins.joins_cubics(i)) runs.push_back({i});
  const bool cycle = runs.empty();
  if (cycle && joins.is_cubic(0)) runs.push_back({0});
  if (runs.empty()) return;
  std::vector<std::size_t> run_of(n, runs.size());  // the run each node inside one belongs to
  if (cycle) run_of[0] = 0;                          // a run that closes on itself: its seam too
  std::vector<std::size_t> run_starting_at(n, runs.size());
  for (std::size_t r = 0; r < runs.size(); ++r) {
    run_starting_at[runs[r].front()] = r;
    for (std::size_t j = (runs[r].back() + 1) % n; joins.joins_cubics(j) && j != runs[r].front(); j = (j + 1) % n) {
      runs[r].push_back(j);
      run_of[j] = r;
    }
  }
  // The corners at a cubic, where a run starts or ends (seat_line_joins_at_corners).
  std::vector<std::size_t> corners;
  for (std::size_t i = 0; i < n; ++i)
    if (!nodes[i].smooth && joins.interior(i) && (joins.is_cubic(i) || joins.is_cubic((i + n - 1) % n))) corners.push_back(i);

  // A nudged node changes the curvature its neighbours' handles give (its handles are their
  // far handles), and the steps chosen are the centre of the next choice's reach: a run is
  // chosen again while it or a nudge changes it and a join of it still jumps.
  // The joins of a run (the one after its last cubic too) that jump.
  const auto jumps_in = [&](std::span<const std::size_t> run) {
    int count = join_jump(joins, (run.back() + 1) % n, limits.flat_curvature) > target_jump;
    for (const std::size_t k : run) count += join_jump(joins, k, limits.flat_curvature) > target_jump;
    return count;
  };
  const auto still_jumps = [&](std::span<const std::size_t> run) { return jumps_in(run) > 0; };
  CubicJudge judge(nodes, ideal, joins, limits);
  auto turns_too_often_in = [&](std::span<const std::size_t> run) {
    return std::any_of(run.begin(), run.end(), [&](std::size_t k) { return turns_too_often(nodes, joins, judge, k); });
  };
  std::vector<std::optional<Vec2>> steps(grid_steps.begin(), grid_steps.end());
  std::vector<bool> again(runs.size(), true);
  const std::vector<OutlineNode> entry = nodes;  // as the passes find them (slide_line_joins)
  for (int pass = 0; pass < max_passes; ++pass) {
    std::vector<std::size_t> inside;
    for (std::size_t r = 0; r < runs.size(); ++r) {
      if (!again[r]) continue;
      again[r] = choose_run_steps(nodes, steps, joins, runs[r], cycle, judge, limits.flat_curvature);
      inside.insert(inside.end(), runs[r].begin() + 1, runs[r].end());
      if (cycle) inside.push_back(runs[r].front());
    }
    std::sort(inside.begin(), inside.end());
    for (const std::size_t i : nudge_jumping_nodes(nodes, ideal, steps, joins, inside, judge, limits.flat_curvature))
      again[run_of[i]] = true;
    for (const std::size_t i : seat_flat_nodes(nodes, ideal, steps, joins, inside, judge, limits.flat_curvature))
      again[run_of[i]] = true;
    for (const std::size_t i :
         seat_line_joins(nodes, ideal, steps, joins, inside, judge, limits.flat_curvature, limits.seats_beside_lines))
      again[run_of[i]] = true;
    for (const std::size_t i : slide_line_joins(nodes, entry, steps, joins, judge, limits.flat_curvature))
      for (const std::size_t r : {run_of[i], run_starting_at[i]})
        if (r < runs.size()) again[r] = true;
    for (const std::size_t i : seat_line_joins_at_corners(nodes, ideal, steps, joins, corners, judge, limits.flat_curvature))
      for (const std::size_t r : {run_starting_at[i], run_of[(i + n - 1) % n], run_starting_at[(i + n - 1) % n]})
        if (r < runs.size()) again[r] = true;
    for (std::size_t r = 0; r < runs.size(); ++r) again[r] = again[r] && still_jumps(runs[r]);
    if (std::none_of(again.begin(), again.end(), [](bool b) { return b; })) break;
  }
  // A run is polished while it jumps or turns so.
  const auto wants_polish = [&](std::span<const std::size_t> run) {
    return jumps_in(run) > 0 || turns_too_often_in(run) ||
           std::any_of(run.begin(), run.end(), [&](std::size_t k) { return slope_jumps(nodes, joins, judge, k); });
  };
  for (std::size_t r = 0; r < runs.size(); ++r)
    for (int k = 0; k < limits.polish_rounds && wants_polish(runs[r]); ++k)
      if (!polish_jumping_run(nodes, ideal, steps, joins, runs[r], cycle, judge, limits.flat_curvature,
                              limits.polish_only_at_jumps))
        break;
  // Brackets: the two cubics next to each line a run meets, where a join of theirs jumps (a
  // run of two between a line and a corner too).
  const auto jumps_at = [&](std::size_t h) {
    const std::array<std::size_t, 3> at{h, (h + 1) % n, (h + 2) % n};
    return std::any_of(at.begin(), at.end(), [&](std::size_t k) { return join_jump(joins, k, limits.flat_curvature) > target_jump; });
  };
  for (const std::vector<std::size_t>& run : runs) {
    if (cycle || run.size() < 2) continue;
    const std::size_t last = (run.back() + 1) % n;
    const bool from_line = joins.meets_line(run.front()), to_line = joins.meets_line(last);
    // A run of two is one bracket from whichever end is a line; a longer run has one at each.
    const bool pair = run.size() == 2;
    if ((from_line || (pair && to_line)) && jumps_at(run.front()))
      place_bracket(nodes, ideal, steps, joins, run.front(), judge, limits.flat_curvature);
    if (!pair && to_line && jumps_at(run[run.size() - 2]))
      place_bracket(nodes, ideal, steps, joins, run[run.size() - 2], judge, limits.flat_curvature);
  }
  // A lone cubic between two lines, where one of its joins jumps.
  for (const std::vector<std::size_t>& run : runs) {
    const std::size_t last = (run.front() + 1) % n;
    if (cycle || run.size() != 1 || !joins.meets_line(run.front()) || !joins.meets_line(last)) continue;
    if (join_jump(joins, run.front(), limits.flat_curvature) > target_jump ||
        join_jump(joins, last, limits.flat_curvature) > target_jump)
      seat_lone_cubic(nodes, ideal, steps, joins, run.front(), judge, limits.flat_curvature);
  }
}

}  // namespace gf
