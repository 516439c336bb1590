// Positions on a normalised log-aesthetic curve: C(θ) = ∫_0^θ e^{iψ} ρ(ψ) dψ (lac-math.md
// §1.2), by the method of §8.2: Gauss–Legendre panels graded toward the singular angle ψ*,
// and the exact power series on a panel that touches it. About 1e-14 of the arc length
// everywhere, with 12–36 integrand evaluations for ordinary segments and 4 or 6 for the short
// steps between a segment's samples.
#pragma once

#include <complex>
#include <optional>

#include "aesthetic/normalised_lac.hpp"

namespace gf {

/// z · iσ, written out: std::complex's operator* checks for NaNs in a library call
/// (__muldc3), and the power series below multiplies by iσ at every term.
inline std::complex<double> times_i(std::complex<double> z, double sigma) {
  return {-z.imag() * sigma, z.real() * sigma};
}

/// ∫_{δ0}^{δ1} e^{i(ψ* + σδ)} (|c|δ)^p dδ, 0 ≤ δ0 ≤ δ1, p > −1 when δ0 = 0: the LAC integrand
/// written by the distance δ to the singular angle, which keeps ρ = (|c|δ)^p accurate
/// however close δ comes to 0.
std::complex<double> singular_power_integral(double psi_star, double sigma, double abs_c, double p, double delta0,
                                             double delta1);

/// C(θb) − C(θa) = ∫_{θa}^{θb} e^{iψ} ρ(ψ) dψ. `delta_b`, when given, is the exact distance
/// |θb − ψ*| (0 when the end touches ψ*): callers that know it avoid the cancellation in
/// θb − ψ* that ruins ρ near the singular angle (§2.3 remedy (i), §8.3 endpoint trap).
std::complex<double> lac_position(const NormalisedLac& curve, double theta_a, double theta_b,
                                  std::optional<double> delta_b = std::nullopt);

}  // namespace gf
