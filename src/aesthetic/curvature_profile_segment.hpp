// A curve whose curvature profile is a cubic Bézier in the (s, κ) plane (seed 004, Watanabe,
// Saito & Kuroda; lac-math.md §7.1 with its corrections). The profile's control points are
//   P1 = (0, κ₀),  P2 = P1 + λ₀(1, κ′₀),  P3 = P4 − λ₁(1, κ′₁),  P4 = (S, κ₁),
// so κ and dκ/ds are given at both ends; the curve follows from
//   Θ(t) = θ₀ + ∫₀ᵗ K s′ dτ   (a degree-6 polynomial, exact),
//   p(t) = p₀ + ∫₀ᵗ (cos Θ, sin Θ) s′ dτ   (aesthetic/end_matching.hpp's direction_integral).
// Two such segments sharing an end's κ and κ′ join G3.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "aesthetic/end_matching.hpp"
#include "aesthetic/log_aesthetic_segment.hpp"
#include "geom/polynomial.hpp"
#include "geom/vec2.hpp"

namespace gf {

class CurvatureProfileSegment {
 public:
  /// From the start's end data, the profile's length S, its two legs λ₀, λ₁ (measured along s)
  /// and the end's κ and κ′.
  CurvatureProfileSegment(const CurvatureEnd& start, double length, double start_leg, double end_leg,
                          double end_curvature, double end_curvature_slope);

  double length() const { return length_; }
  double start_leg() const { return start_leg_; }
  double end_leg() const { return end_leg_; }

  LacPoint start() const { return at_parameter(0.0); }
  LacPoint end() const { return at_parameter(1.0); }
  /// At the profile's Bézier parameter t ∈ [0, 1].
  LacPoint at_parameter(double t) const;
  /// Θ(t), unwrapped: Θ(1) − Θ(0) is the segment's turning.
  double tangent_angle_at_parameter(double t) const { return theta_(t); }
  /// At arc length σ ∈ [0, length()] (needs arc_length_monotone()).
  LacPoint at(double sigma) const;
  /// n + 1 points uniform in arc length, accumulated piece by piece: O(n).
  std::vector<LacPoint> sample(int n) const;

  /// s′(t) > 0 on [0, 1] and both legs positive: the profile is a function of s.
  bool arc_length_monotone() const;
  /// κ(s) never turns back: no extremum of the curvature inside the segment.
  bool curvature_monotone() const;

 private:
  double parameter_at(double sigma) const;
  LacPoint state(double t, Vec2 point) const;

  Vec2 origin_;
  double length_, start_leg_, end_leg_;
  Polynomial s_, kappa_, theta_;  ///< s(t), K(t), Θ(t) in the power basis
};

struct ProfileFit {
  std::optional<CurvatureProfileSegment> segment;  ///< nullopt: no valid segment
  int iterations = 0;
  double residual = 0.0;  ///< max |F| at the end, on the chord-1 problem (angles in radians)
  std::string reason;     ///< why not, in one line
  bool ok() const { return segment.has_value(); }
};

/// The segment from `start` to `end` with both ends' point, tangent, κ and κ′: Newton on
/// (S, λ₀, λ₁) with a finite-difference Jacobian and backtracking on ‖F‖₂, from the G1
/// clothoid's length and λ = S/3 (lac-math.md §7.1). Solved on the problem scaled to a unit
/// chord. No segment when Newton does not reach 1e-12 or ends on a profile that is not a
/// function of s (a leg ≤ 0, s′ ≤ 0).
ProfileFit fit_curvature_profile(const CurvatureEnd& start, const CurvatureEnd& end);

}  // namespace gf
