#include "geom/turning.hpp"

#include <cmath>

namespace gf {

double absolute_turning(Vec2 start, std::span<const Vec2> points, Vec2 end) {
  double total = 0.0;
  Vec2 last = start;
  for (std::size_t i = 1; i < points.size(); ++i) {
    const Vec2 v = points[i] - points[i - 1];
    if (norm(v) == 0.0) continue;
    total += std::abs(turning_angle(last, v));
    last = v;
  }
  return total + std::abs(turning_angle(last, end));
}

}  // namespace gf
