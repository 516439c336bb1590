// Arc length of a segment by adaptive Gauss–Kronrod quadrature of |C'(t)|.
#pragma once

#include "geom/segment.hpp"

namespace gf {

struct ArcLength {
  double length;
  /// The quadrature's error estimate; `converged` is false when it exceeds the requested
  /// relative tolerance.
  double error_estimate;
  bool converged;
};

/// Length of the part t0..t1 (t0 <= t1), to `relative_tolerance` of the segment's size.
ArcLength arc_length(const Segment& s, double t0 = 0.0, double t1 = 1.0,
                     double relative_tolerance = 1e-12);

/// A fast estimate for checks and layout: 16-point Gauss–Legendre on t0..t1, no error
/// control (about 1e-7 relative on font curves; worse across a cusp).
double arc_length_estimate(const Segment& s, double t0 = 0.0, double t1 = 1.0);

}  // namespace gf
