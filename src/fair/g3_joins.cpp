#include "fair/g3_joins.hpp"

#include <algorithm>
#include <cmath>

#include "geom/join.hpp"

namespace gf {

G3JoinCount g3_joins_of(const Contour& c, double relative) {
  G3JoinCount out;
  const std::size_t n = c.segments.size();
  for (const Join& j : joins_of(c)) {
    if (j.kind != JoinKind::smooth) continue;
    const Segment& before = c.segments[(j.node + n - 1) % n];
    const Segment& after = c.segments[j.node % n];
    if (is_line(before) || is_line(after) || !j.curvature_derivative_in || !j.curvature_derivative_out) continue;
    const double in = *j.curvature_derivative_in, out_slope = *j.curvature_derivative_out;
    const double larger = std::max(std::abs(in), std::abs(out_slope));
    ++out.joins;
    if (larger == 0.0 || std::abs(in - out_slope) <= relative * larger) ++out.matched;
  }
  return out;
}

}  // namespace gf
