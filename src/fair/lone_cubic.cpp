#include "fair/lone_cubic.hpp"

#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <span>
#include <utility>

#include "fair/bracket_placements.hpp"
#include "fair/node_change.hpp"
#include "fair/step_costs.hpp"
#include "geom/tangent_crossing.hpp"

namespace gf {

namespace {

constexpr double crossing_reach = 3.0;  // units the crossing X may lie from the unrounded one

using GridPoint = std::pair<double, double>;

// For each grid point within crossing_reach of `crossing` that a join place's line reaches at
// whole steps beyond the join (ahead of it where the line `arrives` at the join, else behind
// it), the places that reach it.
std::map<GridPoint, std::vector<JoinPlace>> places_by_crossing(std::span<const JoinPlace> places, bool arrives,
                                                               Vec2 crossing) {
  std::map<GridPoint, std::vector<JoinPlace>> out;
  for (const JoinPlace& p : places) {
    const Vec2 towards = arrives ? p.step : p.step * -1.0;  // from the join towards the crossing
    const double k0 = dot(crossing - p.join, towards) / dot(towards, towards);
    for (const double k : {std::floor(k0), std::ceil(k0)}) {
      const Vec2 x = p.join + towards * k;
      if (k < 1.0 || distance(x, crossing) > crossing_reach) continue;
      std::vector<JoinPlace>& at = out[{x.x, x.y}];
      if (at.empty() || at.back().join != p.join || at.back().far != p.far) at.push_back(p);
    }
  }
  return out;
}

}  // namespace

bool seat_lone_cubic(std::vector<OutlineNode>& nodes, const std::vector<OutlineNode>& ideal,
                     std::vector<std::optional<Vec2>>& steps, const OutlineJoins& joins, std::size_t a,
                     CubicJudge& judge, double flat) {
  const std::size_t n = nodes.size(), b = (a + 1) % n, fa = (a + n - 1) % n, fb = (b + 1) % n;
  if (n < 4 || !steps[a] || !steps[b]) return false;
  // Where the unrounded lines cross, ahead of the cubic's start and behind its end.
  const Vec2 from = ideal[a].point, to = ideal[b].point;
  const std::optional<Vec2> crossing = tangent_crossing(from, from - ideal[fa].point, to, ideal[fb].point - to);
  if (!crossing) return false;
  const BracketLine first = bracket_line(nodes, ideal, *steps[a], a, fa, !joins.is_cubic((fa + n - 1) % n),
                                         nodes[(fa + n - 1) % n].point);
  const BracketLine last = bracket_line(nodes, ideal, *steps[b], b, fb, !joins.is_cubic(fb), nodes[(fb + 1) % n].point);
  const auto firsts = places_by_crossing(join_places(first, true, grid_turn), true, *crossing);
  const auto lasts = places_by_crossing(join_places(last, false, grid_turn), false, *crossing);

  const CubicTraits& unrounded = judge.unrounded(a);
  const CubicTraits& now = judge.traits(a, outline_cubic(nodes, a));  // the judge's map keeps it in place
  const FaultCeiling ceiling = FaultCeiling::of(judge, a, now);
  const auto cost_of = [&](const CubicTraits& t) {
    return jump_cost(relative_jump(t.k_start, 0.0, flat)) + jump_cost(relative_jump(t.k_end, 0.0, flat)) +
           shape_cost(t.shape, unrounded.shape, flat);
  };
  double best_cost = cost_of(now);

  const std::array<OutlineNode, 4> kept{nodes[fa], nodes[a], nodes[b], nodes[fb]};
  const auto place = [&](Vec2 x, const JoinPlace& p, const JoinPlace& q) {
    nodes[fa].point = p.far, nodes[a].point = p.join, nodes[a].out_handle = x;
    nodes[b].point = q.join, nodes[b].in_handle = x, nodes[fb].point = q.far;
  };
  struct Seat {
    Vec2 x;
    JoinPlace first, last;
  };
  std::optional<Seat> best;
  for (const auto& [x_at, ps] : firsts) {
    const auto qs = lasts.find(x_at);
    if (qs == lasts.end()) continue;
    const Vec2 x{x_at.first, x_at.second};
    for (const JoinPlace& p : ps)
      for (const JoinPlace& q : qs->second) {
        place(x, p, q);
        const CubicTraits& t = judge.traits(a, outline_cubic(nodes, a));
        const double c = cost_of(t);
        if (c >= best_cost || !ceiling.admits(judge, a, t) || turns_less_than_it_did(nodes, ideal, joins.closed, fa) ||
            turns_less_than_it_did(nodes, ideal, joins.closed, fb))
          continue;
        best_cost = c, best = Seat{x, p, q};
      }
  }
  nodes[fa] = kept[0], nodes[a] = kept[1], nodes[b] = kept[2], nodes[fb] = kept[3];
  if (!best) return false;
  place(best->x, best->first, best->last);
  steps[a] = best->first.step, steps[b] = best->last.step;
  return true;
}

}  // namespace gf
