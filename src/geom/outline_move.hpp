// How far a stretch of outline moves when some of its segments are replaced: the two-sided
// Hausdorff distance between the old and the new segments, sampled along them.
#pragma once

#include <initializer_list>
#include <limits>

#include "geom/segment.hpp"

namespace gf {

/// How far the outline moves, both ways, from the segments `before` to `after`, measured on
/// points `spacing` apart; past `limit`, only that it is past.
double outline_move(std::initializer_list<Segment> before, std::initializer_list<Segment> after, double spacing,
                    double limit = std::numeric_limits<double>::infinity());

}  // namespace gf
