// A polynomial spiral (curvature a polynomial in arc length, as in Levien's Spiro) for G3
// joins: on [0, S], with u = s/S,
//   κ(u) = κ₀H₀₀(u) + Sκ′₀H₁₀(u) + κ₁H₀₁(u) + Sκ′₁H₁₁(u) + c₁·16u²(1−u)² + c₂·20u²(1−u)²(2u−1),
// the cubic Hermite of κ and κ′ at both ends plus a symmetric and an odd bump that leave the
// ends' κ and κ′ alone. Θ is a degree-6 polynomial (exact); the position is
// direction_integral (aesthetic/end_matching.hpp).
//
// Next to the seed's profile (curvature_profile_segment.hpp): when κ(s) is nearly a line, as
// on most of a glyph's gentle segments, the seed's legs only re-parametrise it, so its end
// conditions barely see them and Newton runs to extreme or backwards legs; here the unknowns
// (S, c₁, c₂) act on the turning, the length and the first moment of κ whatever the profile,
// and c₁ = c₂ = 0 is the clothoid. Where κ(s) bends strongly (a log-aesthetic segment with
// α ≥ 3), the seed's profile follows it better and the quintic overshoots (tests measure both).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "aesthetic/end_matching.hpp"
#include "aesthetic/log_aesthetic_segment.hpp"
#include "geom/polynomial.hpp"

namespace gf {

class PolynomialSpiral {
 public:
  PolynomialSpiral(const CurvatureEnd& start, double length, double end_curvature, double end_curvature_slope,
                   double symmetric_bump, double odd_bump);

  double length() const { return length_; }
  double symmetric_bump() const { return c1_; }
  double odd_bump() const { return c2_; }
  LacPoint start() const { return at(0.0); }
  LacPoint end() const { return at(length_); }
  /// At arc length σ ∈ [0, length()]. At the ends, κ and κ′ are the given ones exactly, so two
  /// spirals sharing an end's data join G3 to the last bit.
  LacPoint at(double sigma) const;
  /// Θ(σ), unwrapped: Θ(S) − Θ(0) is the turning.
  double tangent_angle_at(double sigma) const { return theta_(sigma / length_); }
  /// n + 1 points uniform in arc length, accumulated piece by piece: O(n).
  std::vector<LacPoint> sample(int n) const;
  /// κ(s) never turns back: no extremum of the curvature inside the segment.
  bool curvature_monotone() const;

 private:
  LacPoint state(double u, Vec2 point) const;

  Vec2 origin_;
  double length_, c1_, c2_;
  double ends_[2][2];  ///< {κ, κ′} at u = 0 and u = 1, as given: the polynomial gives them only to rounding
  Polynomial kappa_, theta_, speed_;  ///< κ(u), Θ(u) and ds/du = S
};

struct SpiralFit {
  std::optional<PolynomialSpiral> spiral;  ///< nullopt: `reason` says why
  int iterations = 0;
  double residual = 0.0;  ///< max |F| at the end, on the chord-1 problem (angles in radians)
  std::string reason;
  bool ok() const { return spiral.has_value(); }
};

/// The spiral from `start` to `end` with both ends' point, tangent, κ and κ′: Newton on
/// (S, c₁, c₂) from the G1 clothoid's length and no bumps, on the problem scaled to a unit chord.
SpiralFit fit_polynomial_spiral(const CurvatureEnd& start, const CurvatureEnd& end);

}  // namespace gf
