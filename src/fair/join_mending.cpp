#include "fair/join_mending.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <span>
#include <variant>
#include <vector>

#include "fair/cubic_change.hpp"
#include "fair/handle_steps.hpp"
#include "fair/node_change.hpp"
#include "fair/outline_faults.hpp"
#include "fair/outline_nodes.hpp"
#include "fair/shape_traits.hpp"
#include "geom/join.hpp"
#include "geom/straight_segments.hpp"

namespace gf {

namespace {

// κ at the start of a cubic (P0, P1, P2, ·) along travel (lac-math.md §4.1 at t = 0):
// (2/3)·(P1 − P0) × (P2 − P1) / |P1 − P0|³.
double start_curvature(Vec2 p0, Vec2 p1, Vec2 p2) {
  const Vec2 h = p1 - p0;
  const double l = norm(h);
  return (2.0 / 3.0) * cross(h, p2 - p1) / (l * l * l);
}

// κ at the end of a cubic (·, P1, P2, P3) along travel: its reversal's start curvature, negated.
double end_curvature_of(Vec2 p1, Vec2 p2, Vec2 p3) { return -start_curvature(p3, p2, p1); }

// Whether κ jumps from `in` to `out` as the fairing counts it (fairing_jump_rule).
bool jumps(double in, double out, double units_per_em) {
  return curvature_jump(in, out, units_per_em, fairing_jump_rule).exceeds();
}

// A bound on how far from k a curvature that does not jump against it lies: 5 % of the larger
// side (so up to 5/95 of k), or 0.05/UPM.
double match_window(double k, double units_per_em) {
  const CurvatureJumpRule rule = fairing_jump_rule;
  return 1.001 * std::max(std::abs(k) * rule.relative / (1.0 - rule.relative), rule.absolute_em / units_per_em);
}

// How many whole steps of `step` units a handle now `now` long may take: one, and up to three
// times as long and two units, from three tenths as long, short of 0.95 of the cubic's chord.
// A range to walk, made without allocating: the searches below make one for every place tried.
class StepCounts {
 public:
  StepCounts(double now, double step, double chord) {
    while ((last_ + 1) * step < 0.95 * chord && (last_ + 1) * step <= 3.0 * now + 2.0) ++last_;
    while (first_long_ <= last_ && first_long_ * step < 0.3 * now) ++first_long_;
  }
  struct Iterator {
    int m, first_long, end;
    int operator*() const { return m; }
    Iterator& operator++() {
      m = m == 1 ? std::min(first_long, end) : m + 1;
      return *this;
    }
    bool operator!=(const Iterator& o) const { return m != o.m; }
  };
  // One step first, where there is any (last_ ≥ 1); else begin() == end().
  Iterator begin() const { return {1, first_long_, last_ + 1}; }
  Iterator end() const { return {last_ + 1, first_long_, last_ + 1}; }
  bool empty() const { return last_ < 1; }
  int last() const { return last_; }

 private:
  int last_ = 0, first_long_ = 2;
};

// The far end of a cubic beside the join: where its handle there may go (its own place first:
// whole steps of its node's direction either way where that node is smooth) and, where the
// join there holds G2 and the handle is off its node, the curvature of the segment beyond,
// which it must keep holding.
struct FarEnd {
  std::vector<Vec2> handles;
  std::optional<double> beyond;
};

FarEnd far_end(const Contour& c, const std::vector<Join>& joins, std::size_t node, Vec2 handle, bool out_handle,
               const JoinMendingLimits& limits) {
  FarEnd f{{handle}, std::nullopt};
  const Join& j = joins[node];
  const JoinFault fault = join_fault(j, {}, limits.units_per_em);
  if (fault == JoinFault::corner || fault == JoinFault::kink) return f;
  const Vec2 at = c.node_point(node);
  if (const std::optional<Vec2> step = primitive_step(handle - at)) {
    const double now = std::round(norm(handle - at) / norm(*step));
    for (int s = -limits.far_handle_reach; s <= limits.far_handle_reach; ++s)
      if (s != 0 && now + s >= 1.0) f.handles.push_back(at + *step * (now + s));
  }
  // A handle on its node (retracted) leaves the cubic no curvature there to keep: the closed
  // form of start_curvature divides by its length.
  if (fault == JoinFault::none && handle != at) f.beyond = out_handle ? j.curvature_in : j.curvature_out;
  return f;
}

// A change to the contour: control points given new places, and what they move in all.
struct Edit {
  std::size_t segment;
  int point;
  Vec2 to;
};
struct Candidate {
  double cost = 0.0;
  std::array<Edit, 10> edits{};
  int count = 0;
  void add(std::size_t segment, int point, Vec2 to) { edits[count++] = {segment, point, to}; }
};

void apply(Contour& c, const Candidate& k) {
  for (int e = 0; e < k.count; ++e)
    std::visit([&](auto& b) { b.p[k.edits[e].point] = k.edits[e].to; }, c.segments[k.edits[e].segment]);
}

// The cheapest candidates offered, at most `most` of them (a heap with the dearest on top).
class Cheapest {
 public:
  explicit Cheapest(std::size_t most) : most_(most) {}
  /// Whether a candidate that costs at least `lower_bound` could still be kept. Once `most` are
  /// kept, the dearest of them only gets cheaper, so a search may skip a whole stretch of its
  /// candidates whose shared terms already cost more: the kept ones come out exactly as
  /// without (DejaVu Sans's U+1DB4: 78 million offers at one join). The margin covers the
  /// bound summing its terms in another order than the cost.
  bool may_keep(double lower_bound) const {
    return kept_.size() < most_ || lower_bound * (1.0 - 1e-12) < kept_.front().cost;
  }
  void offer(const Candidate& k) {
    if (kept_.size() == most_ && k.cost >= kept_.front().cost) return;
    kept_.push_back(k);
    std::push_heap(kept_.begin(), kept_.end(), by_cost);
    if (kept_.size() > most_) std::pop_heap(kept_.begin(), kept_.end(), by_cost), kept_.pop_back();
  }
  /// Cheapest first.
  std::vector<Candidate> sorted() && {
    std::sort_heap(kept_.begin(), kept_.end(), by_cost);
    return std::move(kept_);
  }

