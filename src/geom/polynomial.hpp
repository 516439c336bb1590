// Real polynomials of low degree in the power basis, and their real roots in [0, 1].
//
// Root isolation works on the Bernstein form: by Descartes' rule of signs for the Bernstein
// basis, the number of sign changes of the coefficients bounds the number of roots in the
// interval, so an interval with no change has no root and one with a single change has
// exactly one, which is then refined by bisection to the resolution of double.
#pragma once

#include <array>
#include <span>
#include <vector>

namespace gf {

class Polynomial {
 public:
  static constexpr int max_degree = 7;

  constexpr Polynomial() = default;
  /// Coefficients from the constant term up: c[0] + c[1] t + ...
  explicit Polynomial(std::span<const double> coefficients);

  int degree() const { return degree_; }
  double coefficient(int i) const { return i <= degree_ ? c_[i] : 0.0; }
  double operator()(double t) const;
  Polynomial derivative() const;
  /// ∫₀ᵗ p: zero at t = 0. The degree must stay within max_degree.
  Polynomial antiderivative() const;
  /// Largest coefficient magnitude: the scale against which cancellation is judged.
  double magnitude() const;

  friend Polynomial operator+(const Polynomial& a, const Polynomial& b);
  friend Polynomial operator-(const Polynomial& a, const Polynomial& b);
  friend Polynomial operator*(const Polynomial& a, const Polynomial& b);
  friend Polynomial operator*(double s, const Polynomial& a);

 private:
  std::array<double, max_degree + 1> c_{};
  int degree_ = 0;
};

/// A root of odd multiplicity (the polynomial changes sign there).
struct SignChange {
  double t;
};

/// Every t in [0, 1] where p changes sign, ascending. Roots of even multiplicity (touching
/// zeros) are not sign changes and are not reported. `negligible` is the magnitude below which
/// p counts as identically zero (pass the scale of the terms p was computed from times a
/// relative tolerance); an identically zero p has no sign changes.
std::vector<SignChange> sign_changes_in_unit_interval(const Polynomial& p, double negligible);

}  // namespace gf
