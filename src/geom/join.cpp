#include "geom/join.hpp"

#include <algorithm>
#include <cmath>

#include "geom/curvature.hpp"

namespace gf {

namespace {

Join join_between(const Segment& in, const Segment& out, std::size_t node, const NodeFlags& flags,
                  const JoinThresholds& thresholds) {
  Join j;
  j.node = node;
  j.point = start_point(out);
  const EndCurvature kin = end_curvature(in, SegmentEnd::end);
  const EndCurvature kout = end_curvature(out, SegmentEnd::start);
  j.curvature_in = kin.curvature;
  j.curvature_out = kout.curvature;
  j.curvature_derivative_in = kin.curvature_derivative;
  j.curvature_derivative_out = kout.curvature_derivative;
  const std::optional<Vec2> tin = end_tangent(in, SegmentEnd::end);
  const std::optional<Vec2> tout = end_tangent(out, SegmentEnd::start);
  if (!tin || !tout) {
    j.kind = JoinKind::degenerate;
    return j;
  }
  j.angle_deg = degrees(turning_angle(*tin, *tout));
  j.kind = join_kind(j.angle_deg, flags.smooth.value_or(false), thresholds);
  return j;
}

}  // namespace

JoinKind join_kind(double angle_deg, bool flagged_smooth, const JoinThresholds& thresholds) {
  const double a = std::abs(angle_deg);
  if (a <= thresholds.smooth_max_deg) return JoinKind::smooth;
  if (a < thresholds.kink_max_deg || flagged_smooth) return JoinKind::kink;
  return JoinKind::corner;
}

std::vector<Join> joins_of(const Contour& c, const JoinThresholds& thresholds) {
  std::vector<Join> joins;
  const std::size_t n = c.segments.size();
  if (n == 0) return joins;
  for (std::size_t i = 0; i < n; ++i) {
    if (i == 0 && !c.closed) continue;
    const Segment& in = c.segments[(i + n - 1) % n];
    joins.push_back(join_between(in, c.segments[i], i, c.nodes[i], thresholds));
  }
  return joins;
}

CurvatureJump curvature_jump(double in, double out, double units_per_em, const CurvatureJumpRule& rule) {
  const double jump = std::abs(in - out), larger = std::max(std::abs(in), std::abs(out));
  if (larger * units_per_em >= rule.large_em) return {jump / larger, true, rule.relative};
  return {jump * units_per_em, false, rule.absolute_em};
}

std::optional<CurvatureJump> curvature_jump(const Join& j, double units_per_em, const CurvatureJumpRule& rule) {
  if (!j.curvature_in || !j.curvature_out) return std::nullopt;
  return curvature_jump(*j.curvature_in, *j.curvature_out, units_per_em, rule);
}

const char* to_string(JoinKind kind) {
  switch (kind) {
    case JoinKind::smooth: return "smooth";
    case JoinKind::kink: return "kink";
    case JoinKind::corner: return "corner";
    case JoinKind::degenerate: return "degenerate";
  }
  return "corner";
}

}  // namespace gf
