#include "aesthetic/shifted_lac.hpp"

#include <cmath>

namespace gf {

double ShiftedLac::curvature(double s) const {
  if (alpha == 0.0) return d * std::exp(-c * s) + e;
  return std::pow(c * s + d, -1.0 / alpha) + e;
}

double ShiftedLac::theta(double s) const {
  if (alpha == 0.0) return theta0 - d * std::expm1(-c * s) / c + e * s;
  if (alpha == 1.0) return theta0 + std::log1p(c * s / d) / c + e * s;
  const double k = (alpha - 1.0) / alpha;
  return theta0 + alpha / ((alpha - 1.0) * c) * (std::pow(c * s + d, k) - std::pow(d, k)) + e * s;
}

double GeneralisedCornuSpiral::theta(double s) const {
  if (r == 0.0) return theta0 + (p * s + 0.5 * q * s * s) / S;
  return theta0 + (q / r) * s + (p - q * S / r) * std::log1p(r * s / S) / r;
}

GeneralisedCornuSpiral::RhoShifted GeneralisedCornuSpiral::rho_shifted() const {
  const double e = r / q, f = S - p * r / q;
  return {e, q / f, p / f};
}

}  // namespace gf
