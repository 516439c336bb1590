// Spurs: where a scanned stroke's outline doubles back along itself. An autotracer that
// overshoots a corner of the pen stroke draws the edge on past it, turns round (a cusp of
// nearly 180°) and runs back over what it drew before going on: a needle of no width lying on
// the stroke's own edge (Breip's E: 25 units back from its top bar's end, and a horizontal
// extremum inside the hook the fairing made of it). Nothing of it shows in the filled glyph,
// so it is cut out before the fairing, whose distances are still measured from the source.
#pragma once

#include "fair/node_moves.hpp"
#include "geom/contour.hpp"

namespace gf {

struct SpurLimits {
  double min_turn_deg = 170.0;  ///< a cusp turns through at least this at the spur's foot
  /// The outline comes back to within this of the cusp where the spur ends; every point of
  /// the spur lies within it of the outline outside.
  double width_units = 2.0;
  double max_length_units = 120.0;  ///< along the outline, out and back
};

/// `contour` with each spur cut out: from a cusp turning by `min_turn_deg` or more, the
/// stretch of outline, out and back, up to where it returns to within `width_units` of the
/// cusp (either way along the outline from it, within `max_length_units`), where every point
/// of that stretch lies within `width_units` of the rest of the outline. The outline after
/// the stretch starts at the cusp (its first control points moved with it). A closed contour
/// only; `changes` counts the spurs cut, `moved` the farthest a kept end moved.
MovedContour cut_spurs(const Contour& contour, const SpurLimits& limits);

}  // namespace gf
