// Cubic Bézier G2 Hermite interpolation (de Boor, Höllig & Sabin 1987): the cubic from P0 to P3
// with given unit tangents and signed curvatures at both ends. With P1 = P0 + a·T0,
// P2 = P3 − b·T3, D = P3 − P0 and c = T0 × T3, the end curvatures of a cubic are
//   κ0 = 2/3 · (T0 × D − b c) / a²,    κ3 = 2/3 · (D × T3 − a c) / b²,
// so the handle lengths a, b > 0 solve a quartic; there may be none, one or several.
#pragma once

#include <optional>
#include <vector>

#include "geom/bezier.hpp"
#include "geom/curvature.hpp"

namespace gf {

struct HermiteEnd {
  Vec2 point;
  Vec2 tangent;      ///< unit, along the direction of travel
  double curvature;  ///< signed, left turns positive
};

/// Every cubic with both handle lengths in (0, max_handle] that meets the ends with their
/// tangents and curvatures; empty when there is none. max_handle defaults to 2 |P3 − P0|.
std::vector<Cubic> g2_hermite_cubics(const HermiteEnd& start, const HermiteEnd& end, double max_handle = 0.0);

/// The cubic that meets both ends with their tangents and the curvature of the end that is not
/// `free` (a corner's curvature binds nothing), its handle at `free` `free_handle` long. With a
/// free start, b = √(2/3 · (D × T3 − a c) / κ3) from the equation for κ3 above; a free end
/// likewise from κ0. None where no positive handle gives that curvature (a flat one gives none)
/// or it passes max_handle (default 2 |P3 − P0|).
std::optional<Cubic> g2_hermite_cubic_with_free_end(const HermiteEnd& start, const HermiteEnd& end, SegmentEnd free,
                                                    double free_handle, double max_handle = 0.0);

/// As g2_hermite_cubic_with_free_end where the bound end is flat (κ = 0, a line join): its
/// far control point must lie on its tangent line, so the free end's handle is fixed (free end:
/// b = (T0 × D) / c; free start: a = (D × T3) / c) and the flat end's handle, `flat_handle`,
/// is the one to choose. None where the tangents are parallel or the fixed handle is not in
/// (0, max_handle].
std::optional<Cubic> g2_hermite_cubic_from_flat_end(const HermiteEnd& start, const HermiteEnd& end, SegmentEnd free,
                                                    double flat_handle, double max_handle = 0.0);

}  // namespace gf
