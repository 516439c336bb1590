// The normalised log-aesthetic curve (lac-math.md §1.2; Yoshida–Saito form, seed 001's
// "second standard form"):
//   ρ(s)^α = 1 + Λαs  (α ≠ 0),   ρ(s) = e^{Λs}  (α = 0),
// so ρ(0) = 1, θ(0) = 0, C(0) = 0, the start tangent is +x and the curve turns left; for
// Λ > 0 the curvature decreases along s, Λ = 0 is the unit circle. Every intrinsic quantity
// is closed-form, written with expm1/log1p so that Λ → 0 stays accurate.
#pragma once

#include <optional>

namespace gf {

struct NormalisedLac {
  double alpha = 0.0;   ///< LCG slope α
  double lambda = 0.0;  ///< Λ ≥ 0

  double theta_of_s(double s) const;
  double s_of_theta(double theta) const;
  double rho_of_theta(double theta) const;
  double curvature_of_theta(double theta) const;
  /// dκ/ds = −Λ κ^{α+1}; nullopt where it is unbounded (an inflection end with α < −1).
  std::optional<double> curvature_derivative_of_theta(double theta) const;

  /// ψ* = −1/((α−1)Λ), where 1 + (α−1)Λθ = 0: ρ = 0 for α > 1, an inflection (κ = 0) for
  /// α < 0, an end at infinity for 0 ≤ α < 1. None for α = 1 or Λ = 0.
  std::optional<double> singular_theta() const;
};

/// |θ_d − ψ*| for the standard segment θ ∈ [0, θ_d] whose end curvature ratio κ(θ_d)/κ(0) is
/// e^x: u_end/|(α−1)Λ| with u_end = e^{(1−α)x}, free of the cancellation in θ_d − ψ* (§2.3
/// remedy (i)); 0 for an inflection end (x = −∞); nullopt when there is no ψ*.
std::optional<double> singular_distance_at_ratio(const NormalisedLac& curve, double log_ratio);

}  // namespace gf
