#include "aesthetic/lac_position.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace gf {

namespace {

using cplx = std::complex<double>;

// 12-point Gauss–Legendre rule on [-1, 1] (lac-math.md §8.2): ± nodes, weights.
constexpr std::array<double, 6> gl_nodes{0.12523340851146891, 0.36783149899818018, 0.58731795428661748,
                                         0.76990267419430469, 0.9041172563704748,  0.98156063424671924};
constexpr std::array<double, 6> gl_weights{0.24914704581340269, 0.23349253653835464, 0.20316742672306565,
                                           0.16007832854334611, 0.10693932599531888, 0.047175336386512022};

template <typename F>
cplx gauss_legendre(F&& f, double a, double b) {
  const double mid = 0.5 * (a + b), half = 0.5 * (b - a);
  cplx sum = 0.0;
  for (std::size_t k = 0; k < gl_nodes.size(); ++k)
    sum += gl_weights[k] * (f(mid - half * gl_nodes[k]) + f(mid + half * gl_nodes[k]));
  return half * sum;
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
  cplx total = 0.0;
  double d = delta0;
  if (d == 0.0) {
    const double tau = std::min(0.75, delta1);
    total += touching_series(psi_star, sigma, abs_c, p, tau);
    d = tau;
  }
  // Each panel keeps the singularity at least its own length away (Bernstein ratio ≥ 3 + √8).
  while (d < delta1) {
    const double h = std::min(d, 1.5);
    double next = d + h;
    if (next >= delta1 || delta1 - next < 1e-3 * h) next = delta1;
    total += gauss_legendre(f, d, next);
    d = next;
  }
  return total;
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
  if (std::abs(c) * std::min(da, db) < 0.5) {
    // An end within half of u = 1 + cψ of ψ*: work by the distance δ, ψ = ψ* + σδ, dψ = σ dδ,
    // so ρ = (|c|δ)^p keeps its accuracy as δ → 0. ψ* is then of the order of the ends, so
    // the phase ψ* + σδ loses nothing to rounding.
    const cplx integral = singular_power_integral(psi_star, sigma, std::abs(c), p, std::min(da, db), std::max(da, db));
    return sigma * (db >= da ? integral : -integral);
  }
  // Otherwise in θ, with panels graded by the distance to ψ* (at most 1.5 rad each).
  const auto f = [&](double psi) { return unit(psi) * std::exp(p * std::log1p(c * psi)); };
  const bool a_near = da <= db;
  const double near = a_near ? theta_a : theta_b, far = a_near ? theta_b : theta_a;
  const double dir = far > near ? 1.0 : -1.0;
  cplx total = 0.0;
  double cur = near;
  while (cur != far) {
    const double h = std::min(std::abs(cur - psi_star), 1.5);
    double next = cur + dir * h;
    if ((far - next) * dir <= 1e-3 * h) next = far;
    total += dir * gauss_legendre(f, std::min(cur, next), std::max(cur, next));
    cur = next;
  }
  // total = ∫_near^far; return ∫_a^b.
  return a_near ? total : -total;
}

}  // namespace gf
