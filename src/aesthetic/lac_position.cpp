#include "aesthetic/lac_position.hpp"

#include "aesthetic/gauss_legendre.hpp"

#include <algorithm>
#include <cmath>

namespace gf {

namespace {

using cplx = std::complex<double>;

// ∫_a^b e^{i(phase + σt)} g(t) dt on one panel, with as few nodes as keep it to about 1e-16:
// g is analytic in the Bernstein ellipse reaching the singular point, of parameter
// ρ = r + √(r² − 1), r = distance / half-width, and the rule of n points errs by about ρ^{−2n};
// the phase by about 3e-7·h⁹ (4 points) and 2e-12·h¹³ (6) for a half-width h. The samples of
// a segment (LogAestheticSegment::sample) are short steps far from ψ*.
template <typename G>
cplx panel(G&& g, double phase, double sigma, double a, double b, double singular) {
  const double half = 0.5 * (b - a), r = std::abs(0.5 * (a + b) - singular) / half;
  if (half <= 0.1 && r >= 50.0) return gauss_legendre_phased<4>(g, phase, sigma, a, b);
  if (half <= 0.3 && r >= 12.0) return gauss_legendre_phased<6>(g, phase, sigma, a, b);
  return gauss_legendre_phased<12>(g, phase, sigma, a, b);
}

// Panels from `start` toward `end` (either direction), each at most min(distance to the
// singular angle, 1.5) long: ∫_start^end e^{i(phase + σt)} g(t) dt.
template <typename G>
cplx graded_panels(G&& g, double phase, double sigma, double start, double end, double singular) {
  const double dir = end > start ? 1.0 : -1.0;
  cplx total{};
  double cur = start;
  while (cur != end) {
    const double h = std::min(std::abs(cur - singular), 1.5);
    double next = cur + dir * h;
    if ((end - next) * dir <= 1e-3 * h) next = end;
    const cplx piece = panel(g, phase, sigma, std::min(cur, next), std::max(cur, next), singular);
    total += dir > 0 ? piece : -piece;
    cur = next;
  }
  return total;
}

cplx unit(double angle) { return {std::cos(angle), std::sin(angle)}; }

// ∫_{δ0}^{δ1} e^{i(ψ*+σδ)} |c|^p δ^p dδ = |c|^p e^{iψ*} Σ (iσ)^n/n! ∫ δ^{n+p} dδ termwise
// (§8.2 step 3, generalised to a lower limit): each term is (δ1^k − δ0^k)/k with k = n+p+1,
// written with expm1 so k near 0 stays accurate, and ln(δ1/δ0) when k = 0. With δ0 = 0 it
// needs p > −1 (a finite length); otherwise any p, so ends astronomically close to ψ* work.
cplx power_series(double psi_star, double sigma, double abs_c, double p, double delta0, double delta1) {
  cplx sum = 0.0;
  cplx factor = 1.0;  // (iσ)^n / n!
  const double log_ratio = delta0 > 0.0 ? std::log(delta1 / delta0) : 0.0;
  double upper = std::pow(delta1, p + 1.0);                       // δ1^k, k = n + p + 1
  double lower = delta0 > 0.0 ? std::pow(delta0, p + 1.0) : 0.0;  // δ0^k
  for (int n = 0; n < 100; ++n) {
    const double k = n + p + 1.0;
    double integral;
    if (std::abs(k) >= 0.5) integral = (upper - lower) / k;
    else if (k == 0.0) integral = log_ratio;
    else integral = delta0 > 0.0 ? lower * std::expm1(k * log_ratio) / k : upper / k;
    const cplx term = factor * integral;
    sum += term;
    // |term| ≤ 1e-18 |sum|, squared (std::abs of a complex is a hypot, on the hottest loop).
    if (n > 3 && std::norm(term) <= 1e-36 * std::norm(sum)) break;
    factor = times_i(factor, sigma) / double(n + 1);
    upper *= delta1;
    lower *= delta0;
  }
  return std::pow(abs_c, p) * unit(psi_star) * sum;
}

}  // namespace

cplx singular_power_integral(double psi_star, double sigma, double abs_c, double p, double delta0, double delta1) {
  const auto rho = [&](double delta) { return std::exp(p * std::log(abs_c * delta)); };
  // Near the singular angle the series does [δ0, δ1] (or [δ0, 0.75] when δ1 > 1) in a few
  // dozen multiply-adds however close δ0 is to 0 (no cancellation while δ0 is at most half
  // the upper limit); graded panels do the rest.
  cplx total = 0.0;
  double d = delta0;
  const double near_end = delta1 <= 1.0 ? delta1 : 0.75;
  if (delta0 <= 0.5 * near_end && (delta0 > 0.0 || p > -1.0)) {
    total = power_series(psi_star, sigma, abs_c, p, delta0, near_end);
    d = near_end;
  }
  // Each panel keeps the singularity at least its own length away (Bernstein ratio ≥ 3 + √8).
  return d < delta1 ? total + graded_panels(rho, psi_star, sigma, d, delta1, 0.0) : total;
}

cplx lac_position(const NormalisedLac& curve, double theta_a, double theta_b, std::optional<double> delta_b) {
  const double a = curve.alpha, L = curve.lambda;
  if (theta_a == theta_b) return 0.0;
  if (L == 0.0) return cplx(0.0, -1.0) * (unit(theta_b) - unit(theta_a));  // unit circle
  if (a == 1.0) {                                                             // logarithmic spiral
    const cplx z(L, 1.0);
    return (std::exp(z * theta_b) - std::exp(z * theta_a)) / z;
  }
  const double c = (a - 1.0) * L, p = 1.0 / (a - 1.0);
  const double psi_star = -1.0 / c;
  const double sigma = c > 0.0 ? 1.0 : -1.0;
  const double da = std::abs(theta_a - psi_star);
  const double db = delta_b ? *delta_b : std::abs(theta_b - psi_star);
  if (std::abs(psi_star) <= 8.0 * (1.0 + std::abs(theta_a) + std::abs(theta_b))) {
    // ψ* is of the order of the ends: work by the distance δ, ψ = ψ* + σδ, dψ = σ dδ, so that
    // ρ = (|c|δ)^p keeps its accuracy as δ → 0 while the phase ψ* + σδ loses nothing to
    // rounding, and near ψ* the series does the whole interval.
    const cplx integral = singular_power_integral(psi_star, sigma, std::abs(c), p, std::min(da, db), std::max(da, db));
    return sigma * (db >= da ? integral : -integral);
  }
  // ψ* is far: in θ, with panels graded by the distance to ψ* (at most 1.5 rad each),
  // marching from the end nearer to it.
  const auto rho = [&](double psi) { return std::exp(p * std::log1p(c * psi)); };
  return da <= db ? graded_panels(rho, 0.0, 1.0, theta_a, theta_b, psi_star)
                  : -graded_panels(rho, 0.0, 1.0, theta_b, theta_a, psi_star);
}

}  // namespace gf
