#include "aesthetic/normalised_lac.hpp"

#include <cmath>

namespace gf {

// lac-math.md §1.2, table "θ(s), s(θ), ρ(θ), κ(θ), dκ/ds".

double NormalisedLac::theta_of_s(double s) const {
  const double a = alpha, L = lambda;
  if (L == 0.0) return s;
  if (a == 0.0) return -std::expm1(-L * s) / L;
  if (a == 1.0) return std::log1p(L * s) / L;
  return std::expm1((a - 1.0) / a * std::log1p(L * a * s)) / (L * (a - 1.0));
}

double NormalisedLac::s_of_theta(double theta) const {
  const double a = alpha, L = lambda;
  if (L == 0.0) return theta;
  if (a == 0.0) return -std::log1p(-L * theta) / L;
  if (a == 1.0) return std::expm1(L * theta) / L;
  return std::expm1(a / (a - 1.0) * std::log1p((a - 1.0) * L * theta)) / (L * a);
}

double NormalisedLac::rho_of_theta(double theta) const {
  if (lambda == 0.0) return 1.0;
  if (alpha == 1.0) return std::exp(lambda * theta);
  return std::exp(std::log1p((alpha - 1.0) * lambda * theta) / (alpha - 1.0));
}

double NormalisedLac::curvature_of_theta(double theta) const {
  if (lambda == 0.0) return 1.0;
  if (alpha == 1.0) return std::exp(-lambda * theta);
  return std::exp(-std::log1p((alpha - 1.0) * lambda * theta) / (alpha - 1.0));
}

std::optional<double> NormalisedLac::curvature_derivative_of_theta(double theta) const {
  if (lambda == 0.0) return 0.0;
  const double k = curvature_of_theta(theta);
  const double v = -lambda * (alpha == -1.0 ? 1.0 : std::pow(k, alpha + 1.0));
  if (!std::isfinite(v)) return std::nullopt;
  return v;
}

std::optional<double> NormalisedLac::singular_theta() const {
  if (alpha == 1.0 || lambda == 0.0) return std::nullopt;
  return -1.0 / ((alpha - 1.0) * lambda);
}

std::optional<double> singular_distance_at_ratio(const NormalisedLac& curve, double log_ratio) {
  const double a = curve.alpha, L = curve.lambda;
  if (a == 1.0 || L == 0.0) return std::nullopt;
  return std::exp((1.0 - a) * log_ratio) / std::abs((a - 1.0) * L);
}

}  // namespace gf
