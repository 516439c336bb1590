// A G3 curve through given points with the curvature given at each (seed 004 §6): one
// curvature-profile segment (aesthetic/curvature_profile_segment.hpp) per span, every point's
// κ and κ′ shared by the two segments meeting there, so the joins are G3 by construction.
// Where the seed's profile has no solution for a span (its legs run backwards, or Newton
// stalls: most spans of a gentle wave), the span is a polynomial spiral
// (aesthetic/polynomial_spiral.hpp) with the same end data instead, so the joins stay G3.
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
#include <variant>
#include <vector>

#include "aesthetic/curvature_profile_segment.hpp"
#include "aesthetic/polynomial_spiral.hpp"

namespace gf {

struct InterpolationPoint {
  Vec2 point;
  double curvature;                      ///< κ, left turns positive
  std::optional<double> curvature_slope; ///< κ′ = dκ/ds
  std::optional<double> tangent_angle;   ///< radians
};

/// One span of the spline: the seed's profile, or the polynomial spiral where that has none.
class InterpolationSpan {
 public:
  explicit InterpolationSpan(CurvatureProfileSegment s) : curve_(std::move(s)) {}
  explicit InterpolationSpan(PolynomialSpiral s) : curve_(std::move(s)) {}

  bool is_profile() const { return std::holds_alternative<CurvatureProfileSegment>(curve_); }
  /// "curvature-profile" or "polynomial-spiral", as the JSON output names it.
  const char* kind() const { return is_profile() ? "curvature-profile" : "polynomial-spiral"; }
  double length() const { return std::visit([](const auto& c) { return c.length(); }, curve_); }
  LacPoint start() const { return std::visit([](const auto& c) { return c.start(); }, curve_); }
  LacPoint end() const { return std::visit([](const auto& c) { return c.end(); }, curve_); }
  LacPoint at(double sigma) const { return std::visit([=](const auto& c) { return c.at(sigma); }, curve_); }
  std::vector<LacPoint> sample(int n) const { return std::visit([=](const auto& c) { return c.sample(n); }, curve_); }
  bool curvature_monotone() const { return std::visit([](const auto& c) { return c.curvature_monotone(); }, curve_); }

 private:
  std::variant<CurvatureProfileSegment, PolynomialSpiral> curve_;
};

struct ProfileSpline {
  std::vector<InterpolationSpan> segments;  ///< span i from point i to i + 1; empty on failure
  std::vector<CurvatureEnd> ends;           ///< every point's data as used, the chosen ones filled in
  std::string reason;                       ///< why not, naming the span, in one line
  bool ok() const { return !segments.empty(); }
};

/// At least two points, no two coincident.
ProfileSpline interpolate_curvature_profiles(std::span<const InterpolationPoint> points);

}  // namespace gf
