// What a change to a few cubics of an outline must not worsen, taken over those cubics
// together: a change may move a turn from one of them to another, but not add one.
#pragma once

#include <span>

#include "geom/bezier.hpp"

namespace gf {

struct ShapeTraits {
  int extrema = 0;        ///< horizontal and vertical turns inside (inner_axis_extrema), summed
  int inflections = 0;    ///< summed
  double turning = 0.0;   ///< the largest of the cubics' (cubic_turning)
  double overreach = 0.0; ///< the largest (overreach_length)
  double variation = 0.0; ///< of κ inside (curvature_shape), summed
  bool crowded = false;   ///< any handle crowding its node (crowds_a_node)
};
ShapeTraits shape_traits(std::span<const Cubic> cubics);

/// How far a changed cubic may turn beyond the old ones (a fold turns half a turn more).
inline constexpr double turning_slack = 0.35;

/// Whether cubics of traits `now` replacing ones of `old` gain an extremum or an inflection,
/// fold, reach out farther or crowd a node. Their curvature variation each caller bounds
/// (varies_more).
bool worsens(const ShapeTraits& now, const ShapeTraits& old);

/// Whether `now` varies its curvature by more than `share` times what `old` did and `per_em`
/// (κ·UPM) besides.
bool varies_more(const ShapeTraits& now, const ShapeTraits& old, double share, double per_em, double units_per_em);

}  // namespace gf
