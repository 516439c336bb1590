#include "fair/spare_nodes.hpp"

#include <algorithm>
#include <array>
#include <cmath>
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
// Curvature variation the changed cubics may take on: a quarter more, and 0.05 per em.
constexpr double variation_share = 1.25, variation_em = 0.05;
constexpr int samples_per_cubic = 32;  // of the outline they are fitted to

std::size_t after(std::size_t k, std::size_t n) { return (k + 1) % n; }
std::size_t before(std::size_t k, std::size_t n) { return (k + n - 1) % n; }

// Whether node k lies between two cubics whose curvature there changes sign or is flat.
bool inflection_at(const std::vector<OutlineNode>& nodes, std::size_t k, double units_per_em) {
  const auto [in, out] = curvatures_at(nodes, k);
  return in * out <= 0.0 || std::min(std::abs(in), std::abs(out)) * units_per_em < flat_em;
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
  const auto extends = [&](std::size_t node) {
    return joins.joins_cubics(node) && !inflection_at(joins.nodes, node, units_per_em);
  };
  if (before(l, n) != r && extends(l)) w.starts.insert(w.starts.begin(), before(l, n)), w.merged = 1;
  if (after(r, n) != w.starts.front() && extends(r)) w.starts.push_back(r), w.last_node = after(r, n);
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
  const auto extends = [&](std::size_t node) {
    return joins.joins_cubics(node) && !inflection_at(joins.nodes, node, units_per_em);
  };
  Window b;
  if (forward) {
    b.starts = {t}, b.last_node = after(t, n);
    if (extends(b.last_node) && !in_w(b.last_node)) b.starts.push_back(b.last_node), b.last_node = after(b.last_node, n);
  } else {
    b.starts = {before(t, n)}, b.last_node = t;
    if (extends(b.starts.front()) && !in_w(before(b.starts.front(), n)))
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
  if (distance_between(SampledContour(to_contour(out, closed)), sampled_source) > limits.budget_units) return std::nullopt;
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

}  // namespace

SpareNodeRemoval remove_spare_nodes(std::vector<OutlineNode>& nodes, bool closed, const SampledContour& sampled_source,
                                    const SpareNodeLimits& limits) {
  SpareNodeRemoval removed;
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
  return removed;
}

}  // namespace gf
