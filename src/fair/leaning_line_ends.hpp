// A curve meeting a line that leans a little off an axis, on the grid. The line's nearest grid
// directions step far ((1, 71) for a stem 0.8° off the vertical), and G1 exact at the join needs
// the curve's handle there to be whole such steps: longer than the curve (the rounding slid the
// curve back along the line and it folded: Gentium Plus's M, Comic Neue's i). So before
// rounding, the join is moved onto the axis: the curve leaves along the axis (its last handle
// turned by the lean, its far handle onto the axis line), a fillet (J, V, V, Q) with both
// handles on the vertex V = J + m·axis turns onto the line, and the line starts at Q, one of
// its steps beyond V. The fillet has κ = 0 at both ends (V lies on both tangent lines), so
// both joins stay G2; J takes the axis as its grid step, Q the line's. Where the curve's last
// cubic is a ramp from an H/V extremum too flat for the grid, the fillet starts at the
// extremum instead, with its curvature there.
#pragma once

#include <vector>

#include "fair/outline_nodes.hpp"

namespace gf {

struct LeaningLineLimits {
  double min_lean_deg = 0.05;   ///< a line nearer its axis is on it (the kink limit of the check)
  double max_lean_deg = 2.0;    ///< a line leaning further has short steps near it
  double max_move_units = 0.5;  ///< how far the outline may move (both ways, sampled)
};

/// Where a smooth node joins a cubic to a line leaning between the limits' angles off the
/// nearest axis, whose shortest grid step (its ends moved a unit or less) is longer than the
/// cubic's handle there, the line at least three such steps long, and the fillet would turn
/// the way the cubic bends there (else an inflection): the fillet put in, where the outline
/// then moves by no more than `max_move_units`; or, where the cubic runs from a smooth H/V
/// extremum along that axis and stays within half a unit of it, the fillet from the extremum
/// in the cubic's place, G2 there, its first handle at least 8 units long. How many joins were
/// filleted.
int fillet_leaning_line_ends(std::vector<OutlineNode>& nodes, bool closed, const LeaningLineLimits& limits);

}  // namespace gf
