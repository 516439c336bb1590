// Implementation of position_by_arc_length (a template over the tangent-angle function).
#pragma once

#include <cmath>
#include <complex>

#include "aesthetic/gauss_legendre.hpp"

namespace gf {

namespace detail {

template <typename Curve>
std::complex<double> gauss_legendre_12_in_s(const Curve& curve, double a, double b) {
  return gauss_legendre([&](double s) { return std::polar(1.0, curve.theta(s)); }, a, b);
}

template <typename Curve>
std::complex<double> adaptive_in_s(const Curve& curve, double a, double b, std::complex<double> whole, double tol,
                                   int depth) {
  const double m = 0.5 * (a + b);
  const auto left = gauss_legendre_12_in_s(curve, a, m), right = gauss_legendre_12_in_s(curve, m, b);
  if (depth >= 30 || std::abs(left + right - whole) <= tol) return left + right;
  return adaptive_in_s(curve, a, m, left, 0.5 * tol, depth + 1) + adaptive_in_s(curve, m, b, right, 0.5 * tol, depth + 1);
}

}  // namespace detail

template <typename Curve>
std::complex<double> position_by_arc_length(const Curve& curve, double s) {
  if (s == 0.0) return 0.0;
  const auto whole = detail::gauss_legendre_12_in_s(curve, 0.0, s);
  return detail::adaptive_in_s(curve, 0.0, s, whole, 1e-14 * std::abs(s), 0);
}

}  // namespace gf
