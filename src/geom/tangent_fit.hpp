// The cubic with given ends and end tangent directions nearest a run of points: what a span can
// be where the curvature at its ends binds nothing (corners at both).
#pragma once

#include <optional>
#include <span>

#include "geom/bezier.hpp"

namespace gf {

/// The cubic from p0 to p3 leaving along the unit t0 and arriving along the unit t3 nearest
/// `points` (in order along the curve, its ends included): the two handle lengths by linear
/// least squares, first on the points' offsets at chord-length parameters, then, round after
/// round, on their offsets across the cubic from their feet on it (tangent distance
/// minimisation; the offset along the curve is the parameter's error, not the shape's). Points
/// taken from such a cubic give it back. None where a handle comes out not positive or the
/// points do not determine the two.
std::optional<Cubic> fit_cubic_with_end_tangents(Vec2 p0, Vec2 t0, Vec2 p3, Vec2 t3, std::span<const Vec2> points);

}  // namespace gf
