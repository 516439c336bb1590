// A contour cut into what the fairing treats separately: straight lines, which stay as they
// are, and smooth runs of curves between corners and lines. A run ends at a corner (its own
// tangent there, curvature free) or where it meets a line without a corner (the line's
// direction and κ = 0, so the line–curve join becomes G2). A closed contour with neither is
// one closed run.
#pragma once

#include <optional>
#include <span>
#include <variant>
#include <vector>

#include "geom/contour.hpp"
#include "geom/join.hpp"
#include "geom/straight_segments.hpp"

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
  /// Kind corner: a kink against the line beyond, opened to the corner floor
  /// (PlanOptions::open_against_lines); the fairing keeps its tangent.
  bool opened = false;
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

/// A corner the fairing keeps turns by at least this much (or by what the source turns, if
/// less, and more than the kink limit): half a degree past the limit, room for rounding
/// (handle_steps keeps every corner from the limit since stop 73; a degree and a half while it
/// kept one between cubics only from a degree past it: EB Garamond a–z A–Z 100 g2-jumps then,
/// 97 now).
inline constexpr double corner_floor_deg = kink_limit_deg + 0.5;

struct PlanOptions {
  double corner_angle_deg;
  /// Each run's corner ends say what lies beyond them (RunEnd::beyond), so the fairing keeps
  /// them corners; without, a corner the fairing turns into a kink is noise (handwriting:
  /// fair/kinked_corners).
  bool corners_stay = false;
  /// A curve meeting a line at more than this is a corner (by default the kink limit: only a
  /// tangential line join is made G2).
  double tangential_line_deg = kink_limit_deg;
  /// A kink of 2° or more where a curve meets a line, turning against the curve's bend by more
  /// than the curve's cubic turns, stays a corner, the curve's tangent turned so the corner
  /// turns by the corner floor (smooth, the curve could meet the line only through an
  /// inflection the source does not draw).
  bool open_against_lines = false;
  /// A line shorter than this (units) that a curve meets tangentially, with a corner or
  /// another such curve at its other end, is the curve's stretch drawn straight and becomes
  /// part of its run (2: as short as the cubics rounding merges).
  double stub_line_units = 2.0;
  /// Where given, a curve meeting such a line within this (degrees), not only tangentially,
  /// makes the line its own (handwriting: a tracer's stub meets the curve at a scan's kink).
  std::optional<double> stub_turn_deg{};
};

/// Corners: joins whose smooth flag says so where the source has flags, else joins turning by
/// more than the corner angle (and line joins as PlanOptions says). The joins at
/// `smooth_nodes` (source node indices) are smooth whatever their angle: a curve meeting a line
/// there meets it tangentially, and two lines meeting there become one.
ContourPlan plan_contour(const Contour& contour, std::span<const std::size_t> smooth_nodes, const PlanOptions& options);

/// The angle a corner's tangent (now `current`) may be turned to on the way to `wanted`: all
/// the way, or as far as the corner still turns by the floor against the piece beyond it, the
/// way the source turns; nullopt where the floor leaves no turn at all, and at a corner opened
/// to the floor (RunEnd::opened), whose tangent was set to turn so. The floor: a corner the
/// source turns by the kink limit or more keeps turning by corner_floor_deg (or by what the
/// source turns, if less); turned further, the kink pass would make it smooth, and the corner
/// the source drew would be lost (Carlito's X: a terminal's curve met its diagonal at 6.6°, and
/// the symmetric arc at 2.4°). corner_floor_deg leaves room for rounding.
std::optional<double> kept_corner_angle(const RunEnd& end, bool at_start, double current, double wanted);

/// How many of the plan's line joins are corners opened against their lines (RunEnd::opened).
std::size_t opened_corners(const ContourPlan& plan);

}  // namespace gf
