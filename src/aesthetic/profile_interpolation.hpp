// A G3 curve through given points with the curvature given at each (seed 004 §6): one
// curvature-profile segment (aesthetic/curvature_profile_segment.hpp) per span, every point's
// κ and κ′ shared by the two segments meeting there, so the joins are G3 by construction.
//
// What the caller may leave out, and how it is chosen:
//   tangent  first the tangent of the circle through the point and its two neighbours (at an
//            end, through the first or last three points; the chord with only two points),
//            then turned so that each span's G1 clothoid comes nearest the given curvatures at
//            its ends (least squares), leaving the span's profile little to bend;
//   κ′       from the secant slopes (κᵢ₊₁ − κᵢ)/Lᵢ over the G1 clothoid lengths Lᵢ of the
//            spans: their harmonic mean at an inner point (Fritsch–Butland, so κ(s) stays
//            monotone where the given curvatures are; 0 where the slopes differ in sign), the
//            end span's slope at an end.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "aesthetic/curvature_profile_segment.hpp"

namespace gf {

struct InterpolationPoint {
  Vec2 point;
  double curvature;                      ///< κ, left turns positive
  std::optional<double> curvature_slope; ///< κ′ = dκ/ds
  std::optional<double> tangent_angle;   ///< radians
};

struct ProfileSpline {
  std::vector<CurvatureProfileSegment> segments;  ///< span i from point i to i + 1; empty on failure
  std::vector<CurvatureEnd> ends;                 ///< every point's data as used, the chosen ones filled in
  std::string reason;                             ///< why not, naming the span, in one line
  bool ok() const { return !segments.empty(); }
};

/// At least two points, no two coincident.
ProfileSpline interpolate_curvature_profiles(std::span<const InterpolationPoint> points);

}  // namespace gf
