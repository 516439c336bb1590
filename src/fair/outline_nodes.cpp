#include "fair/outline_nodes.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numeric>

namespace gf {

Cubic outline_cubic(const std::vector<OutlineNode>& nodes, std::size_t i) {
  const OutlineNode &a = nodes[i], &b = nodes[(i + 1) % nodes.size()];
  return {a.point, *a.out_handle, *b.in_handle, b.point};
}

Contour to_contour(const std::vector<OutlineNode>& nodes, bool closed) {
  Contour c;
  c.closed = closed;
  const std::size_t n = nodes.size();
  for (std::size_t i = 0; i < n; ++i) {
    c.nodes.push_back(NodeFlags{false, nodes[i].smooth});
    if (!closed && i + 1 == n) break;
    const OutlineNode &a = nodes[i], &b = nodes[(i + 1) % n];
    if (a.out_handle && b.in_handle) c.segments.emplace_back(outline_cubic(nodes, i));
    else c.segments.emplace_back(Line{a.point, b.point});
  }
  return c;
}

double whole_steps(Vec2 from, Vec2 handle, Vec2 d, double sign) {
  return std::round(sign * dot(handle - from, d) / dot(d, d));
}

Vec2 stepped_handle(Vec2 node, Vec2 d, double sign, Vec2 from, Vec2 handle) {
  return node + d * (sign * std::max(1.0, whole_steps(from, handle, d, sign)));
}

std::optional<Vec2> primitive_step(Vec2 along) {
  const long long g = std::gcd(std::llabs(std::llround(along.x)), std::llabs(std::llround(along.y)));
  if (g == 0) return std::nullopt;
  return along / static_cast<double>(g);
}

double node_curvature(const Cubic& c, SegmentEnd end) { return end_curvature(c, end).curvature.value_or(0.0); }

}  // namespace gf
