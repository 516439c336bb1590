// Moving a contour's nodes before the fairing (fair/upright_lines, fair/stem_jogs): a node
// takes its curves' handles along, and how far any control point moved bounds how far the
// contour did.
#pragma once

#include <optional>

#include "geom/contour.hpp"
#include "geom/curvature.hpp"

namespace gf {

/// A contour with some nodes moved before the fairing, and how far.
struct MovedContour {
  Contour contour;     ///< with_cubics of the source when anything moved, else the source
  double moved = 0.0;  ///< units: the most any control point moved (a bound on the contour's move)
  int changes = 0;     ///< how many lines stood up or jogs straightened
};

/// `s` with its node at `end` moved by `v`: a line (or a straight cubic) just its end; a curve
/// takes its handle along, turned onto `along` (unit, the direction of travel) where given, so
/// that a tangential join stays tangential, else kept parallel (its tangent kept).
Segment with_end_moved(const Segment& s, SegmentEnd end, Vec2 v, std::optional<Vec2> along = std::nullopt);

/// How far the farthest control point of `was` moved in `now` (a Bézier curve moves by at most
/// that); a straight cubic made a line compares its ends.
double largest_move(const Segment& was, const Segment& now);

}  // namespace gf
