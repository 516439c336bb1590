#include "fair/spare_nodes.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <span>
#include <utility>

#include "fair/cubic_change.hpp"
#include "fair/outline_joins.hpp"
#include "fair/shape_traits.hpp"
#include "geom/g2_handle_fit.hpp"
#include "geom/tangent_fit.hpp"

namespace gf {

namespace {

constexpr double flat_em = 0.05;       // κ·UPM under which a node counts as an inflection
// Curvature variation the changed cubics may take on: three times theirs, and 0.05 per em.
// A few cubics' variation is a small part of their glyph's, whose bar (text: at most 0.95 of
// the source's, the median glyph) the fonts meet with room (0.51–0.92 of the source's). a–z
// A–Z of 44 text fonts, against a quarter more: nodes 45,367 → 45,208, g2-jumps 5 → 2
// (Junicode's B and M: their fewer, longer cubics round G2). On the three fonts failing the
// nodes bar, twice theirs took fewer nodes away, and five times no more than three.
constexpr double variation_share = 3.0, variation_em = 0.05;
constexpr int samples_per_cubic = 32;  // of the outline they are fitted to
// A run fitted again whole (without_run_spares): how far its nodes may slide, of the shortest
// chord between them, and how far a round of the fit may move them (G2FitFreedom::step_share).
// Half that chord, not a quarter: Junicode's serifs (a–z A–Z nodes 1.532× → 1.521× of the
// source's, and no other text font but Linux Biolinum, one node); a whole chord no further.
constexpr double slide_share = 0.5, fit_step_share = 0.01;
constexpr std::size_t stretch_points = 48;  // of the source, each cubic of the run is fitted to

std::size_t after(std::size_t k, std::size_t n) { return (k + 1) % n; }
std::size_t before(std::size_t k, std::size_t n) { return (k + n - 1) % n; }

// Whether node k lies between two cubics whose curvature there changes sign or is flat.
bool inflection_at(const std::vector<OutlineNode>& nodes, std::size_t k, double units_per_em) {
  const auto [in, out] = curvatures_at(nodes, k);
  return in * out <= 0.0 || std::min(std::abs(in), std::abs(out)) * units_per_em < flat_em;
}

// Whether node k couples the cubics either side into one run: smooth, between two cubics, no
// inflection. A window or a run extends across it.
bool couples(const OutlineJoins& joins, std::size_t k, double units_per_em) {
  return joins.joins_cubics(k) && !inflection_at(joins.nodes, k, units_per_em);
}

// The curvature a window of cubics from node `first` must meet there: none at a corner or an
// open contour's end, 0 after a line, else the arriving cubic's (outside the window).
std::optional<double> bound_before(const OutlineJoins& joins, std::size_t first) {
  if (!joins.nodes[first].smooth || !joins.interior(first)) return std::nullopt;
  const std::size_t h = before(first, joins.size());
  return joins.is_cubic(h) ? node_curvature(outline_cubic(joins.nodes, h), SegmentEnd::end) : 0.0;
}
std::optional<double> bound_after(const OutlineJoins& joins, std::size_t last) {
  if (!joins.nodes[last].smooth || !joins.interior(last)) return std::nullopt;
  return joins.is_cubic(last) ? node_curvature(outline_cubic(joins.nodes, last), SegmentEnd::start) : 0.0;
}

std::vector<Vec2> samples_of(const Cubic& c) {
  std::vector<Vec2> out;
  for (int i = 0; i <= samples_per_cubic; ++i) out.push_back(c.point_at(static_cast<double>(i) / samples_per_cubic));
  return out;
}

// The window around spare node k: the segments (node indices where each cubic starts) whose
// handles are fitted again, the merged pair counted by its first; the merged cubic's place
// among them; the node the window ends at.
struct Window {
  std::vector<std::size_t> starts;
  std::size_t merged = 0;
  std::size_t last_node = 0;
};

Window window_at(const OutlineJoins& joins, std::size_t k, double units_per_em) {
  const std::size_t n = joins.size(), l = before(k, n), r = after(k, n);
  Window w{{l}, 0, r};
  // Across a smooth node between cubics that is no inflection, the cubic beyond joins in.
  if (before(l, n) != r && couples(joins, l, units_per_em))
    w.starts.insert(w.starts.begin(), before(l, n)), w.merged = 1;
  if (after(r, n) != w.starts.front() && couples(joins, r, units_per_em))
    w.starts.push_back(r), w.last_node = after(r, n);
  return w;
}

}  // namespace

bool is_spare_node(const std::vector<OutlineNode>& nodes, bool closed, std::size_t k, double units_per_em) {
  if (nodes.size() < 4 || !OutlineJoins{nodes, closed}.joins_cubics(k)) return false;
  const Vec2 t = *nodes[k].out_handle - nodes[k].point;
  const double length = norm(t);
  if (!(std::abs(t.x) > 1e-9 * length) || !(std::abs(t.y) > 1e-9 * length)) return false;
  return !inflection_at(nodes, k, units_per_em);
}

namespace {

// Turns tried at an inflection node, degrees: the least first. Up to 12° removed no more
// (EB Garamond's a–z A–Z, every fairing turning: nodes 1.377× → 1.376× of the source's).
constexpr std::array<double, 9> turn_degrees{0.0, 0.5, -0.5, 1.0, -1.0, 2.0, -2.0, 4.0, -4.0};

// The tangent at `node` turned by `radians`.
struct TangentTurn {
  std::size_t node = 0;
  double radians = 0.0;
};

// The cubics of a window as they are (the merged pair as its two) and fitted again, and the
// nodes each fitted cubic runs between.
struct Refit {
  std::vector<Cubic> old, now;
  std::vector<std::size_t> starts, ends;
};

// Window w's handles fitted again to its outline, κ `start` and `end` at its ends where given
// and continuous inside, the pair across `spare` (where given) drawn as one cubic, and the
// tangent turned where `turn` says. The merged cubic's handles, and every cubic's in a window
// with a turn, start from one cubic's least-squares fit to its points; the others' from where
// they are.
std::optional<Refit> refit(const std::vector<OutlineNode>& nodes, const Window& w, std::optional<std::size_t> spare,
                           std::optional<double> start, std::optional<double> end, std::optional<TangentTurn> turn) {
  const std::size_t n = nodes.size();
  const auto turned = [&](Vec2 t) { return direction_of(angle_of(t) + turn->radians); };
  std::vector<CubicFrame> frames;
  std::vector<std::vector<Vec2>> points;
  std::vector<std::pair<double, double>> initial;
  Refit out;
  for (std::size_t j = 0; j < w.starts.size(); ++j) {
    const std::size_t s = w.starts[j];
    const bool pair = spare && j == w.merged;
    const std::size_t e = pair ? after(*spare, n) : after(s, n);
    const Cubic c = outline_cubic(nodes, s);
    out.old.push_back(c), out.starts.push_back(s), out.ends.push_back(e);
    const std::optional<CubicFrame> a = frame_of(c);
    std::optional<CubicFrame> b = a;
    std::vector<Vec2> pts = samples_of(c);
    if (pair) {
      const Cubic second = outline_cubic(nodes, *spare);
      out.old.push_back(second);
      b = frame_of(second);
      const std::vector<Vec2> rest = samples_of(second);
      pts.insert(pts.end(), rest.begin() + 1, rest.end());
    }
    if (!a || !b) return std::nullopt;
    CubicFrame f{a->start, a->start_tangent, b->end, b->end_tangent};
    if (turn && s == turn->node) f.start_tangent = turned(f.start_tangent);
    if (turn && e == turn->node) f.end_tangent = turned(f.end_tangent);
    std::pair<double, double> lengths{distance(c.p[0], c.p[1]), distance(c.p[2], c.p[3])};
    if (pair || turn) {
      const double chord = distance(f.start, f.end);
      lengths = {chord / 3.0, chord / 3.0};
      if (const std::optional<Cubic> fit = fit_cubic_with_end_tangents(f.start, f.start_tangent, f.end, f.end_tangent, pts))
        lengths = {distance(fit->p[0], fit->p[1]), distance(fit->p[2], fit->p[3])};
    }
    frames.push_back(f), points.push_back(std::move(pts)), initial.push_back(lengths);
  }
  std::optional<std::vector<Cubic>> fitted = fit_g2_handles(frames, points, initial, start, end);
  if (!fitted) return std::nullopt;
  out.now = std::move(*fitted);
  return out;
}

// The window past inflection node t, away from window `w` around spare node k (forward: t is
// where w ends): the cubic there, and the one beyond it across a smooth node that is no
// inflection; none where it would reach into w.
std::optional<Window> window_beyond(const OutlineJoins& joins, const Window& w, std::size_t k, std::size_t t,
                                    bool forward, double units_per_em) {
  const std::size_t n = joins.size();
  const auto in_w = [&](std::size_t s) {
    return s == k || std::find(w.starts.begin(), w.starts.end(), s) != w.starts.end();
  };
  Window b;
  if (forward) {
    b.starts = {t}, b.last_node = after(t, n);
    if (couples(joins, b.last_node, units_per_em) && !in_w(b.last_node))
      b.starts.push_back(b.last_node), b.last_node = after(b.last_node, n);
  } else {
    b.starts = {before(t, n)}, b.last_node = t;
    if (couples(joins, b.starts.front(), units_per_em) && !in_w(before(b.starts.front(), n)))
      b.starts.insert(b.starts.begin(), before(b.starts.front(), n));
  }
  if (std::any_of(b.starts.begin(), b.starts.end(), in_w)) return std::nullopt;
  return b;
}

// The outline with the refitted cubics in and spare node k (merged into the first refit's
// cubic `merged`) out, where the limits allow.
std::optional<std::vector<OutlineNode>> with_refits(const std::vector<OutlineNode>& nodes, bool closed, std::size_t k,
                                                    std::span<const Refit> refits, std::size_t merged,
                                                    const SampledContour& sampled_source, const SpareNodeLimits& limits) {
  std::vector<Cubic> old, now;
  for (const Refit& r : refits)
    old.insert(old.end(), r.old.begin(), r.old.end()), now.insert(now.end(), r.now.begin(), r.now.end());
  ShapeTraits was = shape_traits(old);
  // The merged cubic turns as its two did together.
  const std::vector<Cubic>& first = refits.front().old;
  was.turning = std::max(was.turning, cubic_turning(first[merged]) + cubic_turning(first[merged + 1]));
  const ShapeTraits is = shape_traits(now);
  if (worsens(is, was) || varies_more(is, was, variation_share, variation_em, limits.units_per_em)) return std::nullopt;
  std::vector<OutlineNode> out = nodes;
  for (const Refit& r : refits)
    for (std::size_t j = 0; j < r.now.size(); ++j)
      out[r.starts[j]].out_handle = r.now[j].p[1], out[r.ends[j]].in_handle = r.now[j].p[2];
  out.erase(out.begin() + static_cast<std::ptrdiff_t>(k));
  if (!within_distance(SampledContour(to_contour(out, closed)), sampled_source, limits.budget_units))
    return std::nullopt;
  return out;
}

// An outline with a spare node removed, and whether an inflection node's tangent turned for it.
struct NodeRemoved {
  std::vector<OutlineNode> nodes;
  bool turned = false;
};

// The outline with spare node k removed, where the fit and the limits allow; where `limits`
// let it, with the tangent turned at an inflection node the window ends at.
std::optional<NodeRemoved> without_node(const std::vector<OutlineNode>& nodes, bool closed, std::size_t k,
                                        const SampledContour& sampled_source, const SpareNodeLimits& limits) {
  const OutlineJoins joins{nodes, closed};
  const Window w = window_at(joins, k, limits.units_per_em);
  const std::optional<double> first = bound_before(joins, w.starts.front()), last = bound_after(joins, w.last_node);
  if (const std::optional<Refit> plain = refit(nodes, w, k, first, last, std::nullopt))
    if (auto out = with_refits(nodes, closed, k, std::span(&*plain, 1), w.merged, sampled_source, limits))
      return NodeRemoved{std::move(*out), false};
  if (!limits.turn_inflection_nodes) return std::nullopt;
  // Turned, the inflection node keeps κ = 0 on both sides exactly, and the cubics past it are
  // fitted again to its new tangent.
  for (const bool forward : {true, false}) {
    const std::size_t t = forward ? w.last_node : w.starts.front();
    if (!joins.joins_cubics(t) || !inflection_at(nodes, t, limits.units_per_em)) continue;
    const std::optional<Window> b = window_beyond(joins, w, k, t, forward, limits.units_per_em);
    if (!b) continue;
    const std::optional<double> b_first = forward ? 0.0 : bound_before(joins, b->starts.front());
    const std::optional<double> b_last = forward ? bound_after(joins, b->last_node) : 0.0;
    for (const double degrees : turn_degrees) {
      const TangentTurn turn{t, degrees * std::numbers::pi / 180.0};
      std::optional<Refit> near = refit(nodes, w, k, forward ? first : 0.0, forward ? 0.0 : last, turn);
      std::optional<Refit> far = near ? refit(nodes, *b, std::nullopt, b_first, b_last, turn) : std::nullopt;
      if (!far) continue;
      const std::array<Refit, 2> refits{std::move(*near), std::move(*far)};
      if (auto out = with_refits(nodes, closed, k, refits, w.merged, sampled_source, limits))
        return NodeRemoved{std::move(*out), true};
    }
  }
  return std::nullopt;
}

// A run: the cubics from node `first` across smooth nodes that are no inflection, `count` of
// them; `loop` where the contour is closed and every node is such (the run starts anywhere).
struct Run {
  std::size_t first = 0, count = 0;
  bool loop = false;
};

std::vector<Run> runs_of(const OutlineJoins& joins, double units_per_em) {
  const std::size_t n = joins.size();
  std::vector<Run> out;
  bool any_end = false;
  for (std::size_t h = 0; h < n; ++h) {
    if (couples(joins, h, units_per_em)) continue;
    any_end = true;
    if (!joins.is_cubic(h)) continue;
    Run r{h, 1, false};
    for (std::size_t k = after(h, n); couples(joins, k, units_per_em); k = after(k, n)) ++r.count;
    out.push_back(r);
  }
  if (!any_end && joins.closed && n > 0) out.push_back({0, n, true});
  return out;
}

// The index of the sample of `points` nearest p.
std::size_t nearest_sample(const std::vector<Vec2>& points, Vec2 p) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < points.size(); ++i)
    if (distance(points[i], p) < distance(points[best], p)) best = i;
  return best;
}

