#include "fair/run_steps.hpp"

#include <algorithm>
#include <numeric>
#include <utility>

#include "fair/handle_steps.hpp"

namespace gf {

namespace {

// Where one handle of a cubic meeting a line may go besides: the whole steps nearest the line,
// so the cubic leaves it with the least curvature the grid allows (the rounded length is often
// several steps away from them); for a corner's handle, the grid point on the line nearest it.
std::vector<Vec2> handles_meeting_line(const OutlineNode& node, std::optional<Vec2> step, bool out,
                                       const OutlineNode& line_end, Vec2 line_dir) {
  if (step) return handles_near_line(node.point, *step, out ? 1.0 : -1.0, line_end.point, line_dir);
  if (node.smooth) return {};
  const Vec2 h = out ? *node.out_handle : *node.in_handle;
  return {line_end.point + line_dir * whole_steps(line_end.point, h, line_dir, 1.0)};
}

// Adds to `to` the handles of `more` it lacks.
void add_handles(std::vector<Vec2>& to, const std::vector<Vec2>& more) {
  for (const Vec2 h : more)
    if (std::find(to.begin(), to.end(), h) == to.end()) to.push_back(h);
}

// How the candidates of cubic i (from node i to node j) weigh on their own.
class CandidateWeights {
 public:
  CandidateWeights(const std::vector<OutlineNode>& nodes, CubicJudge& judge, std::size_t i, std::size_t j,
                   bool line_before, bool line_after, double flat)
      : nodes_(nodes), judge_(judge), i_(i), j_(j), line_before_(line_before), line_after_(line_after), flat_(flat),
        allowed_(judge.allowed(i)), ideal_(judge.unrounded(i)) {}

  /// Whether a handle turns a corner to keep (node k's) under the kink limit.
  bool turned_under_limit(std::size_t k, std::optional<Vec2> in, std::optional<Vec2> out) const {
    return judge_.turned_under_limit(nodes_, k, in, out);
  }

  /// Every state of `c` (its outs × its ins) measured and costed.
  void weigh(CubicChoices& c) const {
    c.k_start.clear(), c.k_end.clear(), c.cost.clear(), c.traits.clear();
    for (const Vec2 out : c.outs)
      for (const Vec2 in : c.ins) {
        const CubicTraits& t = judge_.weighed(i_, Cubic{nodes_[i_].point, out, in, nodes_[j_].point});
        c.k_start.push_back(t.k_start), c.k_end.push_back(t.k_end);
        c.traits.push_back(&t);
        c.cost.push_back(t.within ? cost(t, out, in) : infeasible);
      }
  }

 private:
  // A candidate within its allowance: how far it moved, and what it gains that its unrounded
  // self lacks.
  double cost(const CubicTraits& t, Vec2 out, Vec2 in) const {
    double cost = allowed_ > 0.0 ? 0.01 * (t.moved / allowed_) * (t.moved / allowed_) : 0.0;
    // A curve meeting a line tangentially meets it with κ = 0.
    if (line_before_) cost += judge_.g2_cost(relative_jump(t.k_start, 0.0, flat_));
    if (line_after_) cost += judge_.g2_cost(relative_jump(t.k_end, 0.0, flat_));
    // Where the grid allows only near zero, or a corner's handle moves, the cubic must not
    // bend the other way near its end: an inflection the unrounded cubic does not have.
    if (judge_.inflections_added(i_, t) > 0) cost += wrong_way;
    // Nor turn horizontal or vertical inside: an extremum without a node.
    if (t.extrema.all > ideal_.extrema.all) cost += wrong_way;
    // Nor carry one that sat within half a unit of its node farther off it.
    if (t.extrema.off_node > ideal_.extrema.off_node) cost += wrong_way;
    // Nor turn a corner at a line into a kink, or smooth: the kink pass then makes it smooth
    // and fairs the contour again, and the grid may give that join no G2 (Lato's S: a 4.3°
    // corner rounded straight, then κ·UPM 3.4 where its curve left the line).
    if (turned_under_limit(i_, {}, out)) cost += wrong_way;
    if (turned_under_limit(j_, in, {})) cost += wrong_way;
    // Nor fold back on itself past its chord.
    if (t.overreach > ideal_.overreach) cost += wrong_way * (1.0 + t.overreach);
    // Nor, short, loop or cusp within it.
    if (t.turning > ideal_.turning + fold_turn) cost += wrong_way;
    // Nor bend wholly the other way, gain a curvature extremum or a spike.
    return cost + shape_cost(t.shape, ideal_.shape, flat_);
  }

