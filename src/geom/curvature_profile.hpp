// κ(s): signed curvature against arc length along a contour, sampled per segment so that
// jumps at joins stay visible as jumps, with the joins' positions along s.
#pragma once

#include <optional>
#include <vector>

#include "geom/contour.hpp"
#include "geom/join.hpp"

namespace gf {

struct CurvatureSample {
  double s;          ///< arc length from the contour's start node
  std::optional<double> curvature;  ///< signed, left turns positive; nullopt where unbounded
  Vec2 point;
  Vec2 normal;       ///< unit left normal (zero where the speed vanishes)
};

struct SegmentProfile {
  std::vector<CurvatureSample> samples;  ///< t = 0 … 1 inclusive, uniform in t
  bool straight = false;                 ///< a line: κ ≡ 0
};

struct ProfileJoin {
  double s;
  Join join;
};

struct CurvatureProfile {
  std::vector<SegmentProfile> segments;
  std::vector<ProfileJoin> joins;
  double length = 0.0;
};

CurvatureProfile curvature_profile(const Contour& c, int samples_per_segment = 48);

}  // namespace gf
