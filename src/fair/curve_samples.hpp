// Log-aesthetic segments or G3 spirals as points, for measuring them against the source.
#pragma once

#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

#include "aesthetic/log_aesthetic_segment.hpp"
#include "geom/vec2.hpp"

namespace gf {

/// Each segment's points, so many that the chords stay within 2 % of the tolerance of the curve
/// (log-aesthetic segments and spirals have monotone curvature: the larger end's bounds it).
template <class Curve>
std::vector<std::vector<Vec2>> sample_each(std::span<const Curve> curves, double tolerance) {
  std::vector<std::vector<Vec2>> out;
  for (const Curve& c : curves) {
    const double k = std::max({std::abs(c.start().curvature), std::abs(c.end().curvature), 1e-9});
    const double h = std::sqrt(8.0 * 0.02 * tolerance / k);
    out.emplace_back();
    for (const LacPoint& p : c.sample(std::clamp(static_cast<int>(std::ceil(c.length() / h)), 8, 400)))
      out.back().push_back(p.point);
  }
  return out;
}

}  // namespace gf