  const std::vector<OutlineNode>& nodes_;
  CubicJudge& judge_;
  std::size_t i_, j_;
  bool line_before_, line_after_;
  double flat_, allowed_;
  const CubicTraits& ideal_;
};

// A corner to keep that every choice turns under the kink limit, or keeps only with a bend
// the unrounded cubic lacks: the corners' handles two units either way too (Lato's Y: a 3.3°
// corner whose line line_rounding moved 2.2 units for a shorter step; the nearly straight
// cubic from it kept 3° only as an S, unless the far corner's handle moved two units). A corner's
// handle (no grid step) only: the others are as they were. Returns whether it added any.
bool widen_at_risky_corners(CubicChoices& c, const std::vector<OutlineNode>& nodes,
                            std::span<const std::optional<Vec2>> steps, const CandidateWeights& weights) {
  bool at_risk = true, lost = false;
  for (std::size_t s = 0; s < c.states() && at_risk; ++s) {
    const Vec2 out = c.outs[s / c.ins.size()], in = c.ins[s % c.ins.size()];
    at_risk = c.cost[s] >= wrong_way;
    lost = lost || weights.turned_under_limit(c.start, {}, out) || weights.turned_under_limit(c.end, in, {});
  }
  if (!at_risk || !lost) return false;
  add_handles(c.outs, handle_candidates(nodes[c.start], steps[c.start], true, 2));
  add_handles(c.ins, handle_candidates(nodes[c.end], steps[c.end], false, 2));
  return true;
}

// Where no choice gives an end at a smooth node within the target of its unrounded curvature,
// the handle lengths aimed at it (handles_for_curvature), against every place of the far
// handle, and, where the far end meets a line, the far handle's (far_handles_for_curvature):
// only there, as they multiply the choices. Returns whether it added any.
bool aim_at_unrounded_curvatures(CubicChoices& c, const std::vector<OutlineNode>& nodes,
                                 std::span<const std::optional<Vec2>> steps, const CubicTraits& ideal,
                                 bool line_before, bool line_after, double flat) {
  const std::size_t i = c.start, j = c.end;
  const bool aim_start = nodes[i].smooth && steps[i] && !line_before;
  const bool aim_end = nodes[j].smooth && steps[j] && !line_after;
  bool start_met = !aim_start, end_met = !aim_end;
  for (std::size_t s = 0; s < c.states(); ++s) {
    if (c.cost[s] == infeasible) continue;
    start_met = start_met || relative_jump(c.k_start[s], ideal.k_start, flat) <= target_jump;
    end_met = end_met || relative_jump(c.k_end[s], ideal.k_end, flat) <= target_jump;
  }
  if (start_met && end_met) return false;
  const Vec2 p0 = nodes[i].point, p3 = nodes[j].point;
  const std::size_t outs = c.outs.size(), ins = c.ins.size();
  if (!start_met)
    for (std::size_t k = 0; k < ins; ++k)
      add_handles(c.outs, handles_for_curvature(p0, *steps[i], true, c.ins[k], p3, ideal.k_start));
  if (!end_met)  // against the far handles as they were, not those just aimed
    for (std::size_t k = 0; k < outs; ++k)
      add_handles(c.ins, handles_for_curvature(p3, *steps[j], false, c.outs[k], p0, ideal.k_end));
  // Where the far end meets a line, its handle runs along the line: where the near handle lies
  // on the line too, κ stays 0 there whatever its length, and elsewhere a longer handle only
  // flattens it. Aimed too, against the near handles as they were; the choice weighs the rest.
  if (!end_met && line_before && steps[i])
    for (std::size_t k = 0; k < ins; ++k)
      add_handles(c.outs, far_handles_for_curvature(p3, *steps[j], false, c.ins[k], p0, *steps[i], ideal.k_end));
  if (!start_met && line_after && steps[j])
    for (std::size_t k = 0; k < outs; ++k)
      add_handles(c.ins, far_handles_for_curvature(p0, *steps[i], true, c.outs[k], p3, *steps[j], ideal.k_start));
  return c.outs.size() != outs || c.ins.size() != ins;
}

// `as_is`: the one choice of the handles where they are (a cubic a choice only weighs).
CubicChoices cubic_choices(const std::vector<OutlineNode>& nodes, std::span<const std::optional<Vec2>> steps,
                           std::size_t i, std::size_t j, CubicJudge& judge, double flat, bool line_before,
                           bool line_after, bool as_is = false) {
  CubicChoices c;
  c.start = i, c.end = j;
  c.outs = as_is ? std::vector<Vec2>{*nodes[i].out_handle} : handle_candidates(nodes[i], steps[i], true);
  c.ins = as_is ? std::vector<Vec2>{*nodes[j].in_handle} : handle_candidates(nodes[j], steps[j], false);
  const CubicTraits& ideal = judge.unrounded(i);
  // κ = 0 at an end that meets a line, or at a smooth node flat before rounding (an inflection,
  // where asked): the far handles nearest that end's tangent line join the choices
  // (seat_flat_nodes moves the node itself for them).
  const bool inflection = judge.inflection_handles();
  const bool zero_start = line_before || (inflection && nodes[i].smooth && std::abs(ideal.k_start) < flat);
  const bool zero_end = line_after || (inflection && nodes[j].smooth && std::abs(ideal.k_end) < flat);
  if (zero_start && steps[i] && !as_is)
    add_handles(c.ins, handles_meeting_line(nodes[j], steps[j], false, nodes[i], *steps[i]));
  if (zero_end && steps[j] && !as_is)
    add_handles(c.outs, handles_meeting_line(nodes[i], steps[i], true, nodes[j], *steps[j]));
  const CandidateWeights weights(nodes, judge, i, j, line_before, line_after, flat);
  weights.weigh(c);
  if (as_is) return c;
  if (widen_at_risky_corners(c, nodes, steps, weights)) weights.weigh(c);
  if (aim_at_unrounded_curvatures(c, nodes, steps, ideal, line_before, line_after, flat)) weights.weigh(c);
  return c;
}

// The indices of `costs`, cheapest first; ties in index order.
std::vector<std::size_t> cheapest_first(std::span<const double> costs) {
  std::vector<std::size_t> order(costs.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return costs[a] < costs[b]; });
  return order;
}

// What the join between state s of cubic a and state t of the cubic b after it costs: its jump
// of κ and, where asked, of dκ/ds (not the turns at its node), and an inflection either side's
// end adds there.
double join_cost(const CubicJudge& judge, const CubicChoices& a, std::size_t s, const CubicChoices& b, std::size_t t,
                 double flat) {
  return judge.g2_cost(relative_jump(a.k_end[s], b.k_start[t], flat)) + judge.slope_cost(*a.traits[s], *b.traits[t]) +
         wrong_way * judge.inflections_at_node(a.start, *a.traits[s], b.start, *b.traits[t]).added;
}

// The cheapest states of a run of cubics joined at smooth nodes; `first`, for a run that
// closes on itself, fixes the first cubic's state and adds the join from the last back to it.
RunChoice best_run(const std::vector<CubicChoices>& run, const CubicJudge& judge, double flat,
                   std::optional<std::size_t> first) {
  const std::size_t n = run.size();
  std::vector<std::vector<std::size_t>> back(n);
  std::vector<double> cost(run[0].states(), infeasible);
  for (std::size_t s = 0; s < cost.size(); ++s)
    if (!first || *first == s) cost[s] = run[0].cost[s];
  for (std::size_t k = 1; k < n; ++k) {
    const CubicChoices &prev = run[k - 1], &cur = run[k];
    std::vector<double> next(cur.states(), infeasible);
    back[k].assign(cur.states(), 0);
    const int unrounded_turns = judge.unrounded_node_turns(prev.start, cur.start);
    // The states before, cheapest first: a join only adds to a state's cost, so once one costs
    // more than the best found, none after it can do better. Ties go to the lower state, as in
    // index order.
    const std::vector<std::size_t> order = cheapest_first(cost);
    for (std::size_t t = 0; t < cur.states(); ++t) {
      if (cur.cost[t] == infeasible) continue;
      for (const std::size_t s : order) {
        if (cost[s] == infeasible || cost[s] > next[t]) break;
        const double c = cost[s] + join_cost(judge, prev, s, cur, t, flat);
        const auto better = [&](double v) { return v < next[t] || (v == next[t] && s < back[k][t]); };
        if (!better(c)) continue;  // a node's turns only add to it
        const double with_turns = c + judge.node_turn_cost(*prev.traits[s], *cur.traits[t], unrounded_turns);
        if (better(with_turns)) next[t] = with_turns, back[k][t] = s;
      }
      next[t] += cur.cost[t];
    }
    cost = std::move(next);
  }
  RunChoice best;
  for (std::size_t s = 0; s < cost.size(); ++s) {
    double c = cost[s];
    if (first && c != infeasible)
      c += join_cost(judge, run[n - 1], s, run[0], *first, flat) +
           judge.node_turn_cost(*run[n - 1].traits[s], *run[0].traits[*first],
                                judge.unrounded_node_turns(run[n - 1].start, run[0].start));
    if (c < best.cost) best.cost = c, best.states.assign(n, 0), best.states[n - 1] = s;
  }
  if (best.cost == infeasible) return best;
  for (std::size_t k = n - 1; k > 0; --k) best.states[k - 1] = back[k][best.states[k]];
  return best;
}

// For a run that closes on itself, the least each state of its first cubic can cost: its own
// cost, the cheapest path from it through the last cubic and the cheapest join back to it from
// any state of the last, the turns at the nodes left out (they cost nothing or more).
std::vector<double> first_state_bounds(const std::vector<CubicChoices>& run, const CubicJudge& judge, double flat) {
  std::vector<double> after = run.back().cost;  // the cheapest path from each state to the end
  for (std::size_t k = run.size() - 1; k > 0; --k) {
    const CubicChoices &prev = run[k - 1], &cur = run[k];
    const std::vector<std::size_t> order = cheapest_first(after);
    std::vector<double> here(prev.states(), infeasible);
    for (std::size_t s = 0; s < prev.states(); ++s) {
      if (prev.cost[s] == infeasible) continue;
      double least = infeasible;
      for (const std::size_t t : order) {
        if (after[t] >= least) break;  // a join only adds
        least = std::min(least, after[t] + join_cost(judge, prev, s, cur, t, flat));
      }
      here[s] = prev.cost[s] + least;
    }
    after = std::move(here);
  }
  // And the cheapest join back from the last cubic, whatever its state.
  const CubicChoices &first = run.front(), &last = run.back();
  for (std::size_t s = 0; s < first.states(); ++s) {
    if (after[s] == infeasible) continue;
    double least = infeasible;
    for (std::size_t t = 0; t < last.states(); ++t)
      if (last.cost[t] != infeasible)
        least = std::min(least, join_cost(judge, last, t, first, s, flat));
    after[s] += least;
  }
  return after;
}

// The cheapest states of a run that closes on itself: each first state in turn, in the order of
// the least its run can cost, until that is past the cheapest run found (no later one can win);
// a tie goes to the lower first state, as in index order. Every first state, in index order,
// took 60 % of the time of DejaVu Sans's a–z A–Z under G3; in this order 5.6 of 85 are solved,
// and the whole takes 43 % less.
RunChoice best_cycle(const std::vector<CubicChoices>& run, const CubicJudge& judge, double flat) {
  RunChoice best;
  const std::vector<double> bound = first_state_bounds(run, judge, flat);
  std::size_t best_first = 0;
  for (const std::size_t first : cheapest_first(bound)) {
    // The bound adds the run's terms in another order: a margin for the last bits.
    if (bound[first] == infeasible || (best.cost != infeasible && bound[first] > best.cost * (1.0 + 1e-9) + 1e-9))
      break;
    RunChoice c = best_run(run, judge, flat, first);
    if (c.cost < best.cost || (c.cost == best.cost && c.cost != infeasible && first < best_first))
      best = std::move(c), best_first = first;
  }
  return best;
}

RunSteps best_run_steps(const std::vector<OutlineNode>& nodes, std::span<const std::optional<Vec2>> steps,
                        const OutlineJoins& joins, std::span<const std::size_t> cubics, bool cycle, CubicJudge& judge,
                        double flat) {
  const std::size_t n = nodes.size();
  std::vector<CubicChoices> run;
  for (const std::size_t i : cubics) {
    const std::size_t j = (i + 1) % n;
    run.push_back(cubic_choices(nodes, steps, i, j, judge, flat, joins.meets_line(i), joins.meets_line(j)));
  }
  RunChoice best = cycle ? best_cycle(run, judge, flat) : best_run(run, judge, flat, std::nullopt);
  return {std::move(run), std::move(best)};
}

}  // namespace

