// The places along a segment that a designer and the fairing care about: inflections,
// curvature extrema, cusps and horizontal/vertical extrema, as parameters t in (0, 1).
//
// Inflections are the sign changes of g = C' × C'' (quadratic for a cubic: lac-math.md §4.1
// corrects the seeds' "cubic"); curvature extrema are the sign changes of
// h = 2 ġ f − 3 g ḟ with f = |C'|^2 (a quintic for a cubic; the seeds say sextic). A root of h
// where the speed vanishes is a cusp, not an extremum.
#pragma once

#include <vector>

#include "geom/segment.hpp"

namespace gf {

struct CurvatureExtremum {
  double t;
  double curvature;
  /// True where |κ| has a local maximum, false at a local minimum.
  bool maximum;
};

enum class Axis { horizontal, vertical };

/// A point where the tangent is horizontal (y' = 0, an extremum in y) or vertical (x' = 0).
struct AxisExtremum {
  double t;
  Axis tangent;
};

struct CriticalPoints {
  std::vector<double> inflections;
  std::vector<CurvatureExtremum> curvature_extrema;
  std::vector<double> cusps;
  std::vector<AxisExtremum> axis_extrema;  // ascending in t
};

/// All of them for one segment, each list ascending in t, all strictly inside (0, 1).
CriticalPoints critical_points(const Segment& s);

std::vector<double> inflections(const Segment& s);
std::vector<AxisExtremum> axis_extrema(const Segment& s);

}  // namespace gf
