// Kinks between two lines taken away: the lines merged into one, or filleted G2 by a cubic with
// both handles on the kink's vertex.
#pragma once

#include <optional>

#include "geom/contour.hpp"

namespace gf {

/// The two legs of a fillet (P0, C, C, P3) at the kink C: P0 − C back along the line before,
/// P3 − C on along the line after.
struct FilletLegs {
  Vec2 back, on;
};

/// The legs, at most `most_back` and `most_on` long, of the fillet at the kink where `before`
/// ends and `after` starts that stays within `allowance_units` of the two lines and whose
/// shorter leg is longest (then whose sum is): the fillet turns most gently there. The longer
/// leg at most four times the shorter, or its line's shortest leg (since stop 97; before, a
/// leg took the whole of a long line beside a short one, and drew it as a curve). On
/// `integer_grid`, whole numbers of each line's primitive step. None where no legs do.
std::optional<FilletLegs> fillet_legs(const Line& before, const Line& after, double most_back, double most_on,
                                      double allowance_units, bool integer_grid);

/// `contour` with the joins of two lines that turn by more than the smooth limit and less than
/// the kink limit taken away where the lines (or more, kink after kink) made one keep every
/// node they drop within `allowance_units` of it: no fillet is needed there (Femke Klaver's B:
/// a sliver's 593-unit side, bent 2.5° at both ends, whose primitive step (−26, −593) leaves a
/// fillet no whole legs on the grid; Yusei Magic's R: a short curve drawn as its 3.6-unit chord,
/// 1.6° off the line before it). Along a chain of such kinks, each line runs on as far as that
/// holds (Liberation Sans Narrow's V: its inner strokes bend 2.8° 100 units above the vertex and
/// by under a degree below, and only the bends below go), so the kinks left are fewer, for the
/// fillets. At a closed contour's first node, the contour then starts where its last line did.
/// Contours with no such kink, or that would keep fewer than three segments, come back
/// unchanged. With `only_against_neighbours`, only the kinks no fillet may take because it
/// would bend against its neighbours (fillet_line_kinks) merge: the rest are left to the fillets
/// (URW P052's Z: a top drawn as four lines sagging three units, bent 1.1° and 0.63° one way,
/// then 0.28° back; merged whole it kept a 1.33° kink whose lines, steps (206, 3) and (347, 3),
/// leave a fillet no legs).
Contour merge_line_kinks(const Contour& contour, double allowance_units, bool only_against_neighbours = false);

/// `contour` with every join of two lines that turns by more than the smooth limit and less
/// than the kink limit (geom/join.hpp: no corner was drawn there) replaced by a fillet: the
/// cubic (P0, C, C, P3) from a point P0 on the line before, through handles both at the vertex
/// C, to a point P3 on the line after. Each handle lies on the line its end leaves along, and
/// the other handle on it too, so κ = 0 at both ends (lac-math.md §3.2's line join): both
/// joins are G2, where the kink was a break in direction. The shorter leg is the longest that
/// keeps the fillet within `allowance_units` of the two lines, each leg at most its line (half
/// of it where the line's other end is a kink too); on `integer_grid`, a whole number of its
/// line's primitive steps (P0 and P3 on the grid). A kink whose fillet would bend against the
/// curves or kinks next to it along the contour, or against the one of them whose bend is
/// known, stays (an inflection the kink did not count as); between neighbours bending opposite
/// ways the kink lies on an inflection already, and the fillet only moves it.
/// Contours with no such kink come back unchanged.
/// On `integer_grid`, a kink left so (no whole legs within the allowance: a line's primitive
/// step longer than the leg may be) is then tried as fillet_kinks_at_moved_vertices does.
Contour fillet_line_kinks(const Contour& contour, double allowance_units, bool integer_grid);

/// The kinks of a closed contour on the integer grid between two lines whose far ends are
/// corners, each, or two turning the same way with a line between them (Liberation Sans's N:
/// (5, −97) and (5, −167) either side of a 1.2° kink, a stem's taper), filleted at a vertex
/// moved to a grid point within twice `allowance_units` (and four units) of the kink, or of where the
/// outer lines meet: each outer line redrawn from its far corner to that vertex, which turns
/// the corner by a fraction of a degree, and the fillet (P0, V, V, P3) from a grid point of one
/// to a grid point of the other, each leg at most half its line, the shorter as long as the
/// allowance lets the whole stretch stay within it of the lines as drawn. None across the
/// contour's seam; contours with no such kink come back unchanged.
Contour fillet_kinks_at_moved_vertices(const Contour& contour, double allowance_units);

/// As fillet_kinks_at_moved_vertices, only the kinks with no whole legs within
/// `leg_allowance_units` (fillet_line_kinks on the grid), each with its same-way neighbour
/// where a line lies between them: to be tried before fillet_line_kinks, whose fillet of the
/// neighbour alone would take its half of that line and leave the kink between lines whose far
/// ends are no longer both corners (Liberation Sans's M: 2.79° at (420, 960), its legs on a
/// line of step (−123, 320), beside a 1.53° kink with legs).
Contour fillet_legless_kinks_at_moved_vertices(const Contour& contour, double leg_allowance_units,
                                               double allowance_units);

}  // namespace gf
