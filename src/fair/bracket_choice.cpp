#include "fair/bracket_choice.hpp"

#include <algorithm>
#include <array>
#include <variant>

#include "fair/bracket_placements.hpp"
#include "fair/node_change.hpp"
#include "fair/step_costs.hpp"

namespace gf {

namespace {

// The most placements of a bracket judged (nearest the unrounded bracket first): the Pagella
// serifs that take one take it among the first few.
constexpr std::size_t bracket_tries = 48;

}  // namespace

bool place_bracket(std::vector<OutlineNode>& nodes, const std::vector<OutlineNode>& ideal,
                   std::vector<std::optional<Vec2>>& steps, const OutlineJoins& joins, std::size_t h, CubicJudge& judge,
                   double flat) {
  const std::size_t n = nodes.size(), i = (h + 1) % n, j = (i + 1) % n, before = (h + n - 1) % n, after = (j + 1) % n;
  // Each end's direction along the contour: a line's or node's step, a corner's handle's.
  const auto end_step = [&](std::size_t k) -> std::optional<Vec2> {
    if (nodes[k].smooth) return steps[k];
    return primitive_step(k == h ? *nodes[k].out_handle - nodes[k].point : nodes[k].point - *nodes[k].in_handle);
  };
  const std::optional<Vec2> step_h = end_step(h), step_j = end_step(j);
  if (n < 5 || !step_h || !steps[i] || !step_j) return false;
  // A line may turn about a far end that is a corner, where it is not horizontal or vertical;
  // that corner may go back to its nearest grid point where the line beyond it is horizontal or
  // vertical and stays so. A node inside the run stays, with the curvature beyond it.
  const auto end = [&](std::size_t join, std::size_t far, std::size_t beyond) -> std::variant<BracketLine, BracketNode> {
    const Vec2 step = join == h ? *step_h : *step_j;
    if (!joins.meets_line(join)) {
      if (!nodes[join].smooth) return BracketNode{nodes[join].point, step, std::nullopt};
      const double kappa = far == before ? curvatures_at(nodes, join).first : curvatures_at(nodes, join).second;
      return BracketNode{nodes[join].point, step, kappa};
    }
    const bool beyond_is_line = !(far == before ? joins.is_cubic(beyond) : joins.is_cubic(far));
    return bracket_line(nodes, ideal, step, join, far, beyond_is_line, nodes[beyond].point);
  };
  const Bracket bracket{end(h, before, (before + n - 1) % n), end(j, after, (after + 1) % n),
                        {ideal[h].point, *ideal[h].out_handle, *ideal[i].in_handle, ideal[i].point,
                         *ideal[i].out_handle, *ideal[j].in_handle, ideal[j].point}};
  // The node within two units of where the passes left it, however far that is from its
  // unrounded place (the judge keeps its cubics within their allowance): within two of both,
  // Carlito's M, its vertex's node slid four units, had no place with a placement.
  const std::vector<BracketPlacement> placements =
      bracket_placements(bracket, node_places(nodes[i].point, nodes[i].point, 2), node_directions(*steps[i], ideal[i]),
                         flat, target_jump, grid_turn, bracket_tries);
  if (placements.empty()) return false;
  const NodeChange change(nodes, joins, judge, flat, i);
  // The far corners of lines turn no less than the kink limit, or than they did.
  const bool line_before = joins.meets_line(h), line_after = joins.meets_line(j);
  const std::array<OutlineNode, 5> kept{nodes[before], nodes[h], nodes[i], nodes[j], nodes[after]};
  double best_cost = change.cost();
  const BracketPlacement* best = nullptr;
  const auto place = [&](const BracketPlacement& p) {
    if (line_before) nodes[before].point = p.far1, nodes[h].point = p.join1;
    if (line_after) nodes[after].point = p.far2, nodes[j].point = p.join2;
    nodes[h].out_handle = p.handle1;
    nodes[i].point = p.node, nodes[i].in_handle = p.handle2, nodes[i].out_handle = p.handle3;
    nodes[j].in_handle = p.handle4;
  };
  for (const BracketPlacement& p : placements) {
    place(p);
    if ((line_before && turns_less_than_it_did(nodes, ideal, joins.closed, before)) ||
        (line_after && turns_less_than_it_did(nodes, ideal, joins.closed, after)))
      continue;
    if (const std::optional<double> c = change.cost_under(best_cost)) best_cost = *c, best = &p;
  }
  nodes[before] = kept[0], nodes[h] = kept[1], nodes[i] = kept[2], nodes[j] = kept[3], nodes[after] = kept[4];
  if (!best) return false;
  place(*best);
  if (line_before) steps[h] = best->step1;
  if (line_after) steps[j] = best->step2;
  steps[i] = best->node_step;
  return true;
}

}  // namespace gf