std::vector<Vec2> handle_candidates(const OutlineNode& node, std::optional<Vec2> step, bool out, int corner_reach) {
  const Vec2 h = out ? *node.out_handle : *node.in_handle;
  std::vector<Vec2> c{h};
  if (step) {
    const double sign = out ? 1.0 : -1.0;
    const double m0 = whole_steps(node.point, h, *step, sign);
    for (int k = -handle_reach; k <= handle_reach; ++k)
      if (k != 0 && m0 + k >= 1.0) c.push_back(node.point + *step * (sign * (m0 + k)));
  } else if (!node.smooth) {
    for (int dx = -corner_reach; dx <= corner_reach; ++dx)
      for (int dy = -corner_reach; dy <= corner_reach; ++dy) {
        const Vec2 moved = h + Vec2{double(dx), double(dy)};
        if (moved != h && moved != node.point) c.push_back(moved);  // never onto its node
      }
  }
  return c;
}

bool apply_steps(std::vector<OutlineNode>& nodes, const RunSteps& chosen) {
  if (chosen.best.cost == infeasible) return false;
  bool moved = false;
  for (std::size_t k = 0; k < chosen.run.size(); ++k) {
    const CubicChoices& c = chosen.run[k];
    const std::size_t state = chosen.best.states[k];
    const Vec2 out = c.outs[state / c.ins.size()], in = c.ins[state % c.ins.size()];
    moved = moved || nodes[c.start].out_handle != out || nodes[c.end].in_handle != in;
    nodes[c.start].out_handle = out;
    nodes[c.end].in_handle = in;
  }
  return moved;
}

