#include "fair/outline_joins.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "fair/contour_plan.hpp"
#include "fair/handle_steps.hpp"

namespace gf {

double turn_at(const std::vector<OutlineNode>& nodes, bool closed, std::size_t k, std::optional<Vec2> in,
               std::optional<Vec2> out) {
  const std::size_t n = nodes.size();
  if (!closed && (k == 0 || k + 1 == n)) return std::numbers::pi;
  const OutlineNode& node = nodes[k];
  const Vec2 from = in ? *in : node.in_handle ? *node.in_handle : nodes[(k + n - 1) % n].point;
  const Vec2 to = out ? *out : node.out_handle ? *node.out_handle : nodes[(k + 1) % n].point;
  const Vec2 a = node.point - from, b = to - node.point;
  if (norm(a) == 0.0 || norm(b) == 0.0) return std::numbers::pi;
  return std::abs(turning_angle(a, b));
}

bool corner_to_keep(const std::vector<OutlineNode>& ideal, bool closed, std::size_t k) {
  const OutlineNode& node = ideal[k];
  if (node.smooth || (!node.in_handle && !node.out_handle)) return false;
  const double turn = turn_at(ideal, closed, k);
  return turn >= radians(kink_limit_deg) && turn < std::numbers::pi;
}

bool turns_less_than_it_did(const std::vector<OutlineNode>& nodes, const std::vector<OutlineNode>& ideal, bool closed,
                            std::size_t k) {
  constexpr double turn_noise = 1e-9;  // radians
  const double least = std::min(radians(kink_limit_deg), turn_at(ideal, closed, k));
  return turn_at(nodes, closed, k) < least - turn_noise;
}

std::pair<double, double> curvatures_at(const std::vector<OutlineNode>& nodes, std::size_t k) {
  const std::size_t before = (k + nodes.size() - 1) % nodes.size();
  return {node_curvature(outline_cubic(nodes, before), SegmentEnd::end),
          node_curvature(outline_cubic(nodes, k), SegmentEnd::start)};
}

double join_jump(const OutlineJoins& joins, std::size_t k, double flat) {
  const std::vector<OutlineNode>& nodes = joins.nodes;
  const std::size_t n = nodes.size(), before = (k + n - 1) % n;
  if (joins.joins_cubics(k)) {
    const auto [in, out] = curvatures_at(nodes, k);
    return relative_jump(in, out, flat);
  }
  if (!joins.meets_line(k)) return 0.0;
  const double kappa = joins.is_cubic(k) ? node_curvature(outline_cubic(nodes, k), SegmentEnd::start)
                                         : node_curvature(outline_cubic(nodes, before), SegmentEnd::end);
  return relative_jump(kappa, 0.0, flat);
}

}  // namespace gf
