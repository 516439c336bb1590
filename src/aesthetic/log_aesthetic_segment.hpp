// A log-aesthetic segment in the plane (lac-math.md §2.3–2.4): the normalised curve on
// θ ∈ [0, θ_d], placed by a similarity — never an affine map —
//   world(θ) = origin + Z · C(θ)      (C conjugated when the segment turns right),
// and `reversed` when the user's P0 is the standard end θ_d (curvature grows from P0).
// Everything is reported along the user's direction P0 → P2, left turns positive.
#pragma once

#include <complex>
#include <optional>
#include <vector>

#include "aesthetic/normalised_lac.hpp"
#include "geom/vec2.hpp"

namespace gf {

struct LacPoint {
  Vec2 point;
  Vec2 tangent;  ///< unit, along P0 → P2
  double curvature;
  std::optional<double> curvature_derivative;  ///< dκ/ds; nullopt where unbounded
};

class LogAestheticSegment {
 public:
  /// `log_end_ratio` = ln(κ(θ_d)/κ(0)) of the standard curve (−∞ for an inflection end);
  /// it gives the standard end's length, curvature and dκ/ds exactly (§2.3 remedy (i)).
  /// `end_position` = C(θ_d) of the standard curve, when the caller has it already.
  LogAestheticSegment(NormalisedLac curve, double theta_d, double log_end_ratio, std::complex<double> origin,
                      std::complex<double> z, bool mirrored, bool reversed,
                      std::optional<std::complex<double>> end_position = std::nullopt);

  const NormalisedLac& curve() const { return curve_; }
  double alpha() const { return curve_.alpha; }
  double lambda() const { return curve_.lambda; }
  double turning() const { return theta_d_; }  ///< |total turning|
  double scale() const { return std::abs(z_); }
  bool mirrored() const { return mirrored_; }
  bool reversed() const { return reversed_; }
  /// ln(κ(θ_d)/κ(0)) of the standard curve, ≤ 0 (−∞ for an inflection end).
  double log_end_ratio() const { return log_end_ratio_; }

  double length() const;
  /// The user's P0 and P2 with their exact values.
  LacPoint start() const;
  LacPoint end() const;
  /// At arc length σ ∈ [0, length()] from P0.
  LacPoint at(double sigma) const;
  /// n + 1 points uniform in arc length from P0 to P2, accumulated piece by piece: O(n).
  std::vector<LacPoint> sample(int n) const;
  /// The same curve traversed from P2 to P0.
  LogAestheticSegment reversed_direction() const;

 private:
  LacPoint at_standard(double theta, std::complex<double> c, bool exact_end) const;
  LacPoint placed(double theta, std::complex<double> c, double k_std, std::optional<double> dk_std) const;
  /// The standard curve `before` short of an inflection end, from that end (nullopt where the
  /// segment has none or the stretch turns too much for the series).
  std::optional<LacPoint> near_inflection_end(double before) const;
  LacPoint standard_start() const { return at_standard(0.0, 0.0, false); }
  LacPoint standard_end() const { return at_standard(theta_d_, end_position_, true); }
  double standard_end_length() const;

  NormalisedLac curve_;
  double theta_d_;
  double log_end_ratio_;
  std::complex<double> origin_, z_;
  bool mirrored_, reversed_;
  std::complex<double> end_position_;  ///< C(θ_d), computed once
};

}  // namespace gf