// The source's samples between `places` (in order along the contour), each stretch its ends
// included; none where their nearest samples do not follow the contour's order.
std::optional<std::vector<std::vector<Vec2>>> source_stretches(std::span<const Vec2> places, bool loop, bool closed,
                                                               const SampledContour& source) {
  const std::vector<Vec2>& pts = source.points();
  const std::size_t count = pts.size();
  if (count < 2) return std::nullopt;
  std::vector<std::size_t> idx;
  for (const Vec2 p : places) idx.push_back(nearest_sample(pts, p));
  if (loop) idx.push_back(idx.front());
  std::size_t total = 0;
  std::vector<std::vector<Vec2>> out;
  for (std::size_t j = 0; j + 1 < idx.size(); ++j) {
    const std::size_t steps = closed ? (idx[j + 1] + count - idx[j]) % count : idx[j + 1] - idx[j];
    if (steps < 2 || (!closed && idx[j + 1] < idx[j])) return std::nullopt;
    total += steps;
    // At most stretch_points of them, evenly by index: the samples run far denser than a
    // cubic's fit needs (one every 3 units or closer).
    std::vector<Vec2> stretch;
    const std::size_t stride = (steps + stretch_points - 1) / stretch_points;
    for (std::size_t s = 0; s < steps; s += stride) stretch.push_back(pts[(idx[j] + s) % count]);
    stretch.push_back(pts[idx[j + 1] % count]);
    out.push_back(std::move(stretch));
  }
  if (total > count || (loop && total != count)) return std::nullopt;
  return out;
}