bool choose_run_steps(std::vector<OutlineNode>& nodes, std::span<const std::optional<Vec2>> steps,
                      const OutlineJoins& joins, std::span<const std::size_t> cubics, bool cycle, CubicJudge& judge,
                      double flat) {
  return apply_steps(nodes, best_run_steps(nodes, steps, joins, cubics, cycle, judge, flat));
}

RunWindow window_around(std::span<const std::size_t> run, bool cycle, std::size_t position) {
  constexpr std::size_t side = 3;
  const std::size_t m = run.size();
  RunWindow w;
  if (cycle && m <= 2 * side + 2) {
    w.cubics.assign(run.begin(), run.end());
    w.whole_cycle = true;
    return w;
  }
  const std::ptrdiff_t size = static_cast<std::ptrdiff_t>(m);
  const auto at = [&](std::ptrdiff_t k) -> std::optional<std::size_t> {
    if (cycle) return run[static_cast<std::size_t>((k % size + size) % size)];
    if (k < 0 || k >= size) return std::nullopt;
    return run[static_cast<std::size_t>(k)];
  };
  const std::ptrdiff_t q = static_cast<std::ptrdiff_t>(position), s = static_cast<std::ptrdiff_t>(side);
  for (std::ptrdiff_t k = q - s; k < q + s; ++k)
    if (const auto c = at(k)) w.cubics.push_back(*c);
  w.before = at(q - s - 1), w.after = at(q + s);
  return w;
}

RunSteps choose_window(const std::vector<OutlineNode>& nodes, std::span<const std::optional<Vec2>> steps,
                       const OutlineJoins& joins, const RunWindow& w, CubicJudge& judge, double flat,
                       std::size_t moving, const RunSteps* known) {
  const std::size_t n = nodes.size();
  std::vector<std::pair<std::size_t, bool>> cubics;  // each cubic, and whether it stays as it is
  if (w.before) cubics.emplace_back(*w.before, true);
  for (const std::size_t i : w.cubics) cubics.emplace_back(i, false);
  if (w.after) cubics.emplace_back(*w.after, true);
  RunSteps out;
  for (const auto& [i, as_is] : cubics) {
    const std::size_t j = (i + 1) % n;
    const bool touches = i == moving || j == moving;
    out.run.push_back(known && !touches ? known->run[out.run.size()]
                                        : cubic_choices(nodes, steps, i, j, judge, flat, joins.meets_line(i),
                                                        joins.meets_line(j), as_is));
  }
  out.best = w.whole_cycle ? best_cycle(out.run, judge, flat) : best_run(out.run, judge, flat, std::nullopt);
  return out;
}

}  // namespace gf
