// Signed curvature and its arc-length derivative on a segment.
//
// With d1 = C'(t), d2 = C''(t), d3 = C'''(t), f = |d1|^2 and g = d1 × d2:
//   κ = g / f^(3/2)                                 (lac-math.md §4.1; seed 001 eq. 6)
//   dκ/ds = (d1 × d3 · f − 3 g (d1 · d2)) / f^3       (differentiate κ, divide by |d1|)
// Curvature is positive where the curve turns left.
#pragma once

#include <optional>

#include "geom/segment.hpp"

namespace gf {

struct Derivatives {
  Vec2 point, d1, d2, d3;
};

Derivatives derivatives_at(const Segment& s, double t);

/// Signed curvature; nullopt where the speed vanishes (a cusp or a retracted handle's end).
std::optional<double> curvature(const Derivatives& d);
/// dκ/ds; nullopt where the speed vanishes.
std::optional<double> curvature_derivative(const Derivatives& d);

/// κ at many parameters of one cubic: curvature(derivatives_at(c, t)), its hodographs made
/// once (the rounding measures every candidate cubic at 33 places).
class CurvatureAlong {
 public:
  explicit CurvatureAlong(const Cubic& c) : d1_(c.hodograph()), d2_(d1_.hodograph()) {}
  std::optional<double> at(double t) const { return curvature(Derivatives{{}, d1_.point_at(t), d2_.point_at(t), {}}); }

 private:
  Quad d1_;
  Line d2_;
};

enum class SegmentEnd { start, end };

/// Unit tangent in the direction of travel at an end. A retracted handle (coincident control
/// point) takes the direction of the next distinct control point; nullopt for a segment whose
/// points all coincide.
std::optional<Vec2> end_tangent(const Segment& s, SegmentEnd end);

/// Curvature and dκ/ds at an end, taking the one-sided limit where a handle is retracted:
/// that limit is 0 when the curve leaves the node straight, and unbounded (nullopt) otherwise.
struct EndCurvature {
  std::optional<double> curvature;
  std::optional<double> curvature_derivative;
};
EndCurvature end_curvature(const Segment& s, SegmentEnd end);

}  // namespace gf
