// How far a curve turns when every bend counts by its size, not by its sign: a loop or a cusp
// turns half a turn or more beyond what its end tangents say.
#pragma once

#include <span>

#include "geom/vec2.hpp"

namespace gf {

/// How far a curve sampled as `points` turns from tangent `start` to tangent `end`, every bend
/// of its polyline counted by its size (radians).
double absolute_turning(Vec2 start, std::span<const Vec2> points, Vec2 end);

}  // namespace gf
