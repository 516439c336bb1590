// A contour cut into what the fairing treats separately: straight lines, which stay as they
// are, and smooth runs of curves between corners and lines. A run ends at a corner (its own
// tangent there, curvature free) or where it meets a line without a corner (the line's
// direction and κ = 0, so the line–curve join becomes G2). A closed contour with neither is
// one closed run.
#pragma once

#include <span>
#include <variant>
#include <vector>

#include "geom/contour.hpp"
#include "geom/join.hpp"

namespace gf {

enum class RunEndKind { corner, line };

struct RunEnd {
  RunEndKind kind = RunEndKind::corner;
  Vec2 tangent;  ///< unit, along the run's direction
  /// Kind line: how much of the line met there is this run's to take (a G3 run slides its end
  /// along the line): all of it when the line's other end is a corner, half when another run
  /// meets the line there too.
  double line_share = 0.0;
  /// Kind corner, where corners stay (plan_contour): the unit tangent of the piece on the
  /// corner's other side, along the contour (zero at an open contour's end, or where corners
  /// need not stay), against which the corner turns; and whether that piece is a line, whose
  /// direction the fairing keeps, rather than a curve, whose tangent it may turn too.
  Vec2 beyond{};
  bool beyond_line = false;
  bool operator==(const RunEnd&) const = default;
};

struct SmoothRun {
  std::vector<Cubic> cubics;  ///< the source's pieces, in order, none degenerate
  bool closed = false;        ///< the whole contour (no corner, no line)
  RunEnd start, end;          ///< open runs only
  bool operator==(const SmoothRun&) const = default;
  /// An open run that leaves a line at its start (meets one at its end) tangentially.
  bool starts_at_line() const { return !closed && start.kind == RunEndKind::line; }
  bool ends_at_line() const { return !closed && end.kind == RunEndKind::line; }
};

struct ContourPlan {
  std::vector<std::variant<Line, SmoothRun>> pieces;  ///< in order, each starting where the last ended
  bool closed = true;
  std::vector<std::size_t> start_nodes;  ///< the source node each piece starts at
};

/// The kink limit of geom/join.hpp: a join turning by less than this (and more than 0.05°) is
/// a kink, meant smooth; a corner must turn by at least this much.
inline constexpr double kink_limit_deg = JoinThresholds{}.kink_max_deg;

/// A cubic whose control points lie on its chord, in order, is a line.
bool is_straight(const Cubic& c);
/// A line, or a cubic that is_straight.
bool is_straight_segment(const Segment& s);

/// Corners: joins whose smooth flag says so where the source has flags, else joins turning by
/// more than `corner_angle_deg` (and a curve meeting a line at more than `tangential_line_deg`,
/// by default the kink limit: only a tangential line join is made G2). The joins at
/// `smooth_nodes` (source node indices) are smooth whatever their angle: a curve meeting a line
/// there meets it tangentially, and two lines meeting there become one. With `corners_stay`,
/// each run's corner ends say what lies beyond them (RunEnd::beyond), so the fairing keeps them
/// corners; without, a corner the fairing turns into a kink is noise (handwriting:
/// fair/kinked_corners).
ContourPlan plan_contour(const Contour& contour, double corner_angle_deg,
                         std::span<const std::size_t> smooth_nodes = {}, bool corners_stay = false,
                         double tangential_line_deg = kink_limit_deg);

}  // namespace gf
