// Tight turns: where a handwritten contour turns through a corner's worth within a few units
// (the pen reversing at the foot of an m, the tip of a hook), a scan draws a bend of small
// radius. Faired as a curve, that radius comes back as a curvature spike, κ·UPM in the
// hundreds, which alone holds most of a glyph's curvature variation. It reads as a corner and
// is made one: the contour is split at the turn's sharpest point, and the pieces either side
// of it keep the directions the contour had before and after the turn. A stroke's end that
// narrow (a hairline's) turns back on itself and becomes a needle.
#pragma once

#include <span>
#include <vector>

#include "fair/contour_plan.hpp"
#include "geom/contour.hpp"

namespace gf {

struct TightTurn {
  std::size_t node;  ///< the node at the turn's sharpest point, in the split contour
  Vec2 tangent_in;   ///< unit: the direction before the turn
  Vec2 tangent_out;  ///< unit: the direction after it
};

struct TightTurnLimits {
  double min_turn_deg = 30.0;   ///< a turn through less is a bend, not a corner
  /// Through more, the stretch is a loop. A turn back on itself within the deviation (a
  /// hairline's end, narrower than the tolerance) is a needle: faired round, the guide drew it
  /// as a spike of its own (Typo Script's loops, tips of 5 units against 14: κ·UPM 1,450).
  double max_turn_deg = 200.0;
  /// The turn's sharpest radius at most this, and the bend within this of the two lines
  /// through its sharpest point along its directions before and after. A turn's stretch keeps
  /// its peak's sign and a radius of at most twice this, and ends no nearer a corner.
  double deviation_units = 5.0;
};

struct TightTurns {
  Contour contour;  ///< the same curve split at each turn (with_cubics), its new nodes not smooth
  std::vector<TightTurn> turns;
};

/// The tight turns of `contour` (joins turning by more than `limits.min_turn_deg` already
/// are corners, and no turn runs across one or an open contour's end). A contour with none
/// comes back unchanged.
TightTurns find_tight_turns(const Contour& contour, const TightTurnLimits& limits);

/// The runs of `plan` (made from `turns.contour`) that end at a tight turn leave it along the
/// turn's directions rather than the bend's own tangent there.
void aim_runs_at_tight_turns(ContourPlan& plan, std::span<const TightTurn> turns);

}  // namespace gf
