// Lines of an outline being rounded to the grid, where a curve meets them tangentially. The
// curve's handle there must lie on the line, a whole number of the line's primitive steps from
// the join, for G1 to stay exact; a diagonal line between nearby grid points may have a long
// primitive step (DejaVu's S spine: (122, −25); Inter's y: (−65, −176)), and the handle would
// be at least that long. So the ends of each run of lines meeting at corners are chosen
// together (Viterbi over the run): each end at its nearest grid point or a neighbour, or any
// grid point within what the tolerance leaves there (up to 3 units: a line a degree off the
// vertical may stand upright; fair/upright_lines stands most such lines up before the fairing),
// the line turning no more than a node may; and where
// a curve's handle would then grow or shrink by more than a quarter, the curve's end may also
// slide along its line (a curve leaves a G2 line join straight, κ = 0, so starting it a few
// units earlier or later along the line, its handle's tip kept, barely moves it) to where the
// line's step is short. A curve too short for even one step of its line (Because We Build's v:
// 2.4 units from a 2° line to the bowl's foot, where every grid direction near 2° steps 17 units
// or more) slides back along the line, up to half of it and 96 units or, on a line of two steps
// or more, one step, and takes over that stretch: the curve then has room for the step instead
// of folding back on itself.
#pragma once

#include <optional>
#include <vector>

#include "fair/handle_steps.hpp"
#include "fair/outline_nodes.hpp"

namespace gf {

/// Places the nodes of every run of lines that a curve meets tangentially: `rounded` gets
/// their grid points and each such curve's handle on its line, `steps` the line's primitive
/// direction at those joins. Each line that a curve meets costs its largest move (of its ends
/// and the curves' handles; a slid end by how far its curve then strays from `exact`, plus a
/// fiftieth of the slide) and a tenth of a unit per unit of step, and more where the curve's
/// far handle cannot give it κ = 0 at the join (|κ| within a twentieth of
/// `limits.flat_curvature`: what the line leaves of the tolerance, at least a unit) and more
/// again where the curve would gain an H/V extremum, where its far node's direction runs
/// along the line off it (no handle seats it: the curve is an S), or where its handle on the
/// line reaches past its far node (it folds back into it); no line turns by more than
/// 0.1 rad or what its nearest grid points turn it, and a line horizontal or vertical on the
/// grid keeps its y or x (a baseline, a cap height, a stem's side); the run's least total
/// wins. A slid
/// end stays within what the line has left of the tolerance (`limits.allowance_at`) of it,
/// both ways where it slid back past its handle. Ends slide where a handle on a line of long
/// step strays (moves by more than a quarter of its length and its curve's allowance) or
/// reaches past three quarters of its curve's chord. An end not slid goes to its nearest grid
/// point or a neighbour of it: any neighbour, or with `limits.any_grid_neighbour` false only
/// those within its allowance. A corner takes its curve's handle along (an extremum on it
/// stays there).
void place_lines_on_grid(const std::vector<OutlineNode>& exact, std::vector<OutlineNode>& rounded,
                         std::vector<std::optional<Vec2>>& steps, bool closed, const HandleStepLimits& limits);

}  // namespace gf
