// Where two end tangents of a curve meet: the one place a cubic between them can put both its
// handles and stay straight-ended there (κ = 0 at both ends, the cubic a, X, X, b).
#pragma once

#include <cmath>
#include <optional>

#include "geom/vec2.hpp"

namespace gf {

/// The point X where the line leaving a along u meets the line arriving at b along v, ahead of a
/// and behind b (X = a + s·u = b − t·v with s, t > 0). None where they run parallel
/// (|u × v| ≤ 1e-14·|u|·|v|) or meet elsewhere.
inline std::optional<Vec2> tangent_crossing(Vec2 a, Vec2 u, Vec2 b, Vec2 v) {
  const double det = cross(u, v);
  if (std::abs(det) <= 1e-14 * norm(u) * norm(v)) return std::nullopt;
  const Vec2 r = b - a;
  const double s = cross(r, v) / det, t = cross(u, r) / det;
  if (!(s > 0.0 && t > 0.0)) return std::nullopt;
  return a + u * s;
}

}  // namespace gf
