// Log-aesthetic segments from three control points (P1 = intersection of the end tangents):
// the Yoshida–Saito construction for a given α (lac-math.md §2, seed 001) and the segment
// whose start is an inflection, with α solved (§3, seed 001 §2.2–2.3, seed 000 [0058]–[0066]).
// Each says "no solution" instead of returning a distorted curve.
#pragma once

#include <optional>
#include <string>

#include "aesthetic/log_aesthetic_segment.hpp"

namespace gf {

struct SegmentFit {
  std::optional<LogAestheticSegment> segment;  ///< nullopt: no solution
  std::string reason;                          ///< why not, in one line
  bool ok() const { return segment.has_value(); }
};

/// The LAC segment of slope α from P0 to P2, tangent to P0P1 at P0 and to P1P2 at P2. No
/// solution when the triangle is degenerate, turns by π or more, lies outside α's drawable
/// region (§2.2), or is so close to its edge that the end curvature ratio falls below 1e-300.
/// `near_log_end_ratio`: that of a fit to nearly the same points (LogAestheticSegment::
/// log_end_ratio), where the search for this one starts; the answer does not depend on it
/// beyond the solve's accuracy. No solution either where the smaller end curvature would be
/// below `min_end_curvature_ratio` times the larger: the search stops as soon as it knows.
SegmentFit fit_three_point(Vec2 p0, Vec2 p1, Vec2 p2, double alpha,
                           std::optional<double> near_log_end_ratio = std::nullopt,
                           double min_end_curvature_ratio = 0.0);

/// The LAC segment with κ = 0 at P0 (an inflection) through P2 with the same tangents; α < 0
/// is solved so that all match. Needs |P0P1| > |P1P2| (the angle at P0 below half the turning).
SegmentFit fit_inflection_start(Vec2 p0, Vec2 p1, Vec2 p2);

/// E_sup(α, θ_d): the supremum of the chord angle at P0 over α's segments turning by θ_d;
/// a triangle with its larger end angle below it is drawable (§2.2).
double drawable_limit(double alpha, double theta_d);

}  // namespace gf
