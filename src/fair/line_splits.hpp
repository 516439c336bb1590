// A curve meeting a line whose primitive grid step is long: FreeSerif Italic's V, a stroke of
// step (373, 615), 719 units, against a 9-unit handle. No whole step of the line fits the
// handle, so rounding stretches the handle to one (and strays) or leaves the curve's end off the
// line (a kink); moving the line's end cannot help (ended a unit over, the line still steps
// (17, 28), 33 units). So where rounding did either (fair/outline_on_grid.hpp), the line is
// split at a grid point K near it where both parts step short: the curve's end goes to a grid
// point J near where it was and leaves along the short step of J–K, and the line turns at K by
// a fraction of a degree, the way the curve bends into J. That turn is a kink between two
// lines, which the fillets after rounding (fair/kink_fillet.hpp) take with whole legs on both
// short steps: the curve, the line J–K, the fillet and the rest of the line then all join G2.
#pragma once

#include <vector>

#include "fair/outline_nodes.hpp"

namespace gf {

struct LineSplitLimits {
  double max_move_units = 0.5;  ///< how far the outline may move (both ways, sampled)
  double max_turn_deg = 2.5;    ///< how far the curve's end may turn, and the line at K
};

/// Where node k, a smooth node J, joins a cubic to a line whose step (its ends on their nearest
/// grid points) is longer than the cubic's handle there: the line split at the grid point K,
/// within the first half of the line and `max_move_units` of it, where a fillet at K turns most
/// gently (its turn over its shorter leg, legs of whole steps up to 64 units or one step), then
/// where the steps of J–K and K–F (F the line's far end) are shortest. J moves to a grid point
/// within `max_move_units` across the line and a unit and a half along it; J–K's step is no
/// longer than the cubic's handle and turns the curve's end by no more than `max_turn_deg`;
/// K–F's step is shorter than the line's and 128 units at most; the line turns at K the way the
/// cubic bends into J, by no more than `max_turn_deg`; and the outline moves by no more than
/// `max_move_units`. J keeps its handle's length, along J–K's step, and takes that step as its
/// grid step; K, a corner, goes in beside J; both are pinned. False (the nodes unchanged) where
/// no such split is.
bool split_line_at(std::vector<OutlineNode>& nodes, bool closed, std::size_t k, const LineSplitLimits& limits);

/// Where no such split is, the line turning against the curve's bend whichever short step
/// J–K takes (Gentium Plus's M: a 4-unit handle into a leg of step (1, −111), the curve bending
/// away from the vertical), the curve is given room instead: where node k, a smooth node J,
/// joins a cubic to a line whose shortest grid step is longer than the cubic's handle there and
/// fits in the line twice, the cubic is split exactly (de Casteljau) at a node N whose tangent
/// runs along a short primitive grid direction, N's grid step, turned from J's tangent between
/// a third and two thirds of the way to the tangent at the cubic's far end. Rounding can then
/// slide J back along the line by a whole step, and the piece from J to N takes over that
/// stretch (fair/line_rounding.hpp); whole, the cubic would have had to turn within its last
/// few units, and strayed. False (the nodes unchanged) where node k is no such join or no such
/// direction is.
bool split_curve_beside_line(std::vector<OutlineNode>& nodes, bool closed, std::size_t k);

}  // namespace gf
