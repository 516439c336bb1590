#include "fair/shape_traits.hpp"

#include <algorithm>

#include "fair/cubic_change.hpp"
#include "geom/critical_points.hpp"

namespace gf {

ShapeTraits shape_traits(std::span<const Cubic> cubics) {
  ShapeTraits t;
  for (const Cubic& c : cubics) {
    t.extrema += inner_axis_extrema(c), t.inflections += static_cast<int>(inflections(c).size());
    t.variation += curvature_shape(c, 0.0).variation;
    t.turning = std::max(t.turning, cubic_turning(c)), t.overreach = std::max(t.overreach, overreach_length(c));
    t.crowded = t.crowded || crowds_a_node(c);
  }
  return t;
}

bool worsens(const ShapeTraits& now, const ShapeTraits& old) {
  return now.extrema > old.extrema || now.inflections > old.inflections || now.turning > old.turning + turning_slack ||
         now.overreach > old.overreach || (now.crowded && !old.crowded);
}

bool varies_more(const ShapeTraits& now, const ShapeTraits& old, double share, double per_em, double units_per_em) {
  return now.variation > share * old.variation + per_em / units_per_em;
}

}  // namespace gf
