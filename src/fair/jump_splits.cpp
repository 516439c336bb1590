#include "fair/jump_splits.hpp"

#include <algorithm>
#include <cmath>

#include "geom/polynomial.hpp"

namespace gf {

namespace {

// The split's parameter keeps both halves at least a quarter of the cubic.
constexpr double first_split = 0.25, last_split = 0.75;
constexpr int longest_split_step = 5;  // |d|² of the directions a split node may run along

}  // namespace

CubicSplit split_place(const Cubic& c) {
  CubicSplit best;
  double nearest = 1.0;
  const PolynomialCurve velocity = c.hodograph().polynomial();
  const double scale = std::max({norm(c.p[1] - c.p[0]), norm(c.p[2] - c.p[1]), norm(c.p[3] - c.p[2]), 1.0});
  // Each direction comes both ways; both give the same roots, and the first is kept.
  for (const Vec2 d : grid_directions(longest_split_step)) {
    const Polynomial across = d.y * velocity.x - d.x * velocity.y;
    for (const SignChange root : sign_changes_in_unit_interval(across, 1e-12 * scale)) {
      if (root.t < first_split || root.t > last_split || std::abs(root.t - 0.5) >= nearest) continue;
      nearest = std::abs(root.t - 0.5);
      best.t = root.t;
      best.grid_step = dot(velocity(root.t), d) > 0.0 ? d : d * -1.0;
    }
  }
  return best;
}

std::vector<OutlineNode> split_cubics_beside(const std::vector<OutlineNode>& nodes, bool closed,
                                             std::span<const Vec2> joins, double shortest_chord, double reach) {
  const std::size_t n = nodes.size();
  std::vector<bool> split(n, false);  // by the node starting the cubic
  const auto is_cubic = [&](std::size_t i) {
    return (closed || i + 1 < n) && nodes[i].out_handle && nodes[(i + 1) % n].in_handle;
  };
  if (n == 0) return nodes;
  for (const Vec2 join : joins) {
    const std::optional<std::size_t> node = node_within(nodes, join, reach);
    if (!node) continue;
    const std::size_t at = *node;
    for (const std::size_t i : {(at + n - 1) % n, at})
      if (is_cubic(i) && distance(nodes[i].point, nodes[(i + 1) % n].point) >= shortest_chord) split[i] = true;
  }
  std::vector<OutlineNode> out;
  std::optional<Vec2> next_in;  // the in-handle of the node after a split cubic
  for (std::size_t i = 0; i < n; ++i) {
    out.push_back(nodes[i]);
    if (next_in) out.back().in_handle = next_in, next_in.reset();
    if (!split[i]) continue;
    const Cubic cubic = outline_cubic(nodes, i);
    const CubicSplit place = split_place(cubic);
    const auto [before, after] = cubic.split(place.t);
    out.back().out_handle = before.p[1];
    OutlineNode middle;
    middle.point = after.p[0];
    middle.in_handle = before.p[2];
    middle.out_handle = after.p[1];
    middle.grid_step = place.grid_step;
    out.push_back(middle);
    next_in = after.p[2];
  }
  if (next_in) out.front().in_handle = next_in;  // the closing cubic was split
  return out;
}

}  // namespace gf
