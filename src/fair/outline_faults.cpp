#include "fair/outline_faults.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <span>
#include <vector>

#include "geom/critical_points.hpp"
#include "geom/curvature.hpp"
#include "geom/join.hpp"

namespace gf {

namespace {

constexpr double corner_reach_em = 0.0025;  // the check's: a corner kept within this of the em

constexpr double flat_em = 1e-6;  // the check's: |κ|·UPM under this has no sign

bool is_corner(const Join& j, double kink_max_deg) {
  return j.kind == JoinKind::degenerate || std::abs(j.angle_deg) > kink_max_deg;
}

// The signs of κ along a segment, one for each stretch between its inflections (none where
// |κ|·UPM is under flat_em there: a line's throughout).
void append_curvature_signs(const Segment& s, double units_per_em, std::vector<int>& signs) {
  std::vector<double> cuts = inflections(s);
  cuts.insert(cuts.begin(), 0.0);
  cuts.push_back(1.0);
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    const std::optional<double> kappa = curvature(derivatives_at(s, 0.5 * (cuts[k] + cuts[k + 1])));
    if (kappa && std::abs(*kappa) * units_per_em >= flat_em) signs.push_back(*kappa > 0.0 ? 1 : -1);
  }
}

// What a jump or kink mended may cost in inflections beyond the source's (fewer_faults).
constexpr int inflections_per_mended_join = 2;

}  // namespace

JoinFault join_fault(const Join& j, const JoinThresholds& thresholds, double units_per_em) {
  if (is_corner(j, thresholds.kink_max_deg)) return JoinFault::corner;
  if (std::abs(j.angle_deg) > thresholds.smooth_max_deg) return JoinFault::kink;
  const std::optional<CurvatureJump> jump = curvature_jump(j, units_per_em, fairing_jump_rule);
  return !jump || jump->exceeds() ? JoinFault::jump : JoinFault::none;
}

int inflections_along(const Contour& c, std::span<const Join> joins, double units_per_em, double kink_max_deg) {
  const std::size_t n = c.segments.size();
  // Where each stretch starts: at a corner, and an open contour at its first segment.
  std::vector<bool> starts(n, false);
  if (!c.closed && n > 0) starts[0] = true;
  for (const Join& j : joins) starts[j.node] = starts[j.node] || is_corner(j, kink_max_deg);
  const auto first = std::find(starts.begin(), starts.end(), true);
  const bool round = first == starts.end();
  const std::size_t from = round ? 0 : static_cast<std::size_t>(first - starts.begin());
  int count = 0;
  std::vector<int> signs;
  const auto count_stretch = [&] {
    for (std::size_t k = 1; k < signs.size(); ++k) count += signs[k] != signs[k - 1];
    signs.clear();
  };
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = (from + k) % n;
    if (starts[i]) count_stretch();
    append_curvature_signs(c.segments[i], units_per_em, signs);
  }
  if (round && c.closed && !signs.empty()) signs.push_back(signs.front());
  count_stretch();
  return count;
}

FaultCounter::FaultCounter(const Contour& source, double units_per_em) : units_per_em_(units_per_em) {
  const JoinThresholds thresholds;
  const std::vector<Join> joins = joins_of(source, thresholds);
  for (const Join& j : joins)
    if (is_corner(j, thresholds.kink_max_deg) && j.kind != JoinKind::degenerate) source_corners_.push_back(j.point);
  source_inflections_ = inflections_along(source, joins, units_per_em, thresholds.kink_max_deg);
}

OutlineFaults FaultCounter::count(const Contour& faired) const {
  const JoinThresholds thresholds;
  OutlineFaults out;
  std::vector<Vec2> corners;
  const std::vector<Join> joins = joins_of(faired, thresholds);
  for (const Join& j : joins) {
    const JoinFault fault = join_fault(j, thresholds, units_per_em_);
    if (fault == JoinFault::corner) corners.push_back(j.point);
    out.kinks += fault == JoinFault::kink;
    out.jumps += fault == JoinFault::jump;
  }
  out.inflections = std::max(0, inflections_along(faired, joins, units_per_em_, thresholds.kink_max_deg) - source_inflections_);
  const double reach = corner_reach_em * units_per_em_;
  for (const Vec2 c : source_corners_)
    out.corners_lost += std::none_of(corners.begin(), corners.end(), [&](Vec2 p) { return distance(p, c) <= reach; });
  return out;
}

std::vector<Vec2> joins_at_fault(const Contour& faired, JoinFault fault, double units_per_em) {
  const JoinThresholds thresholds;
  std::vector<Vec2> out;
  for (const Join& j : joins_of(faired, thresholds))
    if (join_fault(j, thresholds, units_per_em) == fault) out.push_back(j.point);
  return out;
}

bool fewer_faults(const OutlineFaults& a, const OutlineFaults& b) {
  const int mended = b.at_smooth_joins() - a.at_smooth_joins();
  if (a.kinks > b.kinks || a.corners_lost > b.corners_lost || mended < 0) return false;
  return a.inflections <= b.inflections + inflections_per_mended_join * mended &&
         (mended > 0 || a.inflections < b.inflections || a.corners_lost < b.corners_lost);
}

}  // namespace gf
