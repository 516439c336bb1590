// Lines a degree or two off upright (or level) where a curve meets them tangentially, stood on
// the axis before the fairing rather than in rounding. On the integer grid such a line's
// nearest direction steps 30 units or more, longer than the handle of a curve meeting it can
// be, so rounding stands it upright (fair/line_rounding.hpp) — but after the fairing has bent
// the curve to the slant. The written curve then leaves the upright line, swings back to the
// faired curve's course and its extremum beside the line's old end: an S. Comic Neue's i: a
// stem 0.8° off the vertical, an inflection where it meets each cap. Stood up first, the
// curve is faired to the upright line, and its extremum is the join.
#pragma once

#include "fair/node_moves.hpp"

namespace gf {

struct UprightLimits {
  /// Off the axis; more is a slant the grid can step (1, 22) along. (At 2°, Open Sans's Q tail
  /// foot, 2.08° off level, was stood level only in rounding: its curve's extremum 39 units on
  /// came out a flat cubic, then κ·UPM 2.2.)
  double max_angle_deg = 2.5;
  double max_move_units = 3.0;  ///< the most any control point may move
};

/// `contour` with each line that a curve meets tangentially (turning less than the kink limit,
/// not flagged a corner) and that lies within `max_angle_deg` of an axis put on the axis
/// through its middle, where no control point moves more than `max_move_units`. Each end node
/// moves across the axis only, so a line it shares at a corner keeps its level (a stem on a
/// baseline); a curve takes its handle along, turned onto the axis where it met the line
/// tangentially (the join stays tangential), kept parallel at a corner, and kept parallel too
/// where turning it would move it past the limit but the curve turns four times as far as
/// that leaves its end off the axis (the fairing turns the end onto the line). Left slanted: a line
/// sharing a node with one stood up (the node would be pulled two ways), and one whose neighbour
/// at an end is a curve shorter than four times the move, or a line within 10° of the same axis
/// (a kink the fillet pass owns).
MovedContour stand_lines_upright(const Contour& contour, const UprightLimits& limits);

}  // namespace gf
