#include "fair/curve_line_joins.hpp"

#include <algorithm>
#include <limits>

namespace gf {

std::optional<CurveLineJoin> curve_line_join(const std::vector<OutlineNode>& nodes, bool closed, std::size_t k) {
  const std::size_t n = nodes.size();
  if (k >= n || (!closed && (k == 0 || k + 1 == n))) return std::nullopt;
  const std::size_t prev = (k + n - 1) % n, next = (k + 1) % n;
  const OutlineNode& node = nodes[k];
  if (!node.smooth || node.in_handle.has_value() == node.out_handle.has_value()) return std::nullopt;
  const bool arrives = node.in_handle.has_value();
  // The line's side must be a line (no handle at its far end either) and the cubic whole.
  if (arrives ? nodes[next].in_handle.has_value() || !nodes[prev].out_handle
              : nodes[prev].out_handle.has_value() || !nodes[next].in_handle)
    return std::nullopt;
  return CurveLineJoin{arrives, arrives ? outline_cubic(nodes, prev) : outline_cubic(nodes, k).reversed(),
                       arrives ? next : prev};
}

double shortest_line_step(Vec2 a, Vec2 b) {
  const Vec2 d = nearest_grid_point(b) - nearest_grid_point(a);
  double best = std::numeric_limits<double>::infinity();
  for (int dx = -2; dx <= 2; ++dx)
    for (int dy = -2; dy <= 2; ++dy)
      if (const std::optional<Vec2> s = primitive_step(d + Vec2{static_cast<double>(dx), static_cast<double>(dy)}))
        best = std::min(best, norm(*s));
  return best;
}

double end_bend(const Cubic& c) {
  const auto velocity = c.hodograph();
  const auto acceleration = velocity.hodograph();
  for (const double t : {0.9, 0.75, 0.5}) {
    const double k = cross(velocity.point_at(t), acceleration.point_at(t));
    if (k != 0.0) return k > 0.0 ? 1.0 : -1.0;
  }
  return 0.0;
}

}  // namespace gf
