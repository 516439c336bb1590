// Stem jogs: a straight line that a curve continues tangentially, as a flat S a few units
// across, back to the line's direction, before the curve turns away (DejaVu Sans Bold's u: its
// stem's line ends 400 units above the bowl, and a quadratic S carries the stem 2 units over
// on the way down). Faired as drawn, the S keeps κ = 0 at the line and at its far end only in
// floating point: on the integer grid, a cubic between two parallel tangents 2 units apart
// cannot leave both with κ = 0, and each end jumps. The S is noise on a straight stroke; the
// stem is straightened first: one line, parallel to the old one and halfway across the jog,
// from the line's start to where the S ends, and the curve continues from there.
#pragma once

#include "fair/node_moves.hpp"

namespace gf {

struct JogLimits {
  double max_move_units = 1.0;  ///< half the jog: the most any control point may move
};

/// `contour` with each stem jog straightened: a line, then one to three cubics that leave it
/// tangentially (within the kink limit; no node from the line's end on flagged a corner), stay
/// within the jog's width of it and end parallel to it (within the kink limit, on its side of the
/// join), at least one unit and at most twice `max_move_units` across and flatter than the kink
/// limit, then a curve. The line and those cubics become one line parallel to the line, half the
/// jog across; the line's start and the curve after the jog move by half the jog across the line (a
/// curve takes its handle along, a line its end; neither may be a curve shorter than twice the
/// jog). The same read backwards: a curve, a jog, then the line. No control point moves more than
/// `max_move_units`.
MovedContour straighten_stem_jogs(const Contour& contour, const JogLimits& limits);

}  // namespace gf
