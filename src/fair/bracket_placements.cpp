#include "fair/bracket_placements.hpp"

#include <algorithm>
#include <cmath>

#include "fair/handle_steps.hpp"
#include "geom/polyline_distance.hpp"

namespace gf {

namespace {

constexpr double slide = 16.0;    // units a join may lie along its line from the unrounded one
// A join slides along a line that does not turn by at most this many of its steps, and an
// end's handle lies between 1/handle_share and handle_share times its unrounded length: a
// stem's unit steps otherwise gave 33 places and a hundred lengths at each (DejaVu Sans's
// Cyrillic, its corners rounded between two upright lines: 13 % of the range's instructions,
// 3 % so; at twice, Carlito and Noto Serif kept a jump each more and TeX Gyre Pagella three, at
// four times Pagella's J keeps one).
constexpr int most_slide_steps = 4;
constexpr double handle_share = 4.0;
constexpr double off_line = 0.75;  // units a turned line's join may lie off the unrounded line
constexpr int exact_samples = 48;  // points per unrounded cubic the spread is measured against
// Placements kept per cubic of the leading side, those of the other side's cubics nearest the
// unrounded bracket: else one far cubic and every stem slide that matches it filled the list
// (Pagella's M: 48 placements, one cubic on the serif's side, none allowed).
constexpr std::size_t pairings_per_cubic = 3;

// The line's unit direction, from its far end to its join where it `arrives` at the join (the
// bracket's first line), else from its join to its far end.
Vec2 unit_direction(const BracketLine& line, bool arrives) {
  const Vec2 d = arrives ? line.exact_join - line.exact_far : line.exact_far - line.exact_join;
  return d / norm(d);
}

// How far along its line (along `e`, from the unrounded join) a join may lie: within `slide` of
// the unrounded join and of its rounded place, and between them.
struct AlongReach {
  double least, most;
};
AlongReach along_reach(const BracketLine& line, Vec2 e) {
  const double rounded = dot(line.join - line.exact_join, e);
  return {std::min(0.0, rounded) - slide, std::max(0.0, rounded) + slide};
}

// The places of a bracket's end: its line's (join_places) or its node.
std::vector<JoinPlace> end_places(const std::variant<BracketLine, BracketNode>& end, bool arrives, double most_turn) {
  if (const BracketNode* node = std::get_if<BracketNode>(&end))
    return {{node->point, node->point, node->step, true, node->kappa}};
  return join_places(std::get<BracketLine>(end), arrives, most_turn);
}

// The whole steps of `unit` units an end's handle may take: between 1/handle_share and
// handle_share times its unrounded length, and at least one.
struct HandleSteps {
  double least, most;
};
HandleSteps end_handle_steps(double exact_handle, double unit) {
  return {std::max(1.0, std::ceil(exact_handle / handle_share / unit)), std::floor(handle_share * exact_handle / unit)};
}

// One cubic of a bracket from one of its ends to its node, or from the node to an end.
struct SideCubic {
  std::size_t place;    ///< into the side's end places
  Vec2 end_handle, node_handle;  ///< the end's handle and the bracket node's
  double node_kappa;    ///< κ at the node
  Cubic cubic;
  /// The farthest of its quarter points from the unrounded bracket, once asked for (most
  /// cubics match none of the other side's).
  mutable std::optional<double> spread;
};

// A side cubic's spread (SideCubic::spread), or some value past `bound` where it is past.
double spread_of(const SideCubic& s, std::span<const Vec2> exact, double bound) {
  if (!s.spread) {
    const std::array<Vec2, 3> quarters{s.cubic.point_at(0.25), s.cubic.point_at(0.5), s.cubic.point_at(0.75)};
    const double d = directed_hausdorff(quarters, exact, bound);
    if (d > bound) return d;  // only that it is past: not kept
    s.spread = d;
  }
  return *s.spread;
}

// The cubics from an end node to the bracket's node at `node` stepping `u`, or back: the
// bracket node's handle any whole steps of u short of the end node; the end node's the whole
// steps of its direction that give it its κ (handles_for_curvature), or, at a corner, any
// short of the bracket node. `first`: the bracket's first side; `wanted`: as side_cubics.
void node_side_cubics(const JoinPlace& place, std::size_t k, bool first, Vec2 node, Vec2 u, double exact_handle,
                      double flat, double target, std::optional<std::pair<double, double>> wanted,
                      std::vector<SideCubic>& out) {
  const SegmentEnd at_end = first ? SegmentEnd::start : SegmentEnd::end;
  const SegmentEnd at_node = first ? SegmentEnd::end : SegmentEnd::start;
  const double chord = distance(node, place.join);
  const Vec2 into = first ? place.step : place.step * -1.0;  // from the end node into the bracket
  const double unit = norm(into);
  const HandleSteps steps = end_handle_steps(exact_handle, unit);
  for (double m = 1.0; m * norm(u) < chord; ++m) {
    const Vec2 far = node + u * (first ? -m : m);
    std::vector<Vec2> nears;
    if (place.kappa) nears = handles_for_curvature(place.join, place.step, first, far, node, *place.kappa);
    else
      for (double a = steps.least; a * unit < chord && a <= steps.most; ++a) nears.push_back(place.join + into * a);
    for (const Vec2 near : nears) {
      const Cubic c = first ? Cubic{place.join, near, far, node} : Cubic{node, far, near, place.join};
      const double kappa = node_curvature(c, at_node);
      if ((place.kappa && relative_jump(node_curvature(c, at_end), *place.kappa, flat) > target) ||
          (wanted && (kappa < wanted->first || kappa > wanted->second)))
        continue;
      out.push_back({k, near, far, kappa, c, std::nullopt});
    }
  }
}

// The cubics from a join on a line to the bracket's node, or back: the join's handle whole
// steps of the line's from it, short of the node's handle, which lies the whole steps of u
// nearest the line (handles_near_line); κ within target·flat of 0 at the join. Where `wanted`
// is given, only those whose κ at the node lies within it: κ there is linear in the join
// handle's steps (the node and its handle stay: (2/3)·(far − near) × (node − far) /
// |node − far|³), so two steps find the range.
void line_side_cubics(const JoinPlace& place, std::size_t k, bool first, Vec2 node, Vec2 u, double exact_handle,
                      double flat, double target, std::optional<std::pair<double, double>> wanted,
                      std::vector<SideCubic>& out) {
  const SegmentEnd at_join = first ? SegmentEnd::start : SegmentEnd::end;
  const SegmentEnd at_node = first ? SegmentEnd::end : SegmentEnd::start;
  const Vec2 into = first ? place.step : place.step * -1.0;  // along the line into the bracket
  const HandleSteps steps = end_handle_steps(exact_handle, norm(into));
  for (const Vec2 far : handles_near_line(node, u, first ? -1.0 : 1.0, place.join, place.step)) {
    const auto cubic = [&](double a) {
      const Vec2 near = place.join + into * a;
      return first ? Cubic{place.join, near, far, node} : Cubic{node, far, near, place.join};
    };
    double lo = steps.least;
    double hi = std::min(std::ceil(dot(far - place.join, into) / dot(into, into)) - 1.0, steps.most);
    if (wanted) {
      const double k1 = node_curvature(cubic(1.0), at_node), per_step = node_curvature(cubic(2.0), at_node) - k1;
      if (per_step == 0.0) {
        if (k1 < wanted->first || k1 > wanted->second) continue;
      } else {
        const double a1 = 1.0 + (wanted->first - k1) / per_step, a2 = 1.0 + (wanted->second - k1) / per_step;
        lo = std::max(lo, std::ceil(std::min(a1, a2)));
        hi = std::min(hi, std::floor(std::max(a1, a2)));
      }
    }
    for (double a = lo; a <= hi; ++a) {
      const Cubic c = cubic(a);
      if (std::abs(node_curvature(c, at_join)) > target * flat) continue;
      out.push_back({k, c.p[first ? 1 : 2], far, node_curvature(c, at_node), c, std::nullopt});
    }
  }
}

// The cubics of one side of the bracket for its node at `node` stepping `u`, from each of the
// side's end places: `first` is the side from the bracket's start. Where `wanted` is given,
// only those whose κ at the node lies within it.
std::vector<SideCubic> side_cubics(std::span<const JoinPlace> places, bool first, Vec2 node, Vec2 u, double exact_handle,
                                   double flat, double target,
                                   std::optional<std::pair<double, double>> wanted = std::nullopt) {
  std::vector<SideCubic> out;
  for (std::size_t k = 0; k < places.size(); ++k)
    (places[k].at_node ? node_side_cubics : line_side_cubics)(places[k], k, first, node, u, exact_handle, flat, target,
                                                               wanted, out);
  return out;
}

// The `most` placements of least spread, in that order.
void keep_least_spread(std::vector<BracketPlacement>& found, std::size_t most) {
  const auto less = [](const BracketPlacement& a, const BracketPlacement& b) { return a.spread < b.spread; };
  if (found.size() > most) {
    std::nth_element(found.begin(), found.begin() + static_cast<std::ptrdiff_t>(most), found.end(), less);
    found.resize(most);
  }
  std::sort(found.begin(), found.end(), less);
}

}  // namespace

BracketLine bracket_line(const std::vector<OutlineNode>& nodes, const std::vector<OutlineNode>& ideal, Vec2 step,
                         std::size_t join, std::size_t far, bool beyond_is_line, Vec2 beyond) {
  const Vec2 d = ideal[far].point - ideal[join].point;
  BracketLine l{nodes[far].point, std::nullopt, nodes[join].point, step, ideal[far].point, ideal[join].point,
                !nodes[far].smooth && d.x != 0.0 && d.y != 0.0};
  const Vec2 nearest = nearest_grid_point(ideal[far].point);
  const bool stays_upright = (l.far.x == beyond.x && nearest.x == beyond.x) || (l.far.y == beyond.y && nearest.y == beyond.y);
  if (l.may_turn && beyond_is_line && stays_upright && nearest != l.far) l.far_alternative = nearest;
  return l;
}

// Within `slide` of the rounded place too: where a curve ends nearly straight, rounding may
// slide its join farther (FreeSerif's w and TeX Gyre Pagella's m, y, V and X meet only there).
std::vector<JoinPlace> join_places(const BracketLine& line, bool arrives, double most_turn) {
  const double exact_length = distance(line.exact_join, line.exact_far);
  std::vector<JoinPlace> out;
  if (exact_length == 0.0) return out;
  const Vec2 e = unit_direction(line, arrives);
  const auto keeps_length = [&](Vec2 p, Vec2 far) { return distance(p, far) >= 0.5 * exact_length; };
  const auto [least_along, most_along] = along_reach(line, e);
  const auto within_reach = [&](Vec2 p) {
    const double along = dot(p - line.exact_join, e);
    return along >= least_along && along <= most_along;
  };
  if (!line.may_turn) {
    const double unit = norm(line.step);
    const int most = std::min(most_slide_steps, static_cast<int>(slide / unit));
    for (int k = -most; k <= most; ++k) {
      const Vec2 p = line.join + line.step * static_cast<double>(k);
      if (within_reach(p) && keeps_length(p, line.far))
        out.push_back({line.far, p, line.step, false, std::nullopt});
    }
    return out;
  }
  std::vector<Vec2> fars{line.far};
  if (line.far_alternative) fars.push_back(*line.far_alternative);
  // Grid points near the unrounded line: along its major axis, the two either side of it.
  const bool along_x = std::abs(e.x) >= std::abs(e.y);
  const double major = along_x ? e.x : e.y;
  const double centre = along_x ? line.exact_join.x : line.exact_join.y;
  const double from = centre + std::min(least_along * major, most_along * major) - 1.0;
  const double to = centre + std::max(least_along * major, most_along * major) + 1.0;
  for (double u = std::ceil(from); u <= to; ++u) {
    const double t = (u - centre) / major;  // along the line from the exact join
    const Vec2 on = line.exact_join + e * t;
    const double minor = along_x ? on.y : on.x;
    for (const double v : {std::floor(minor), std::ceil(minor)}) {
      const Vec2 p = along_x ? Vec2{u, v} : Vec2{v, u};
      if (std::abs(cross(e, p - line.exact_join)) > off_line || !within_reach(p)) continue;
      for (const Vec2 far : fars) {
        const std::optional<Vec2> step = primitive_step(arrives ? p - far : far - p);
        if (!step || std::abs(turning_angle(e, *step)) > most_turn || !keeps_length(p, far)) continue;
        if (std::none_of(out.begin(), out.end(), [&](const JoinPlace& q) { return q.join == p && q.far == far; }))
          out.push_back({far, p, *step, false, std::nullopt});
      }
    }
  }
  return out;
}

std::vector<BracketPlacement> bracket_placements(const Bracket& bracket, std::span<const Vec2> node_points,
                                                 std::span<const Vec2> node_steps, double flat, double target,
                                                 double most_turn, std::size_t most) {
  const std::vector<JoinPlace> firsts = end_places(bracket.first, true, most_turn);
  const std::vector<JoinPlace> lasts = end_places(bracket.last, false, most_turn);
  std::vector<BracketPlacement> found;
  if (firsts.empty() || lasts.empty()) return found;
  double bound = std::numeric_limits<double>::infinity();
  // The unrounded bracket with a stretch of each line, which a slid join's cubic takes over.
  const std::array<Vec2, 7>& x = bracket.exact;
  // As far towards its far end as a join may lie (along_reach).
  const auto line_stretch = [](const std::variant<BracketLine, BracketNode>& end, Vec2 join, bool arrives) {
    const BracketLine* line = std::get_if<BracketLine>(&end);
    if (!line) return join;
    const AlongReach reach = along_reach(*line, unit_direction(*line, arrives));
    const double towards_far = arrives ? -reach.least : reach.most;
    return join + (line->exact_far - join) * std::min(1.0, towards_far / distance(line->exact_far, join));
  };
  std::vector<Vec2> exact{line_stretch(bracket.first, x[0], true)};
  for (const Cubic& c : {Cubic{x[0], x[1], x[2], x[3]}, Cubic{x[3], x[4], x[5], x[6]}})
    for (int t = 0; t <= exact_samples; ++t) exact.push_back(c.point_at(double(t) / exact_samples));
  exact.push_back(line_stretch(bracket.last, x[6], false));

  // The side with fewer cubics leads (an end node's, else the one whose line steps longer),
  // and the other side's cubics are found only where their κ at the node can match (a stem's
  // unit steps give hundreds).
  const auto leading = [](const std::variant<BracketLine, BracketNode>& end) {
    const BracketLine* line = std::get_if<BracketLine>(&end);
    return line ? norm(line->step) : std::numeric_limits<double>::infinity();
  };
  const bool first_leads = leading(bracket.first) >= leading(bracket.last);
  const std::vector<JoinPlace>& lead_places = first_leads ? firsts : lasts;
  const std::vector<JoinPlace>& follow_places = first_leads ? lasts : firsts;
  const double first_handle = distance(x[0], x[1]), last_handle = distance(x[6], x[5]);
  const double lead_handle = first_leads ? first_handle : last_handle;
  const double follow_handle = first_leads ? last_handle : first_handle;
  const auto by_kappa = [](const SideCubic& a, const SideCubic& b) { return a.node_kappa < b.node_kappa; };
  for (const Vec2 node : node_points)
    for (const Vec2 u : node_steps) {
      const std::vector<SideCubic> leads = side_cubics(lead_places, first_leads, node, u, lead_handle, flat, target);
      if (leads.empty()) continue;
      const auto [least, most_kappa] = std::minmax_element(leads.begin(), leads.end(), by_kappa);
      const double margin = target * std::max({std::abs(least->node_kappa), std::abs(most_kappa->node_kappa), flat});
      std::vector<SideCubic> follows = side_cubics(follow_places, !first_leads, node, u, follow_handle, flat, target,
                                                   std::pair{least->node_kappa - margin, most_kappa->node_kappa + margin});
      std::sort(follows.begin(), follows.end(), by_kappa);
      std::vector<const SideCubic*> matched;
      for (const SideCubic& lead : leads) {
        // Curvatures within `target` of lead.node_kappa lie within its magnitude's share either side.
        const double within = target * std::max(std::abs(lead.node_kappa), flat);
        auto it = std::lower_bound(follows.begin(), follows.end(), lead.node_kappa - within,
                                   [](const SideCubic& s, double k) { return s.node_kappa < k; });
        matched.clear();
        for (; it != follows.end() && it->node_kappa <= lead.node_kappa + within; ++it)
          if (relative_jump(lead.node_kappa, it->node_kappa, flat) <= target) matched.push_back(&*it);
        if (matched.empty()) continue;
        const double lead_spread = spread_of(lead, exact, bound);
        if (lead_spread >= bound) continue;
        // A few of the other side's cubics each: the placements one cubic dominates differ
        // in what the other side does at its least spread.
        std::erase_if(matched, [&](const SideCubic* f) { return spread_of(*f, exact, bound) >= bound; });
        const std::size_t keep = std::min(matched.size(), pairings_per_cubic);
        std::partial_sort(matched.begin(), matched.begin() + static_cast<std::ptrdiff_t>(keep), matched.end(),
                          [](const SideCubic* a, const SideCubic* b) { return *a->spread < *b->spread; });
        for (std::size_t k = 0; k < keep; ++k) {
          const SideCubic& one = first_leads ? lead : *matched[k];
          const SideCubic& two = first_leads ? *matched[k] : lead;
          const JoinPlace &p1 = firsts[one.place], &p2 = lasts[two.place];
          found.push_back({p1.far, p1.join, p1.step, one.end_handle, one.node_handle, node, u, two.node_handle,
                           two.end_handle, p2.join, p2.step, p2.far, std::max(lead_spread, *matched[k]->spread)});
        }
        if (found.size() >= 4 * most) {
          keep_least_spread(found, most);
          bound = found.back().spread;  // past the farthest of a full list, a placement is not kept
        }
      }
    }
  keep_least_spread(found, most);
  return found;
}

}  // namespace gf
