#include "geom/outline_move.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "geom/polyline_distance.hpp"

namespace gf {

namespace {

// Points at most `spacing` apart along the segments (by their control polygons), in order.
std::vector<Vec2> points_along(std::initializer_list<Segment> segments, double spacing) {
  std::vector<Vec2> out;
  for (const Segment& s : segments) {
    const int n = std::max(1, static_cast<int>(std::ceil(control_polygon_length(s) / spacing)));
    for (int k = 0; k <= n; ++k) out.push_back(point_at(s, static_cast<double>(k) / n));
  }
  return out;
}

}  // namespace

double outline_move(std::initializer_list<Segment> before, std::initializer_list<Segment> after, double spacing,
                    double limit) {
  const std::vector<Vec2> a = points_along(before, spacing), b = points_along(after, spacing);
  return std::max(directed_hausdorff(a, b, limit), directed_hausdorff(b, a, limit));
}

}  // namespace gf
