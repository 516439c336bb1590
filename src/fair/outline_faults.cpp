#include "fair/outline_faults.hpp"

#include <algorithm>
#include <cmath>

#include "geom/critical_points.hpp"
#include "geom/join.hpp"

namespace gf {

namespace {

constexpr double corner_reach_em = 0.0025;  // the check's: a corner kept within this of the em

bool is_corner(const Join& j, const JoinThresholds& t) {
  return j.kind == JoinKind::degenerate || std::abs(j.angle_deg) > t.kink_max_deg;
}

}  // namespace

FaultCounter::FaultCounter(const Contour& source, double units_per_em) : units_per_em_(units_per_em) {
  const JoinThresholds thresholds;
  for (const Join& j : joins_of(source, thresholds))
    if (is_corner(j, thresholds) && j.kind != JoinKind::degenerate) source_corners_.push_back(j.point);
}

OutlineFaults FaultCounter::count(const Contour& faired) const {
  const JoinThresholds thresholds;
  OutlineFaults out;
  std::vector<Vec2> corners;
  for (const Join& j : joins_of(faired, thresholds)) {
    if (is_corner(j, thresholds)) {
      corners.push_back(j.point);
      continue;
    }
    if (std::abs(j.angle_deg) > thresholds.smooth_max_deg) {
      ++out.kinks;
      continue;
    }
    const std::optional<CurvatureJump> jump = curvature_jump(j, units_per_em_);
    out.jumps += !jump || jump->exceeds();
    // κ changing sign across the join.
    out.inflections += jump && *j.curvature_in * *j.curvature_out < 0.0;
  }
  for (const Segment& s : faired.segments) out.inflections += static_cast<int>(inflections(s).size());
  const double reach = corner_reach_em * units_per_em_;
  for (const Vec2 c : source_corners_)
    out.corners_lost += std::none_of(corners.begin(), corners.end(), [&](Vec2 p) { return distance(p, c) <= reach; });
  return out;
}

bool fewer_faults(const OutlineFaults& a, const OutlineFaults& b) {
  return a.at_smooth_joins() < b.at_smooth_joins() && a.kinks <= b.kinks && a.inflections <= b.inflections &&
         a.corners_lost <= b.corners_lost;
}

}  // namespace gf
