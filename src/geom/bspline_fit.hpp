// Least-squares cubic B-spline through a point sequence (seed 000 [0038]–[0045]): chord-length
// parameters, uniform clamped knots, the end conditions as Lagrange-multiplier constraints;
// returned as the cubic Bézier of each span, so everything downstream gets a smooth curve with
// analytic derivatives.
#pragma once

#include <span>
#include <vector>

#include "geom/bezier.hpp"

namespace gf {

struct BSplineFit {
  std::vector<Cubic> spans;
  double max_residual = 0.0;  ///< largest distance of a point from the curve at its parameter
};

/// `span_count` ≥ 1; needs at least span_count + 3 distinct points (fewer give an empty fit).
/// `closed`: the sequence ends where it starts, and the fit is G1 across that seam (a closed
/// fit needs span_count ≥ 2).
BSplineFit fit_cubic_bspline(std::span<const Vec2> points, int span_count, bool closed = false);

/// The fit with the fewest spans (doubling from 1) whose max_residual is within `tolerance`,
/// as seed 000 raises the segment count; the last one tried when none is (check max_residual).
BSplineFit fit_cubic_bspline_within(std::span<const Vec2> points, double tolerance, bool closed = false);

}  // namespace gf
