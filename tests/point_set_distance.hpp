// Distances between densely sampled curves, by brute force: the tests' oracles (no code shared
// with geom/polyline_distance).
#pragma once

#include <algorithm>
#include <limits>
#include <vector>

#include "geom/contour.hpp"
#include "geom/vec2.hpp"

namespace gf::test {

/// `per_segment` points of each segment of `c`, evenly in t from its start (its end is the next
/// segment's start).
inline std::vector<Vec2> contour_points(const Contour& c, int per_segment) {
  std::vector<Vec2> out;
  for (const Segment& s : c.segments)
    for (int k = 0; k < per_segment; ++k) out.push_back(point_at(s, double(k) / per_segment));
  return out;
}

/// The two-sided Hausdorff distance between two point sets. Between curves sampled with
/// spacing h it errs high by up to about h²/(8d) at a distance d.
inline double point_set_hausdorff(const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
  auto one_way = [](const std::vector<Vec2>& from, const std::vector<Vec2>& to) {
    double worst = 0.0;
    for (const Vec2 p : from) {
      double nearest = 1e300;
      for (const Vec2 q : to) nearest = std::min(nearest, distance(p, q));
      worst = std::max(worst, nearest);
    }
    return worst;
  };
  return std::max(one_way(a, b), one_way(b, a));
}

/// max over the points `from` of the distance to the nearest segment of the polyline `to`,
/// straight from the definition.
inline double directed_to_polyline(const std::vector<Vec2>& from, const std::vector<Vec2>& to) {
  double worst = 0.0;
  for (const Vec2 p : from) {
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i + 1 < to.size(); ++i) {
      const Vec2 d = to[i + 1] - to[i];
      const double t = std::clamp(dot(p - to[i], d) / dot(d, d), 0.0, 1.0);
      nearest = std::min(nearest, distance(p, to[i] + d * t));
    }
    worst = std::max(worst, nearest);
  }
  return worst;
}

/// The two-sided Hausdorff distance between two polylines' points and segments: between
/// curves sampled densely, off only by the chords' sagitta.
inline double polyline_hausdorff(const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
  return std::max(directed_to_polyline(a, b), directed_to_polyline(b, a));
}

}  // namespace gf::test
