// Segments that are straight whatever their kind, and contours with them written plainly: a
// straight cubic as its line, and straight segments running on along one line as one.
#pragma once

#include "geom/contour.hpp"

namespace gf {

/// A cubic whose control points lie on its chord's line and which never runs back along it is a
/// line: its point set is the chord. Its handles may reach past each other or past its ends
/// (rounding leaves such handles on short stems: (424, 73) (424, 44) (424, 47) (424, 45)).
bool is_straight(const Cubic& c);
/// A line, or a quadratic or cubic that is_straight.
bool is_straight_segment(const Segment& s);
/// `contour` with each quadratic or cubic that is_straight written as its line.
Contour with_straight_segments_as_lines(const Contour& contour);

/// `contour` with each smooth node between two straight segments that run on along one line
/// (the second leaving the node the way the first arrived) removed, the two written as one: a line
/// where either was a line, else the cubic of the first's first handle and the second's second
/// (a line where that cubic would run back). Every control point lies on the joined chord, so
/// the outline is the same point set, its curvature 0 there as before; only the node goes. A
/// closed contour keeps its first node (where it starts).
Contour with_straight_runs_joined(const Contour& contour);

}  // namespace gf