// The outline with the spare nodes of run r removed, where the limits allow: the run's cubics
// between the nodes left fitted again whole, to the source's points, under G2, the nodes
// inside it sliding along their tangents. EB Garamond's O draws its outer bowl in four cubics
// so, 0.58 units from the source; with its extrema where the faired path put them, four G2
// cubics come no nearer than 2.3.
std::optional<std::vector<OutlineNode>> without_run_spares(const std::vector<OutlineNode>& nodes, bool closed,
                                                           const Run& r, const SampledContour& sampled_source,
                                                           const SpareNodeLimits& limits) {
  const OutlineJoins joins{nodes, closed};
  const std::size_t n = nodes.size();
  // The run's nodes kept: its ends (a loop's first node too, should it be spare) and the inner
  // nodes that are not spare.
  std::vector<std::size_t> kept{r.first};
  std::vector<std::size_t> old_starts{r.first};
  int spares = 0;
  for (std::size_t j = 1; j < r.count; ++j) {
    const std::size_t k = (r.first + j) % n;
    old_starts.push_back(k);
    if (is_spare_node(nodes, closed, k, limits.units_per_em)) ++spares;
    else kept.push_back(k);
  }
  if (r.loop && is_spare_node(nodes, closed, r.first, limits.units_per_em)) {
    // Start the loop at a node that stays.
    if (kept.size() < 2) return std::nullopt;
    ++spares;
    kept.erase(kept.begin());
  }
  if (spares == 0 || kept.size() + (r.loop ? 0 : 1) < 2) return std::nullopt;
  const std::size_t last = (r.first + r.count) % n;  // the run's end node (r.first for a loop)
  std::vector<std::size_t> ends(kept.begin() + 1, kept.end());
  if (r.loop) ends.push_back(kept.front());
  else ends.push_back(last);

  std::vector<CubicFrame> frames;
  G2FitFreedom freedom{{}, 0.0, r.loop};
  double shortest = std::numeric_limits<double>::infinity();
  for (std::size_t j = 0; j < kept.size(); ++j) {
    const std::size_t s = kept[j], e = ends[j];
    const Vec2 t0 = *nodes[s].out_handle - nodes[s].point, t3 = nodes[e].point - *nodes[e].in_handle;
    if (!(norm(t0) > 0.0) || !(norm(t3) > 0.0)) return std::nullopt;
    frames.push_back({nodes[s].point, t0 / norm(t0), nodes[e].point, t3 / norm(t3)});
    shortest = std::min(shortest, distance(nodes[s].point, nodes[e].point));
    // The run's inner nodes left slide along their tangents (an extremum so stays one); its
    // ends stay.
    freedom.slides.push_back(r.loop || j > 0);
  }
  if (!r.loop) freedom.slides.push_back(false);
  freedom.slide_reach = slide_share * shortest;
  freedom.step_share = fit_step_share;
  const std::optional<double> first = r.loop ? std::nullopt : bound_before(joins, r.first);
  const std::optional<double> end = r.loop ? std::nullopt : bound_after(joins, last);
  // The source split at the nodes where they are. The points at a sliding node are not fitted
  // (G2FitFreedom::slides), so the split does not hold it where it was.
  std::vector<Vec2> places;
  for (const std::size_t k : kept) places.push_back(nodes[k].point);
  if (!r.loop) places.push_back(nodes[last].point);
  const std::optional<std::vector<std::vector<Vec2>>> points = source_stretches(places, r.loop, closed, sampled_source);
  if (!points) return std::nullopt;
  std::vector<std::pair<double, double>> initial;
  for (std::size_t j = 0; j < frames.size(); ++j) {
    const CubicFrame& f = frames[j];
    const double chord = distance(f.start, f.end);
    std::pair<double, double> lengths{chord / 3.0, chord / 3.0};
    if (const std::optional<Cubic> fit =
            fit_cubic_with_end_tangents(f.start, f.start_tangent, f.end, f.end_tangent, (*points)[j]))
      if (distance(fit->p[0], fit->p[1]) > 1e-3 * chord && distance(fit->p[2], fit->p[3]) > 1e-3 * chord)
        lengths = {distance(fit->p[0], fit->p[1]), distance(fit->p[2], fit->p[3])};
    initial.push_back(lengths);
  }
  const std::optional<std::vector<Cubic>> fitted = fit_g2_handles(frames, *points, initial, first, end, freedom);
  if (!fitted) return std::nullopt;

  // Judged as the merged pair is (with_refits): over the run's cubics together, each new
  // cubic turning as much as those it replaces did together.
  std::vector<Cubic> old;
  for (const std::size_t s : old_starts) old.push_back(outline_cubic(nodes, s));
  ShapeTraits was = shape_traits(old);
  for (std::size_t j = 0; j < kept.size(); ++j) {
    double turning = 0.0;
    std::size_t s = kept[j];
    do turning += cubic_turning(outline_cubic(nodes, s)), s = after(s, n);
    while (s != ends[j]);
    was.turning = std::max(was.turning, turning);
  }
  const ShapeTraits is = shape_traits(*fitted);
  if (worsens(is, was) || varies_more(is, was, variation_share, variation_em, limits.units_per_em)) return std::nullopt;
  std::vector<OutlineNode> out = nodes;
  for (std::size_t j = 0; j < kept.size(); ++j) {
    const Cubic& c = (*fitted)[j];
    out[kept[j]].point = c.p[0], out[kept[j]].out_handle = c.p[1];
    out[ends[j]].in_handle = c.p[2], out[ends[j]].point = c.p[3];
  }
  std::vector<bool> drop(n, false);
  for (const std::size_t k : old_starts)
    if (std::find(kept.begin(), kept.end(), k) == kept.end()) drop[k] = true;
  std::vector<OutlineNode> fewer;
  for (std::size_t k = 0; k < n; ++k)
    if (!drop[k]) fewer.push_back(out[k]);
  if (!within_distance(SampledContour(to_contour(fewer, closed)), sampled_source, limits.budget_units))
    return std::nullopt;
  return fewer;
}

}  // namespace

