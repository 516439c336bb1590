// The two-sided Hausdorff distance between two point sets, by brute force: the tests' oracle
// for distances between curves sampled densely (no code shared with geom/polyline_distance).
#pragma once

#include <algorithm>
#include <vector>

#include "geom/vec2.hpp"

namespace gf::test {

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

}  // namespace gf::test
