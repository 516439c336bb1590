#include "fair/tight_turn.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

#include "geom/curvature.hpp"

namespace gf {

namespace {

constexpr int samples_per_segment = 32;
// A turn is the stretch about a curvature peak (its radius at most the deviation) that keeps
// the peak's sign and a radius of at most twice the deviation: one turn, however many peaks
// (dkg's h turns 66° through two, which a fifth of the sharper peak's curvature cut in two
// corners 8 units apart).
constexpr double stretch_radius = 2.0;
// A turn's sharpest point this close to a node is taken at the node: no sliver of a segment.
constexpr double snap_units = 0.5;

struct Sample {
  std::size_t segment;
  double t;
  Vec2 point, tangent;
  double curvature;
};

std::optional<Sample> sample_at(const Segment& c, std::size_t segment, double t) {
  const Derivatives d = derivatives_at(c, t);
  const double speed = norm(d.d1);
  if (speed == 0.0) return std::nullopt;
  return Sample{segment, t, d.point, d.d1 / speed, curvature(d).value_or(0.0)};
}

std::vector<Sample> samples_of(const Contour& c) {
  std::vector<Sample> out;
  for (std::size_t i = 0; i < c.segments.size(); ++i) {
    const int count = is_line(c.segments[i]) ? 1 : samples_per_segment;
    for (int k = 0; k < count; ++k)
      if (const auto s = sample_at(c.segments[i], i, static_cast<double>(k) / count)) out.push_back(*s);
  }
  return out;
}

// The parameter of greatest |κ| within a sample spacing of `t` (golden-section search).
double sharpest_t(const Cubic& c, double t) {
  const auto sharpness = [&](double u) { return std::abs(curvature(derivatives_at(Segment{c}, u)).value_or(0.0)); };
  double lo = std::max(0.0, t - 1.0 / samples_per_segment), hi = std::min(1.0, t + 1.0 / samples_per_segment);
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int k = 0; k < 40; ++k) {
    const double a = hi - g * (hi - lo), b = lo + g * (hi - lo);
    if (sharpness(a) < sharpness(b)) lo = a;
    else hi = b;
  }
  return 0.5 * (lo + hi);
}

struct Found {
  std::size_t segment;
  double t;
  Vec2 tangent_in, tangent_out;
};

// The tight turns of `c` (all cubics and lines), sharpest first.
std::vector<Found> turns_of(const Contour& c, const TightTurnLimits& limits) {
  const std::vector<Sample> s = samples_of(c);
  const std::size_t n = s.size();
  std::vector<Found> found;
  if (n < 3 || limits.deviation_units <= 0.0) return found;
  const auto next = [&](std::size_t j) { return (j + 1) % n; };
  const auto prev = [&](std::size_t j) { return (j + n - 1) % n; };
  // The turn from sample j to the next; a join already turning past a corner's worth (or the
  // open contour's ends) bounds every stretch.
  std::vector<double> turn(n);
  std::vector<bool> barrier(n);
  for (std::size_t j = 0; j < n; ++j) {
    turn[j] = turning_angle(s[j].tangent, s[next(j)].tangent);
    barrier[j] = (!c.closed && next(j) == 0) || (s[next(j)].t == 0.0 && std::abs(turn[j]) > radians(limits.min_turn_deg));
  }
  // A turn into a corner (or an open end) ends there: no room for a corner of its own.
  const auto room = [&](std::size_t j, bool forward) {
    double run = 0.0;
    for (std::size_t step = 0; step < n && run < limits.deviation_units; ++step) {
      if (barrier[forward ? j : prev(j)]) return false;
      const std::size_t k = forward ? next(j) : prev(j);
      run += distance(s[j].point, s[k].point), j = k;
    }
    return true;
  };
  std::vector<std::size_t> peaks;
  for (std::size_t j = 0; j < n; ++j)
    if (std::abs(s[j].curvature) * limits.deviation_units >= 1.0) peaks.push_back(j);
  std::sort(peaks.begin(), peaks.end(), [&](auto a, auto b) { return std::abs(s[a].curvature) > std::abs(s[b].curvature); });
  std::vector<bool> used(n, false);
  for (const std::size_t p : peaks) {
    if (used[p]) continue;
    const double k = s[p].curvature;
    const auto within = [&](std::size_t j) {
      return !used[j] && k * s[j].curvature > 0.0 && std::abs(s[j].curvature) * stretch_radius * limits.deviation_units >= 1.0;
    };
    std::size_t lo = p, hi = p, size = 1;  // a closed contour bending one way throughout stops at n
    while (size < n && !barrier[prev(lo)] && within(prev(lo))) lo = prev(lo), ++size;
    while (size < n && !barrier[hi] && within(next(hi))) hi = next(hi), ++size;
    double turned = 0.0;
    for (std::size_t j = lo; j != hi; j = next(j)) turned += turn[j], used[j] = true;
    used[hi] = true;
    if (!room(lo, false) || !room(hi, true)) continue;
    if (turned * k <= 0.0 || std::abs(turned) < radians(limits.min_turn_deg) || std::abs(turned) > radians(limits.max_turn_deg))
      continue;
    const Cubic& cubic = std::get<Cubic>(c.segments[s[p].segment]);
    const double t = sharpest_t(cubic, s[p].t);  // a peak is on a curve: lines have κ = 0
    const Vec2 apex = cubic.point_at(t), in = s[lo].tangent, out_dir = s[hi].tangent;
    // Both sides within the deviation of the lines through the apex along their directions.
    double off = 0.0;
    for (std::size_t j = lo; j != p; j = next(j)) off = std::max(off, std::abs(cross(in, s[j].point - apex)));
    for (std::size_t j = p; j != next(hi); j = next(j)) off = std::max(off, std::abs(cross(out_dir, s[j].point - apex)));
    if (off <= limits.deviation_units) found.push_back({s[p].segment, t, in, out_dir});
  }
  return found;
}

// `c` split at its turns `found`: each at a node of `c` (when its apex is that close to one,
// the node made a corner) or at a cut of its cubic, a new corner node.
TightTurns split_at_turns(const Contour& c, std::span<const Found> found) {
  TightTurns out;
  const std::size_t segments = c.segments.size();
  std::map<std::size_t, const Found*> at_source_node;
  std::map<std::size_t, std::vector<std::pair<double, const Found*>>> cuts;
  for (const Found& f : found) {
    const Cubic& cubic = std::get<Cubic>(c.segments[f.segment]);
    const Vec2 apex = cubic.point_at(f.t);
    if (distance(apex, cubic.p[0]) < snap_units) at_source_node.emplace(f.segment, &f);
    else if (distance(apex, cubic.p[3]) < snap_units) at_source_node.emplace(c.closed ? (f.segment + 1) % segments : f.segment + 1, &f);
    else cuts[f.segment].emplace_back(f.t, &f);
  }
  Contour split;
  split.closed = c.closed;
  std::vector<std::size_t> new_node(c.nodes.size());
  for (std::size_t i = 0; i < segments; ++i) {
    new_node[i] = split.nodes.size();
    split.nodes.push_back(c.nodes[i]);
    double from = 0.0;
    auto& here = cuts[i];
    std::sort(here.begin(), here.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    if (here.empty()) {
      split.segments.push_back(c.segments[i]);
      continue;
    }
    const Cubic& cubic = std::get<Cubic>(c.segments[i]);
    for (const auto& [t, f] : here) {
      split.segments.push_back(cubic.subsegment(from, t));
      out.turns.push_back({split.nodes.size(), f->tangent_in, f->tangent_out});
      split.nodes.push_back(NodeFlags{false, false});
      from = t;
    }
    split.segments.push_back(cubic.subsegment(from, 1.0));
  }
  if (!c.closed) new_node.back() = split.nodes.size(), split.nodes.push_back(c.nodes.back());
  for (const auto& [node, f] : at_source_node) {
    split.nodes[new_node[node]].smooth = false;
    out.turns.push_back({new_node[node], f->tangent_in, f->tangent_out});
  }
  out.contour = std::move(split);
  return out;
}

}  // namespace

TightTurns find_tight_turns(const Contour& source, const TightTurnLimits& limits) {
  const Contour c = with_cubics(source);
  const std::vector<Found> found = turns_of(c, limits);
  if (found.empty()) return {source, {}};
  return split_at_turns(c, found);
}

void aim_runs_at_tight_turns(ContourPlan& plan, std::span<const TightTurn> turns) {
  const auto turn_at = [&](std::size_t node) -> const TightTurn* {
    for (const TightTurn& t : turns)
      if (t.node == node) return &t;
    return nullptr;
  };
  const std::size_t count = plan.pieces.size();
  for (std::size_t i = 0; i < count; ++i) {
    SmoothRun* run = std::get_if<SmoothRun>(&plan.pieces[i]);
    if (!run || run->closed) continue;
    if (const TightTurn* t = turn_at(plan.start_nodes[i]); t && run->start.kind == RunEndKind::corner)
      run->start.tangent = t->tangent_out;
    if (i + 1 == count && !plan.closed) continue;
    if (const TightTurn* t = turn_at(plan.start_nodes[(i + 1) % count]); t && run->end.kind == RunEndKind::corner)
      run->end.tangent = t->tangent_in;
  }
}

}  // namespace gf
