// The LCG slope α of a given smooth curve (lac-math.md §4, seed 000 [0028]): least squares of
// Y = log|κ/κ_s| against X = log ρ = −log|κ| over samples uniform in arc length, with analytic
// κ and κ_s from the curve's own Bézier segments (never finite differences of positions).
// The pitfalls of §4.3 are handled: near-constant curvature is reported as an arc, and the
// ends of the X range (near an inflection every curve looks like α = −1; near a curvature
// extremum the graph turns vertical) are trimmed.
#pragma once

#include <span>

#include "geom/segment.hpp"

namespace gf {

struct LcgSlope {
  enum class Kind {
    slope,         ///< α estimated
    arc,           ///< curvature nearly constant: every α fits (use a default)
    undetermined,  ///< too few usable samples (straight, or curvature not monotone)
  };
  Kind kind = Kind::undetermined;
  double alpha = 0.0;
  double intercept = 0.0;     ///< C of Y = αX + C
  double rms_residual = 0.0;  ///< of the fit, in Y
  int samples_used = 0;
};

struct LcgOptions {
  int samples = 400;
  double trim_fraction = 0.08;       ///< of the X range, at each end
  double arc_curvature_ratio = 1.01;  ///< max|κ|/min|κ| below this is an arc
};

/// `curve`: consecutive segments of one smooth piece (e.g. the spans of a B-spline fit).
LcgSlope estimate_lcg_slope(std::span<const Segment> curve, const LcgOptions& options = {});

}  // namespace gf