SpareNodeRemoval remove_spare_nodes(std::vector<OutlineNode>& nodes, bool closed, const SampledContour& sampled_source,
                                    const SpareNodeLimits& limits) {
  SpareNodeRemoval removed;
  // Each spare node in its window first (without_node): what the runs fitted again whole
  // would take of them first may leave the rest none to go (Liberation Sans's o: its bowl in
  // six cubics, against four). Then each run fitted again whole without the spare nodes left
  // in it. Not without each spare node alone as well: a–z A–Z nodes Comic Neue 1.381× →
  // 1.371×, EB Garamond 1.388× → 1.383×, Junicode 1.516× → 1.507× of the source's (before the
  // points at sliding nodes went unfitted), but whole DejaVu Sans 60 s → 73 s.
  for (bool again = true; again;) {
    again = false;
    for (std::size_t k = 0; k < nodes.size();) {
      if (is_spare_node(nodes, closed, k, limits.units_per_em))
        if (std::optional<NodeRemoved> fewer = without_node(nodes, closed, k, sampled_source, limits)) {
          nodes = std::move(fewer->nodes), ++removed.removed, removed.turned += fewer->turned ? 1 : 0, again = true;
          continue;
        }
      ++k;
    }
  }
  // Each run once: a run fitted so keeps its ends where they are, and the curvature there, so
  // one that did not fit still would not after another did. The runs found again after each
  // removal (the nodes' indices shift), those whose first node was tried passed over.
  std::vector<Vec2> tried;
  const auto fewer_in_a_run = [&]() -> std::optional<std::vector<OutlineNode>> {
    for (const Run& r : runs_of(OutlineJoins{nodes, closed}, limits.units_per_em)) {
      if (std::find(tried.begin(), tried.end(), nodes[r.first].point) != tried.end()) continue;
      tried.push_back(nodes[r.first].point);
      if (auto fewer = without_run_spares(nodes, closed, r, sampled_source, limits)) return fewer;
    }
    return std::nullopt;
  };
  if (limits.fit_runs)
    while (std::optional<std::vector<OutlineNode>> fewer = fewer_in_a_run()) {
      removed.in_runs += static_cast<int>(nodes.size() - fewer->size());
      nodes = std::move(*fewer);
    }
  removed.removed += removed.in_runs;
  return removed;
}

}  // namespace gf
