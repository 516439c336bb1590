// Where points fall on a cubic: chord-length parameters to start from, and the Newton step
// toward a point's foot (the parameter where C(t) − p is normal to C′(t)).
#pragma once

#include <span>
#include <vector>

#include "geom/bezier.hpp"

namespace gf {

/// The points' cumulative chord lengths over their total, 0 … 1; all 0 where the points do not
/// move (the caller checks `back()`).
std::vector<double> chord_length_parameters(std::span<const Vec2> points);

/// One Newton step on f(t) = (C(t) − p) · C′(t): t moves by −along / slope. A slope not positive
/// means t is not near a foot (a point beyond the curve's centre of curvature).
struct FootStep {
  double along;  ///< f(t)
  double slope;  ///< f′(t) = C′·C′ + (C − p)·C″
};
FootStep foot_step(const Cubic& c, Vec2 p, double t);

}  // namespace gf
