// The shifted log-aesthetic form and the generalised Cornu spiral (seed 000 [0109]–[0115];
// lac-math.md §5, whose θ(s) corrects the patent's). The shift e makes these "aesthetic-like":
// their LCG is no longer straight (§5), so the 3-point machinery does not apply to them.
#pragma once

#include <complex>

namespace gf {

/// κ-shifted LAC: κ(s) = (cs + d)^{−1/α} + e for α ≠ 0, and κ(s) = d·e^{−cs} + e for α = 0 (d is
/// then the k₀ of §5). Valid where cs + d > 0. Tangent angle θ₀ at s = 0.
struct ShiftedLac {
  double alpha = 1.0, c = 1.0, d = 1.0, e = 0.0, theta0 = 0.0;

  double curvature(double s) const;
  /// Closed form, lac-math.md §5 (boxed):
  ///   θ(s) = θ₀ + α/((α−1)c)·[(cs+d)^{(α−1)/α} − d^{(α−1)/α}] + es   (α ∉ {0, 1}),
  ///   θ(s) = θ₀ + ln((cs+d)/d)/c + es  (α = 1),  θ(s) = θ₀ + d(1 − e^{−cs})/c + es  (α = 0).
  double theta(double s) const;
};

/// Generalised Cornu spiral ([0110]): ρ(s) = (S + rs)/(p + qs), so κ = (p + qs)/(S + rs).
struct GeneralisedCornuSpiral {
  double S = 1.0, r = 0.0, p = 1.0, q = 0.0, theta0 = 0.0;

  double curvature(double s) const { return (p + q * s) / (S + r * s); }
  /// θ₀ + (q/r)s + (p − qS/r)·ln(1 + rs/S)/r, or θ₀ + (ps + qs²/2)/S when r = 0.
  double theta(double s) const;

  /// [0111]: ρ = e + f/(p + qs) with e = r/q, f = S − pr/q; then (ρ − e)^{−1} = cs + d with
  /// c = q/f, d = p/f. Needs q ≠ 0 and f ≠ 0.
  struct RhoShifted {
    double e, c, d;
  };
  RhoShifted rho_shifted() const;
};

/// C(s) − C(0) = ∫_0^s e^{iθ(u)} du for any tangent-angle function, by 12-point Gauss–Legendre
/// panels halved until two levels agree to 1e-14 of s.
template <typename Curve>
std::complex<double> position_by_arc_length(const Curve& curve, double s);

}  // namespace gf

#include "aesthetic/shifted_lac_position.hpp"
