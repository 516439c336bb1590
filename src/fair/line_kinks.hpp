// The last pass over a faired contour: the kinks left between two lines (no run passes through
// them) merged or filleted by the passes of fair/kink_fillet.hpp, each pass kept only where the
// contour stays within the tolerance.
#pragma once

#include "geom/contour.hpp"

namespace gf {

/// A faired contour with its line kinks taken away, and its distance from the source.
struct LineKinksTaken {
  Contour contour;
  double deviation = 0.0;
  bool changed = false;  ///< whether any pass took a kink
};

/// `faired`, `deviation` units from `source`, with its line kinks merged where the lines made one
/// stay within `tolerance_units` (merge_line_kinks), then filleted within what the contour leaves
/// of the tolerance: on `integer_grid`, the kinks whose lines leave no whole legs at a moved
/// vertex first (within that, then within nearly the whole tolerance: the lines are the
/// source's, and the contour's largest distance lies elsewhere, often a curve's: Liberation
/// Sans's M came 2.26 units from its source at 2.56, which left its stem's kinks 0.28), then
/// every kink with whole legs (fillet_line_kinks), then the rest at moved vertices within nearly
/// the whole tolerance. The smaller allowance first keeps the vertex close: Open Sans's d,
/// filleted at the larger alone, had its stem tilted a unit off the vertical. Straight quadratics
/// and cubics count as lines (Liberation Sans Narrow's V: its inner vertex drawn as quadratics
/// whose control point sits on their start, 0.2–2.8° apart) and are written as lines where a
/// pass changed the contour.
LineKinksTaken without_line_kinks(const Contour& faired, double deviation, const Contour& source,
                                  double tolerance_units, bool integer_grid);

}  // namespace gf
