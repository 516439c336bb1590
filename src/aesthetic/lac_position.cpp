#include "aesthetic/lac_position.hpp"

#include "aesthetic/gauss_legendre.hpp"

#include <algorithm>
#include <cmath>

namespace gf {

namespace {

using cplx = std::complex<double>;

// Panels from `start` toward `end` (either direction), each at most min(distance to the
// singular angle, 1.5) long: ∫_start^end f.
template <typename F>
auto graded_panels(F&& f, double start, double end, double singular) {
  const double dir = end > start ? 1.0 : -1.0;
  decltype(f(start)) total{};
  double cur = start;
  while (cur != end) {
    const double h = std::min(std::abs(cur - singular), 1.5);
    double next = cur + dir * h;
    if ((end - next) * dir <= 1e-3 * h) next = end;
    const auto piece = gauss_legendre_12(f, std::min(cur, next), std::max(cur, next));
    total += dir > 0 ? piece : -piece;
    cur = next;
  }
  return total;
}

cplx unit(double angle) { return {std::cos(angle), std::sin(angle)}; }

// ∫_0^T e^{i(ψ*+στ)} |c|^p τ^p dτ = |c|^p e^{iψ*} Σ (iσ)^n T^{n+p+1} / (n! (n+p+1))   (§8.2 step 3)
cplx touching_series(double psi_star, double sigma, double abs_c, double p, double T) {
  cplx sum = 0.0;
  cplx factor = 1.0;  // (iσ)^n / n!
  double power = std::pow(T, p + 1.0);
  for (int n = 0; n < 80; ++n) {
    const cplx term = factor * (power / (n + p + 1.0));
    sum += term;
    if (n > 3 && std::abs(term) <= 1e-18 * std::abs(sum)) break;
    factor *= cplx(0.0, sigma) / double(n + 1);
    power *= T;
  }
  return std::pow(abs_c, p) * unit(psi_star) * sum;
}

}  // namespace

cplx singular_power_integral(double psi_star, double sigma, double abs_c, double p, double delta0, double delta1) {
  const auto f = [&](double delta) { return unit(psi_star + sigma * delta) * std::exp(p * std::log(abs_c * delta)); };
  // Near the singular angle the series from 0 covers the whole interval in a few dozen
  // multiply-adds: ∫_{δ0}^{δ1} = J(δ1) − J(δ0), without cancellation while δ0 ≤ δ1/2.
  if (p > -1.0 && delta1 <= 1.0 && delta0 <= 0.5 * delta1)
    return touching_series(psi_star, sigma, abs_c, p, delta1) -
           (delta0 > 0.0 ? touching_series(psi_star, sigma, abs_c, p, delta0) : cplx(0.0));
  cplx total = 0.0;
  double d = delta0;
  if (d == 0.0) {
    const double tau = std::min(0.75, delta1);
    total += touching_series(psi_star, sigma, abs_c, p, tau);
    d = tau;
  }
  // Each panel keeps the singularity at least its own length away (Bernstein ratio ≥ 3 + √8).
  return total + graded_panels(f, d, delta1, 0.0);
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
  const auto f = [&](double psi) { return unit(psi) * std::exp(p * std::log1p(c * psi)); };
  return da <= db ? graded_panels(f, theta_a, theta_b, psi_star) : -graded_panels(f, theta_b, theta_a, psi_star);
}

}  // namespace gf