 private:
  static bool by_cost(const Candidate& a, const Candidate& b) { return a.cost < b.cost; }
  std::size_t most_;
  std::vector<Candidate> kept_;
};

// One side of the join, as the search enumerates it: the curvature at the join and the two
// handles that give it (the near one, the far one).
struct Side {
  double kappa;
  Vec2 near, far;
};

// Each pair of sides whose curvatures at the join do not jump, passed to `each`.
template <class Each>
void for_each_match(const std::vector<Side>& before, std::vector<Side>& after, double units_per_em, Each&& each) {
  std::sort(after.begin(), after.end(), [](const Side& a, const Side& b) { return a.kappa < b.kappa; });
  for (const Side& a : before) {
    const double w = match_window(a.kappa, units_per_em);
    auto it = std::lower_bound(after.begin(), after.end(), a.kappa - w,
                               [](const Side& s, double k) { return s.kappa < k; });
    for (; it != after.end() && it->kappa <= a.kappa + w; ++it)
      if (!jumps(a.kappa, it->kappa, units_per_em)) each(a, *it);
  }
}

// The sides leaving `at` along d: the cubic to `to` with its near handle `steps` whole steps of
// d long and its far handle one of `end`'s, each keeping the join at `to` as it held.
void leaving_sides(Vec2 at, Vec2 d, const StepCounts& steps, Vec2 to, const FarEnd& end, double units_per_em,
                   std::vector<Side>& out) {
  for (const int m : steps)
    for (const Vec2 far : end.handles) {
      const Vec2 near = at + d * m;
      if (end.beyond && jumps(end_curvature_of(near, far, to), *end.beyond, units_per_em)) continue;
      out.push_back({start_curvature(at, near, far), near, far});
    }
}

// How much more curvature variation a changed cubic may take on (a spike a comb would show),
// of the old and of the em.
constexpr double variation_share = 2.0, variation_em = 1.0;

// Cubics `indices` of c's segments.
std::vector<Cubic> cubics_at(const Contour& c, std::span<const std::size_t> indices) {
  std::vector<Cubic> out;
  for (const std::size_t k : indices) out.push_back(std::get<Cubic>(c.segments[k]));
  return out;
}

// The cheapest of `found` whose changed cubics (`cubics`, indices into c's segments) gain
// no extremum, inflection, fold, overreach, crowded handle or spike in total, and that keeps the
// contour within the tolerance of the source. With `turning_together` the cubics redraw one
// curve, and either may turn as far as they did together; `old_jump` (|Δκ| at a join the change
// makes G2) counts as curvature variation the old cubics had.
std::optional<Contour> cheapest_within(const Contour& c, Cheapest&& found, std::span<const std::size_t> cubics,
                                       const SampledContour& sampled_source, const JoinMendingLimits& limits,
                                       bool turning_together = false, double old_jump = 0.0) {
  ShapeTraits old = shape_traits(cubics_at(c, cubics));
  old.variation += old_jump;
  if (turning_together) {
    old.turning = 0.0;
    for (const Cubic& b : cubics_at(c, cubics)) old.turning += cubic_turning(b);
  }
  for (const Candidate& k : std::move(found).sorted()) {
    Contour t = c;
    apply(t, k);
    const ShapeTraits now = shape_traits(cubics_at(t, cubics));
    if (worsens(now, old)) continue;
    if (varies_more(now, old, variation_share, variation_em, limits.units_per_em)) continue;
    if (within_distance(SampledContour(t), sampled_source, limits.tolerance_units)) return t;
  }
  return std::nullopt;
}

// The join at node k between cubics A (segment h) and B (segment k): the node a few units
// either way, its direction within most_turn_rad of its tangent, its handles whole steps of it,
// and each cubic's far handle whole steps of its own node's direction.
std::optional<Contour> mend_between_cubics(const Contour& c, const std::vector<Join>& joins, std::size_t k,
                                           const SampledContour& sampled_source, const JoinMendingLimits& limits) {
  const std::size_t n = c.segments.size(), h = (k + n - 1) % n;
  const Cubic& a = std::get<Cubic>(c.segments[h]);
  const Cubic& b = std::get<Cubic>(c.segments[k]);
  const double upm = limits.units_per_em;
  const FarEnd start = far_end(c, joins, h, a.p[1], true, limits);
  const FarEnd end = far_end(c, joins, (k + 1) % n, b.p[2], false, limits);
  const Vec2 node = a.p[3];
  const std::vector<Vec2> directions = directions_near(b.p[1] - a.p[2], limits.most_turn_rad, limits.longest_step);
  Cheapest found(limits.most_judged);
  std::vector<Side> before, after;
  for (int dx = -limits.node_reach; dx <= limits.node_reach; ++dx)
    for (int dy = -limits.node_reach; dy <= limits.node_reach; ++dy) {
      const Vec2 at = node + Vec2{double(dx), double(dy)};
      const double moved_node = distance(at, node);
      if (!found.may_keep(moved_node)) continue;
      for (const Vec2 d : directions) {
        const double step = norm(d);
        before.clear(), after.clear();
        for (const int m : StepCounts(distance(a.p[2], node), step, distance(a.p[0], at)))
          for (const Vec2 far : start.handles) {
            const Vec2 near = at - d * m;
            if (!found.may_keep(moved_node + distance(near, a.p[2]) + distance(far, a.p[1]))) continue;
            if (start.beyond && jumps(*start.beyond, start_curvature(a.p[0], far, near), upm)) continue;
            before.push_back({end_curvature_of(far, near, at), near, far});
          }
        if (before.empty()) continue;
        leaving_sides(at, d, StepCounts(distance(b.p[1], node), step, distance(at, b.p[3])), b.p[3], end, upm, after);
        for_each_match(before, after, upm, [&](const Side& x, const Side& y) {
          Candidate cand;
          cand.cost = distance(at, node) + distance(x.near, a.p[2]) + distance(x.far, a.p[1]) +
                      distance(y.near, b.p[1]) + distance(y.far, b.p[2]);
          cand.add(h, 1, x.far), cand.add(h, 2, x.near), cand.add(h, 3, at);
          cand.add(k, 0, at), cand.add(k, 1, y.near), cand.add(k, 2, y.far);
          found.offer(cand);
        });
      }
    }
  const std::array<std::size_t, 2> cubics{h, k};
  return cheapest_within(c, std::move(found), cubics, sampled_source, limits);
}

// Where the line's end may go: a few of the line's steps along it either way, and where the
// line's other end is a corner (its tangent is free to turn) also the grid points near within
// line_end_offset of the line; each with the line's primitive step from there, no component
// over longest_line_step.
std::vector<std::pair<Vec2, Vec2>> line_ends(const Contour& c, const std::vector<Join>& joins, std::size_t line,
                                             const JoinMendingLimits& limits) {
  const Line& l = std::get<Line>(c.segments[line]);
  const Vec2 from = l.p[0], to = l.p[1];
  std::vector<std::pair<Vec2, Vec2>> out;
  const std::optional<Vec2> along = primitive_step(to - from);
  if (!along) return out;
  const auto offer = [&](Vec2 end) {
    const std::optional<Vec2> d = primitive_step(end - from);
    if (d && std::max(std::abs(d->x), std::abs(d->y)) <= limits.longest_line_step) out.push_back({end, *d});
  };
  for (int s = -limits.line_slide_steps; s <= limits.line_slide_steps; ++s) offer(to + *along * s);
  if (join_fault(joins[line], {}, limits.units_per_em) != JoinFault::corner) return out;
  for (int dx = -limits.line_end_reach; dx <= limits.line_end_reach; ++dx)
    for (int dy = -limits.line_end_reach; dy <= limits.line_end_reach; ++dy) {
      const Vec2 end = to + Vec2{double(dx), double(dy)};
      const double off = std::abs(cross(*along, end - from)) / norm(*along);
      if (off > 0.0 && off <= limits.line_end_offset) offer(end);  // those on the line are slides
    }
  return out;
}

// The join at node k where line h meets cubic C (segment k), followed by cubic D (segment
// j) at smooth node M: the line's end (line_ends), C's near handle whole steps of the line's
// step along it, M a few units either way with its direction near its tangent and its
// handles whole steps of it, and D's far handle whole steps of its own node's direction.
std::optional<Contour> mend_line_join(const Contour& c, const std::vector<Join>& joins, std::size_t k,
                                      const SampledContour& sampled_source, const JoinMendingLimits& limits) {
  const std::size_t n = c.segments.size(), h = (k + n - 1) % n, j = (k + 1) % n;
  const double upm = limits.units_per_em;
  if (n < 4 || !std::holds_alternative<Cubic>(c.segments[j])) return std::nullopt;
  const JoinFault at_m = join_fault(joins[j], {}, upm);
  if (at_m == JoinFault::corner || at_m == JoinFault::kink) return std::nullopt;
  const Vec2 join = std::get<Line>(c.segments[h]).p[1];
  const Cubic& cc = std::get<Cubic>(c.segments[k]);
  const Cubic& dc = std::get<Cubic>(c.segments[j]);
  const FarEnd end = far_end(c, joins, (j + 1) % n, dc.p[2], false, limits);
  const Vec2 m = cc.p[3];
  const std::vector<Vec2> directions = directions_near(dc.p[1] - cc.p[2], limits.most_turn_rad, limits.longest_step);
  Cheapest found(limits.most_judged);
  std::vector<Side> before, after;
  for (const auto& [at, line_step] : line_ends(c, joins, h, limits)) {
    const double line_step_length = norm(line_step);
    for (int dx = -limits.far_node_reach; dx <= limits.far_node_reach; ++dx)
      for (int dy = -limits.far_node_reach; dy <= limits.far_node_reach; ++dy) {
        const Vec2 mid = m + Vec2{double(dx), double(dy)};
        const double moved_ends = distance(at, join) + distance(mid, m);
        if (!found.may_keep(moved_ends)) continue;
        const double chord = distance(at, mid);
        const StepCounts line_steps(distance(cc.p[1], join), line_step_length, chord);
        // κ at the join, C's near handle s steps L along the line, is (2/3)·L × (C2 − N) / (s²|L|³)
        // (start_curvature): flat enough only where the far handle C2 lies this near the line.
        const double longest = line_steps.last();
        const double reach = 1.5 * fairing_jump_rule.absolute_em / upm * longest * longest * std::pow(line_step_length, 3);
        const double off_line = cross(line_step, mid - at);
        for (const Vec2 d : directions) {
          const double step = norm(d), across = cross(line_step, d);
          before.clear(), after.clear();
          for (const int t : StepCounts(distance(cc.p[2], m), step, chord)) {
            if (std::abs(off_line - t * across) > reach) continue;
            const Vec2 near_mid = mid - d * t;
            for (const int s : line_steps) {
              const Vec2 near_line = at + line_step * s;
              if (!found.may_keep(moved_ends + distance(near_line, cc.p[1]) + distance(near_mid, cc.p[2]))) continue;
              if (jumps(0.0, start_curvature(at, near_line, near_mid), upm)) continue;
              before.push_back({end_curvature_of(near_line, near_mid, mid), near_mid, near_line});
            }
          }
          if (before.empty()) continue;
          leaving_sides(mid, d, StepCounts(distance(dc.p[1], m), step, distance(mid, dc.p[3])), dc.p[3], end, upm, after);
          for_each_match(before, after, upm, [&](const Side& x, const Side& y) {
            Candidate cand;
            cand.cost = distance(at, join) + distance(x.far, cc.p[1]) + distance(x.near, cc.p[2]) + distance(mid, m) +
                        distance(y.near, dc.p[1]) + distance(y.far, dc.p[2]);
            cand.add(h, 1, at);
            cand.add(k, 0, at), cand.add(k, 1, x.far), cand.add(k, 2, x.near), cand.add(k, 3, mid);
            cand.add(j, 0, mid), cand.add(j, 1, y.near), cand.add(j, 2, y.far);
            found.offer(cand);
          });
        }
      }
  }
  const std::array<std::size_t, 2> cubics{k, j};
  return cheapest_within(c, std::move(found), cubics, sampled_source, limits);
}

// The whole steps of `step` from `origin` to p, where p lies on that line at one (its grid points
// are exactly those: `step` is primitive); none otherwise.
std::optional<int> steps_along(Vec2 origin, Vec2 step, Vec2 p) {
  if (cross(p - origin, step) != 0.0) return std::nullopt;
  return static_cast<int>(whole_steps(origin, p, step, 1.0));
}

// The grid points within a unit of the curve the cubics draw, each with the curve's tangent
// where it passes nearest (of 48 samples a cubic).
std::vector<std::pair<Vec2, Vec2>> grid_points_along(std::span<const Cubic> cubics) {
  struct Near {
    Vec2 point, tangent;
    double off;
  };
  std::vector<Near> all;
  constexpr int samples = 48;
  for (const Cubic& c : cubics) {
    const auto velocity = c.hodograph();
    for (int i = 0; i <= samples; ++i) {
      const double t = static_cast<double>(i) / samples;
      const Vec2 p = c.point_at(t), tangent = velocity.point_at(t);
      if (norm(tangent) == 0.0) continue;
      for (int dx = -1; dx <= 1; ++dx)
        for (int dy = -1; dy <= 1; ++dy) {
          const Vec2 g = nearest_grid_point(p) + Vec2{double(dx), double(dy)};
          all.push_back({g, tangent, distance(g, p)});
        }
    }
  }
  const auto by_place = [](const Near& a, const Near& b) {
    if (a.point.x != b.point.x) return a.point.x < b.point.x;
    return a.point.y != b.point.y ? a.point.y < b.point.y : a.off < b.off;
  };
  std::sort(all.begin(), all.end(), by_place);
  std::vector<std::pair<Vec2, Vec2>> out;
  for (const Near& e : all)
    if (out.empty() || out.back().first != e.point) out.push_back({e.point, e.tangent});
  return out;
}

// c with its cubic k split at its middle into two (the curve unchanged), their node smooth.
Contour split_at_middle(const Contour& c, std::size_t k) {
  Contour w = c;
  const std::array<Cubic, 2> halves = std::get<Cubic>(c.segments[k]).split(0.5);
  w.segments[k] = halves[0];
  w.segments.insert(w.segments.begin() + static_cast<std::ptrdiff_t>(k) + 1, halves[1]);
  if (w.nodes.size() == c.segments.size())
    w.nodes.insert(w.nodes.begin() + static_cast<std::ptrdiff_t>(k) + 1, NodeFlags{false, true});
  return w;
}

// The curve between two lines (line h, cubic k, cubic k + 1, then a line; a lone cubic split at
// its middle first) whose join with line h jumps, redrawn as two cubics that leave and reach
// the lines with κ = 0 exactly. The node M between them goes to any grid point within a unit of
// the curve, its direction near the curve's tangent there, where its tangent line crosses both
// lines at grid points: M's handles there lie on the lines, and a cubic whose far handle lies
// on the line it leaves has κ = 0 there whatever its lengths ((P1 − P0) × (P2 − P1) = 0). The
// lines' ends and the cubics' other handles are whole steps of the lines between, the second
// line's end up to its far end (the line then goes), and κ at M matches from both sides.
// TeX Gyre Pagella's W: a (2, 7) leg into a turn of 68° in 45 units, κ·UPM 10 where it leaves
// the leg; the rounding passes move a node two or three units, and no such place reaches the
// leg's grid points.
std::optional<Contour> mend_curve_between_lines(const Contour& c, std::size_t k, const SampledContour& sampled_source,
                                                const JoinMendingLimits& limits) {
  std::size_t n = c.segments.size(), h = (k + n - 1) % n;
  if (n < 4 || !std::holds_alternative<Line>(c.segments[h]) || !std::holds_alternative<Cubic>(c.segments[k]))
    return std::nullopt;
  const bool lone = std::holds_alternative<Line>(c.segments[(k + 1) % n]);
  const Contour w = lone ? split_at_middle(c, k) : c;
  n = w.segments.size(), h = (k + n - 1) % n;  // the line in w: the last where k = 0
  const bool flagged = w.nodes.size() == n;  // the nodes' flags, kept in step with the segments'
  const std::size_t j = (k + 1) % n, l = (k + 2) % n;
  if (!std::holds_alternative<Cubic>(w.segments[j]) || !std::holds_alternative<Line>(w.segments[l]) || l == h)
    return std::nullopt;
  const Line& first = std::get<Line>(w.segments[h]);
  const Line& second = std::get<Line>(w.segments[l]);
  const Vec2 a1 = first.p[0], join = first.p[1], q0 = second.p[0], a2 = second.p[1];
  const std::optional<Vec2> u = primitive_step(join - a1), v = primitive_step(a2 - q0);
  if (!u || !v) return std::nullopt;
  const std::array<Cubic, 2> old{std::get<Cubic>(w.segments[k]), std::get<Cubic>(w.segments[j])};
  const Vec2 old_m = old[0].p[3];
  const double reach = distance(join, q0);  // the curve's chord: how far its handles reach
  const double upm = limits.units_per_em;
  // The lines' ends a few of their steps either way along them (the first line keeps a step);
  // in steps from the first line's start and back from the second line's end.
  const int slide = limits.line_slide_steps;
  const std::optional<int> join_steps = steps_along(a1, *u, join), q0_steps = steps_along(a2, *v * -1.0, q0);
  if (!join_steps || !q0_steps) return std::nullopt;  // off the grid
  Cheapest found(limits.most_judged);
  for (const auto& [m, tangent] : grid_points_along(old))
    for (const Vec2 d : directions_near(tangent, limits.most_turn_rad, limits.longest_step)) {
      // M's handles exactly on the lines: its in-handle on the first, its out-handle on the second.
      const std::optional<double> back = whole_steps_to_line(m, d, -1.0, a1, *u);
      const std::optional<double> ahead = whole_steps_to_line(m, d, 1.0, a2, *v);
      if (!back || !ahead) continue;
      const Vec2 near_first = m - d * *back, near_second = m + d * *ahead;
      if (distance(near_first, m) > reach || distance(near_second, m) > reach) continue;
      const double moved_middle =
          distance(m, old_m) + distance(near_first, old[0].p[2]) + distance(near_second, old[1].p[1]);
      if (!found.may_keep(moved_middle)) continue;
      const int s2 = static_cast<int>(whole_steps(a1, near_first, *u, 1.0));
      const int r2 = static_cast<int>(whole_steps(a2, near_second, *v, -1.0));
      const int s0_first = std::max(1, *join_steps - slide), s0_last = std::min(*join_steps + slide, s2 - 2);
      const int r0_first = std::max(0, *q0_steps - slide), r0_last = std::min(*q0_steps + slide, r2 - 2);
      if (s0_first > s0_last || r0_first > r0_last) continue;
      // κ at M is linear in how far each cubic's other handle lies from M's along its line:
      // α·k1 from the first cubic (its P1 α steps behind P2), β·k2 from the second.
      const double k1 = end_curvature_of(near_first - *u, near_first, m);
      const double k2 = start_curvature(m, near_second, near_second + *v);
      if (k1 == 0.0 || k2 == 0.0) continue;
      for (int alpha = 1; alpha <= s2 - 1 - s0_first; ++alpha) {
        const double ka = alpha * k1;
        const double centre = std::round(ka / k2);
        const Vec2 p1 = near_first - *u * alpha;
        const double moved_first = moved_middle + distance(p1, old[0].p[1]);
        if (!found.may_keep(moved_first)) continue;
        for (int beta = static_cast<int>(centre) - 1; beta <= static_cast<int>(centre) + 1; ++beta) {
          if (beta < 1 || beta > r2 - 1 - r0_first || jumps(ka, beta * k2, upm)) continue;
          const Vec2 p2 = near_second + *v * beta;
          const double moved_handles = moved_first + distance(p2, old[1].p[2]);
          if (!found.may_keep(moved_handles)) continue;
          for (int s0 = s0_first; s0 <= std::min(s0_last, s2 - alpha - 1); ++s0)
            for (int r0 = r0_first; r0 <= std::min(r0_last, r2 - beta - 1); ++r0) {
              const Vec2 p0 = a1 + *u * s0, q = a2 - *v * r0;
              if (!found.may_keep(moved_handles + distance(p0, join) + distance(q, q0))) continue;
              Candidate cand;
              cand.cost = distance(p0, join) + distance(m, old_m) + distance(q, q0) + distance(p1, old[0].p[1]) +
                          distance(near_first, old[0].p[2]) + distance(near_second, old[1].p[1]) +
                          distance(p2, old[1].p[2]);
              cand.add(h, 1, p0);
              cand.add(k, 0, p0), cand.add(k, 1, p1), cand.add(k, 2, near_first), cand.add(k, 3, m);
              cand.add(j, 0, m), cand.add(j, 1, near_second), cand.add(j, 2, p2), cand.add(j, 3, q);
              cand.add(l, 0, q);
              found.offer(cand);
            }
        }
      }
    }
  const std::array<std::size_t, 2> cubics{k, j};
  std::optional<Contour> mended = cheapest_within(w, std::move(found), cubics, sampled_source, limits, true);
  // The second line's end at its far end: the line goes, its far node the corner it was.
  if (mended && std::get<Line>(mended->segments[l]).p[0] == a2) {
    mended->segments.erase(mended->segments.begin() + static_cast<std::ptrdiff_t>(l));
    if (flagged) mended->nodes.erase(mended->nodes.begin() + static_cast<std::ptrdiff_t>(l));
  }
  return mended;
}

// The curve from a line into a smooth node E (line h, cubic k to E, then a cubic), whose join
// with the line jumps, redrawn as two cubics: the first leaves the line with κ = 0 exactly, the
// second reaches E along E's direction with the curvature the cubic after E has there (that
// cubic's handle at E whole steps of E's direction, the join at its far end held as it was).
// Their node M goes to any grid point within a unit of the curve, its direction near the
// curve's tangent there, where its tangent line crosses the line at a grid point: M's in-handle
// on the line, so κ = 0 where the first cubic leaves it whatever its lengths. The first cubic's
// other handle is whole steps of the line, its start (the line's end) as near the join as that
// handle leaves room for, anywhere back along the line: the cubic runs on along the line (its
// first three points on it), so the outline hardly moves. The second cubic's handles are whole
// steps of M's and E's directions, and κ at M matches from both sides. Quicksand's x: its
// (−10, −13) leg, carried on, crosses the baseline extremum's level off the grid, so no cubic
// from the leg into the extremum left it with κ = 0 (κ·UPM 13 against 0); the first cubic now
// takes four of the leg's 16-unit steps.
std::optional<Contour> mend_curve_from_line(const Contour& c, const std::vector<Join>& joins, std::size_t k,
                                            const SampledContour& sampled_source, const JoinMendingLimits& limits) {
  std::size_t n = c.segments.size(), h = (k + n - 1) % n;
  if (n < 4 || !std::holds_alternative<Line>(c.segments[h]) || !std::holds_alternative<Cubic>(c.segments[k]) ||
      !std::holds_alternative<Cubic>(c.segments[(k + 1) % n]))
    return std::nullopt;
  if (join_fault(joins[(k + 1) % n], {}, limits.units_per_em) != JoinFault::none) return std::nullopt;
  const Contour w = split_at_middle(c, k);
  n = w.segments.size(), h = (k + n - 1) % n;  // the line in w: the last where k = 0
  const std::size_t j = (k + 1) % n, after = (k + 2) % n;
  const Line& line = std::get<Line>(w.segments[h]);
  const Cubic& next = std::get<Cubic>(w.segments[after]);
  const Vec2 a1 = line.p[0], join = line.p[1], e = next.p[0];
  const std::array<Cubic, 2> old{std::get<Cubic>(w.segments[k]), std::get<Cubic>(w.segments[j])};
  // E's direction from the cubic as it was: the halves' handles lie off the grid.
  const std::optional<Vec2> u = primitive_step(join - a1), de = primitive_step(e - std::get<Cubic>(c.segments[k]).p[2]);
  const std::optional<int> join_steps = u ? steps_along(a1, *u, join) : std::nullopt;
  if (!u || !de || !join_steps || next.p[1] == e) return std::nullopt;
  const double upm = limits.units_per_em, reach = distance(join, e);
  // The next cubic's handle at E, and its curvature there, in order of that curvature.
  const FarEnd beyond_next = far_end(w, joins_of(w), (after + 1) % n, next.p[2], false, limits);
  std::vector<std::pair<double, Vec2>> leaving_e;
  for (const int steps : StepCounts(distance(e, next.p[1]), norm(*de), distance(e, next.p[3]))) {
    const Vec2 handle = e + *de * steps;
    if (beyond_next.beyond && jumps(end_curvature_of(handle, next.p[2], next.p[3]), *beyond_next.beyond, upm)) continue;
    leaving_e.emplace_back(start_curvature(e, handle, next.p[2]), handle);
  }
  std::sort(leaving_e.begin(), leaving_e.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  if (leaving_e.empty()) return std::nullopt;
  Cheapest found(limits.most_judged);
  for (const auto& [m, tangent] : grid_points_along(old)) {
    if (m == e) continue;
    const double chord = distance(m, e);
    for (const Vec2 d : directions_near(tangent, limits.most_turn_rad, limits.longest_step)) {
      const std::optional<double> back = whole_steps_to_line(m, d, -1.0, a1, *u);
      if (!back) continue;
      const Vec2 near_line = m - d * *back;
      if (distance(near_line, m) > reach) continue;
      const double moved_middle = distance(near_line, old[0].p[2]) + distance(m, old[0].p[3]);
      if (!found.may_keep(moved_middle)) continue;
      const int s2 = static_cast<int>(whole_steps(a1, near_line, *u, 1.0));  // near_line's steps along the line
      const int s0_last = std::min(*join_steps + limits.line_slide_steps, s2 - 2);
      const double k1 = end_curvature_of(near_line - *u, near_line, m);  // κ at M per step of the first's P1
      if (s0_last < 1 || k1 == 0.0) continue;
      const StepCounts into_e(distance(old[1].p[2], e), norm(*de), chord);
      if (into_e.empty()) continue;
      for (const int b : StepCounts(distance(old[1].p[0], old[1].p[1]), norm(d), chord)) {
        const Vec2 near_m = m + d * b;
        const double moved_m = moved_middle + distance(near_m, old[1].p[1]);
        if (!found.may_keep(moved_m)) continue;
        // κ arriving at E runs as 1/a² over E's handle's whole steps a ((2/3)·(dₑ × (N − E)) /
        // (a²|dₑ|³), N the handle at M), so between its values at the fewest and the most: where
        // no curvature leaving E lies within a match window of those, none of the a matches.
        const double fewest = end_curvature_of(near_m, e - *de, e);  // one step, the fewest
        const double most = end_curvature_of(near_m, e - *de * into_e.last(), e);
        const double margin = std::max(match_window(fewest, upm), match_window(most, upm)) +
                              1e-9 * std::max(std::abs(fewest), std::abs(most));
        if (std::max(fewest, most) + margin < leaving_e.front().first ||
            std::min(fewest, most) - margin > leaving_e.back().first)
          continue;
        for (const int a : into_e) {
          const Vec2 near_e = e - *de * a;
          if (!found.may_keep(moved_m + distance(near_e, old[1].p[2]))) continue;
          const double arriving = end_curvature_of(near_m, near_e, e), window = match_window(arriving, upm);
          auto it = std::lower_bound(leaving_e.begin(), leaving_e.end(), arriving - window,
                                     [](const auto& x, double k) { return x.first < k; });
          // Most steps a of a hopeless join meet no curvature leaving E: κ at M only where one does.
          if (it == leaving_e.end() || it->first > arriving + window) continue;
          const double km = start_curvature(m, near_m, near_e);
          const int centre = static_cast<int>(std::round(km / k1));
          for (; it != leaving_e.end() && it->first <= arriving + window; ++it) {
            const auto& [k_e, handle_e] = *it;
            if (jumps(arriving, k_e, upm)) continue;
            for (int alpha = std::max(1, centre - 1); alpha <= centre + 1; ++alpha) {
              const int s0 = std::min(s0_last, s2 - alpha - 1);
              if (s0 < 1 || jumps(alpha * k1, km, upm)) continue;
              const Vec2 p0 = a1 + *u * s0, p1 = near_line - *u * alpha;
              Candidate cand;
              cand.cost = distance(p0, join) + distance(p1, old[0].p[1]) + distance(near_line, old[0].p[2]) +
                          distance(m, old[0].p[3]) + distance(near_m, old[1].p[1]) + distance(near_e, old[1].p[2]) +
                          distance(handle_e, next.p[1]);
              cand.add(h, 1, p0);
              cand.add(k, 0, p0), cand.add(k, 1, p1), cand.add(k, 2, near_line), cand.add(k, 3, m);
              cand.add(j, 0, m), cand.add(j, 1, near_m), cand.add(j, 2, near_e);
              cand.add(after, 1, handle_e);
              found.offer(cand);
            }
          }
        }
      }
    }
  }
  // The jump the old curve left at the line counts as variation it had: the new one has none there.
  const double old_jump = std::abs(start_curvature(join, old[0].p[1], old[0].p[2]));
  const std::array<std::size_t, 3> cubics{k, j, after};
  return cheapest_within(w, std::move(found), cubics, sampled_source, limits, true, old_jump);
}

// The closed contour walked the other way: its segment i is segment n − 1 − i reversed, and
// its node i node (n − i) mod n.
Contour walked_back(const Contour& c) {
  Contour r = c;
  const std::size_t n = c.segments.size();
  for (std::size_t i = 0; i < n; ++i) {
    r.segments[i] = std::visit([](const auto& b) { return Segment{b.reversed()}; }, c.segments[n - 1 - i]);
    r.nodes[i] = c.nodes[(n - i) % n];
  }
  return r;
}

// The mend for the join at node k, by the kinds of segment either side of it.
std::optional<Contour> mend_join(const Contour& c, const std::vector<Join>& joins, std::size_t k,
                                 const SampledContour& sampled_source, const JoinMendingLimits& limits) {
  const std::size_t n = c.segments.size();
  const Segment& in = c.segments[(k + n - 1) % n];
  const Segment& out = c.segments[k];
  if (std::holds_alternative<Cubic>(in) && std::holds_alternative<Cubic>(out))
    return mend_between_cubics(c, joins, k, sampled_source, limits);
  if (std::holds_alternative<Line>(in) && std::holds_alternative<Cubic>(out)) {
    std::optional<Contour> done = mend_line_join(c, joins, k, sampled_source, limits);
    if (!done && limits.curves_between_lines) done = mend_curve_between_lines(c, k, sampled_source, limits);
    if (!done && limits.curves_between_lines) done = mend_curve_from_line(c, joins, k, sampled_source, limits);
    return done;
  }
  if (std::holds_alternative<Cubic>(in) && std::holds_alternative<Line>(out)) {
    const Contour back = walked_back(c);
    const std::optional<Contour> mended_back = mend_join(back, joins_of(back), (n - k) % n, sampled_source, limits);
    if (mended_back) return walked_back(*mended_back);
  }
  return std::nullopt;
}

// c with the straight cubics either side of node k written as their lines, each joined with the
// straight segments it runs on along (with_straight_runs_joined), and where node k went; none
// where neither side is a straight cubic.
std::optional<std::pair<Contour, std::size_t>> with_lines_beside(const Contour& c, std::size_t k) {
  const std::size_t n = c.segments.size();
  Contour lined = c;
  bool any = false;
  for (const std::size_t i : {(k + n - 1) % n, k}) {
    const Cubic* b = std::get_if<Cubic>(&c.segments[i]);
    if (b && is_straight(*b)) lined.segments[i] = Line{b->p[0], b->p[3]}, any = true;
  }
  if (!any) return std::nullopt;
  if (lined.nodes.size() != n) return std::pair{std::move(lined), k};  // no flags to join by
  Contour joined = with_straight_runs_joined(lined);
  const Vec2 at = start_point(c.segments[k]);
  for (std::size_t i = 0; i < joined.segments.size(); ++i)
    if (start_point(joined.segments[i]) == at) return std::pair{std::move(joined), i};
  return std::nullopt;
}

}  // namespace

int mend_jumping_joins(Contour& rounded, const SampledContour& sampled_source, const JoinMendingLimits& limits) {
  if (!rounded.closed || rounded.segments.size() < 3) return 0;
  int mended = 0;
  std::vector<Join> joins = joins_of(rounded);
  for (std::size_t k = 0; k < rounded.segments.size(); ++k) {
    const JoinFault fault = join_fault(joins[k], {}, limits.units_per_em);
    if (fault != JoinFault::jump && fault != JoinFault::kink) continue;
    std::optional<Contour> done = mend_join(rounded, joins, k, sampled_source, limits);
    // A straight cubic beside the join is a line to the mends, one with the line it runs on
    // along: rounding leaves a stem's last stretch so, and joins the two only at the end
    // (with_straight_runs_joined). Comic Neue's d: its stem's (385, 47) to (385, 27) a straight
    // cubic into its round end, κ·UPM 20.7 where the end leaves it, which only the mends from a
    // line reach.
    std::size_t mended_at = k;  // where the join is in the contour mended
    if (!done)
      if (const auto lined = with_lines_beside(rounded, k)) {
        const auto& [c, at] = *lined;
        done = mend_join(c, joins_of(c), at, sampled_source, limits);
        mended_at = at;
      }
    if (!done) continue;
    rounded.nodes = std::move(done->nodes);
    rounded.segments = std::move(done->segments);
    joins = joins_of(rounded);
    ++mended;
    k = mended_at;  // on from there
  }
  return mended;
}

MendedJoins mend_where_fewer_faults(Contour& rounded, const OutlineFaults& faults, const FaultCounter& counter,
                                    const SampledContour& sampled_source, const JoinMendingLimits& limits) {
  if (faults.at_smooth_joins() == 0) return {faults, 0};
  Contour mended = rounded;
  const int joins = mend_jumping_joins(mended, sampled_source, limits);
  if (joins == 0) return {faults, 0};
  const OutlineFaults mended_faults = counter.count(mended);
  if (!fewer_faults(mended_faults, faults)) return {faults, 0};
  rounded = std::move(mended);
  return {mended_faults, joins};
}

}  // namespace gf
