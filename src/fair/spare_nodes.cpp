#include "fair/spare_nodes.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
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

// The outline with spare node k removed, where the fit and the limits allow.
std::optional<std::vector<OutlineNode>> without_node(const std::vector<OutlineNode>& nodes, bool closed, std::size_t k,
                                                     const SampledContour& sampled_source, const SpareNodeLimits& limits) {
  const std::size_t n = nodes.size();
  const OutlineJoins joins{nodes, closed};
  const Window w = window_at(joins, k, limits.units_per_em);
  std::vector<CubicFrame> frames;
  std::vector<std::vector<Vec2>> points;
  std::vector<std::pair<double, double>> initial;
  std::vector<Cubic> old;
  for (std::size_t j = 0; j < w.starts.size(); ++j) {
    const std::size_t s = w.starts[j];
    const Cubic c = outline_cubic(nodes, s);
    old.push_back(c);
    if (j != w.merged) {
      const std::optional<CubicFrame> f = frame_of(c);
      if (!f) return std::nullopt;
      frames.push_back(*f), points.push_back(samples_of(c));
      initial.emplace_back(distance(c.p[0], c.p[1]), distance(c.p[2], c.p[3]));
      continue;
    }
    const Cubic second = outline_cubic(nodes, k);
    old.push_back(second);
    const std::optional<CubicFrame> a = frame_of(c), b = frame_of(second);
    if (!a || !b) return std::nullopt;
    const CubicFrame f{a->start, a->start_tangent, b->end, b->end_tangent};
    std::vector<Vec2> pts = samples_of(c);
    const std::vector<Vec2> rest = samples_of(second);
    pts.insert(pts.end(), rest.begin() + 1, rest.end());
    const double chord = distance(f.start, f.end);
    std::pair<double, double> lengths{chord / 3.0, chord / 3.0};
    if (const std::optional<Cubic> fit = fit_cubic_with_end_tangents(f.start, f.start_tangent, f.end, f.end_tangent, pts))
      lengths = {distance(fit->p[0], fit->p[1]), distance(fit->p[2], fit->p[3])};
    frames.push_back(f), points.push_back(std::move(pts)), initial.push_back(lengths);
  }
  const std::optional<std::vector<Cubic>> fitted =
      fit_g2_handles(frames, points, initial, bound_before(joins, w.starts.front()), bound_after(joins, w.last_node));
  if (!fitted) return std::nullopt;
  ShapeTraits was = shape_traits(old);
  // The merged cubic turns as its two did together.
  was.turning = std::max(was.turning, cubic_turning(old[w.merged]) + cubic_turning(old[w.merged + 1]));
  const ShapeTraits now = shape_traits(*fitted);
  if (worsens(now, was) || varies_more(now, was, variation_share, variation_em, limits.units_per_em)) return std::nullopt;
  std::vector<OutlineNode> out = nodes;
  for (std::size_t j = 0; j < fitted->size(); ++j) {
    const std::size_t s = w.starts[j], e = j == w.merged ? after(k, n) : after(s, n);
    out[s].out_handle = (*fitted)[j].p[1], out[e].in_handle = (*fitted)[j].p[2];
  }
  out.erase(out.begin() + static_cast<std::ptrdiff_t>(k));
  if (distance_between(SampledContour(to_contour(out, closed)), sampled_source) > limits.budget_units) return std::nullopt;
  return out;
}

}  // namespace

int remove_spare_nodes(std::vector<OutlineNode>& nodes, bool closed, const SampledContour& sampled_source,
                       const SpareNodeLimits& limits) {
  int removed = 0;
  for (bool again = true; again;) {
    again = false;
    for (std::size_t k = 0; k < nodes.size();) {
      if (is_spare_node(nodes, closed, k, limits.units_per_em))
        if (std::optional<std::vector<OutlineNode>> fewer = without_node(nodes, closed, k, sampled_source, limits)) {
          nodes = std::move(*fewer), ++removed, again = true;
          continue;
        }
      ++k;
    }
  }
  return removed;
}

}  // namespace gf
