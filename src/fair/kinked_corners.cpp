#include "fair/kinked_corners.hpp"

#include <cmath>
#include <optional>

#include "fair/contour_plan.hpp"
#include "geom/curvature.hpp"

namespace gf {

namespace {

// How far a corner may end up from where the pieces met: rounding moves it a unit or two, and
// a G3 run slides its end along its line by several (dkg Bold's j: 6 units).
constexpr double corner_drift = 8.0;

}  // namespace

std::vector<std::size_t> kinked_corners(const Contour& faired, std::span<const CornerJoin> corners) {
  std::vector<std::size_t> out;
  const std::size_t n = faired.segments.size();
  if (n < 2) return out;
  const double kink = radians(kink_limit_deg);
  const auto smooth = [&](std::size_t k) { return faired.nodes[k].smooth.value_or(false); };
  for (const CornerJoin& c : corners) {
    std::size_t k = 0;
    for (std::size_t i = 1; i < n; ++i)
      if (distance(faired.node_point(i), c.point) < distance(faired.node_point(k), c.point)) k = i;
    if (smooth(k) && (faired.closed || (k > 0 && k + 1 < n)))
      for (const std::size_t other : {(k + n - 1) % n, (k + 1) % n}) {
        const Segment& between = faired.segments[other == (k + 1) % n ? k : other];
        const double length = distance(start_point(between), end_point(between));
        if (is_line(between) && length > 0.0 && length <= corner_drift && !smooth(other)) {
          k = other;
          break;
        }
      }
    if ((!faired.closed && k == 0) || smooth(k)) continue;
    const std::optional<Vec2> in = end_tangent(faired.segments[(k + n - 1) % n], SegmentEnd::end);
    const std::optional<Vec2> leaving = end_tangent(faired.segments[k], SegmentEnd::start);
    if (in && leaving && std::abs(turning_angle(*in, *leaving)) < kink) out.push_back(c.source_node);
  }
  return out;
}

}  // namespace gf
