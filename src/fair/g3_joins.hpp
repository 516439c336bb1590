// How far a written outline carries G3: at its smooth joins between two curves, how often
// dκ/ds matches across. Under --continuity g3 the faired curve is G3 and the writeback carries
// it into the cubics (fair/g3_cubics); rounding to the grid then moves every point by up to
// half a unit, and dκ/ds, a third derivative, moves most. This counts what is left.
#pragma once

#include "geom/contour.hpp"

namespace gf {

struct G3JoinCount {
  int joins = 0;    ///< smooth joins between two curves (not lines)
  int matched = 0;  ///< of them, those whose dκ/ds jump is within the relative limit

  G3JoinCount& operator+=(const G3JoinCount& o) {
    joins += o.joins, matched += o.matched;
    return *this;
  }
};

/// The G3 bar's measure at each smooth join between two curves: |κ′− − κ′+| / max(|κ′−|, |κ′+|)
/// (0 where both are 0), matched where it is at most `relative` (the bar holds its median under
/// 0.05).
G3JoinCount g3_joins_of(const Contour& c, double relative = 0.05);

}  // namespace gf
