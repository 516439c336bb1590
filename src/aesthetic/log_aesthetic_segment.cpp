#include "aesthetic/log_aesthetic_segment.hpp"

#include <algorithm>
#include <cmath>

#include "aesthetic/lac_position.hpp"

namespace gf {

namespace {

using cplx = std::complex<double>;

Vec2 vec(cplx z) { return {z.real(), z.imag()}; }

}  // namespace

LogAestheticSegment::LogAestheticSegment(NormalisedLac curve, double theta_d, double log_end_ratio, cplx origin,
                                         cplx z, bool mirrored, bool reversed, std::optional<cplx> end_position)
    : curve_(curve), theta_d_(theta_d), log_end_ratio_(log_end_ratio), origin_(origin), z_(z), mirrored_(mirrored),
      reversed_(reversed),
      end_position_(end_position ? *end_position
                                 : lac_position(curve_, 0.0, theta_d_, singular_distance_at_ratio(curve_, log_end_ratio))) {}

// With u_end = 1 + (α−1)Λθ_d = r^{1−α} (r = e^x the end curvature ratio), s(θ_d) becomes
// expm1(−αx)/(Λα): no cancellation however small r is.
double LogAestheticSegment::standard_end_length() const {
  const double a = curve_.alpha, L = curve_.lambda, x = log_end_ratio_;
  if (L == 0.0) return theta_d_;
  if (a == 0.0) return -x / L;
  return std::expm1(-a * x) / (L * a);
}

double LogAestheticSegment::length() const { return scale() * standard_end_length(); }

LacPoint LogAestheticSegment::at_standard(double theta, cplx c, bool exact_end) const {
  const double S = scale();
  const double a = curve_.alpha, L = curve_.lambda, x = log_end_ratio_;
  double k_std;
  std::optional<double> dk_std;
  if (exact_end) {  // κ = r = e^x and dκ/ds = −Λ r^{α+1} at θ_d (α = −1 also where r = 0)
    k_std = std::exp(x);
    const double v = L == 0.0 ? 0.0 : a == -1.0 ? -L : -L * std::exp((a + 1.0) * x);
    if (std::isfinite(v)) dk_std = v;
  } else {
    k_std = curve_.curvature_of_theta(theta);
    dk_std = curve_.curvature_derivative_of_theta(theta);
  }
  const double m = mirrored_ ? -1.0 : 1.0;
  const double g = m * (reversed_ ? -1.0 : 1.0);
  const cplx along = z_ * (mirrored_ ? std::polar(1.0, -theta) : std::polar(1.0, theta)) / S;
  LacPoint p;
  p.point = vec(origin_ + z_ * (mirrored_ ? std::conj(c) : c));
  p.tangent = vec(reversed_ ? -along : along);
  p.curvature = g * k_std / S;
  // Reversal flips κ and the direction of s together, so dκ/ds keeps its sign (§2.4).
  if (dk_std) p.curvature_derivative = m * *dk_std / (S * S);
  return p;
}

LacPoint LogAestheticSegment::start() const { return reversed_ ? standard_end() : standard_start(); }
LacPoint LogAestheticSegment::end() const { return reversed_ ? standard_start() : standard_end(); }

LacPoint LogAestheticSegment::at(double sigma) const {
  const double total = standard_end_length();
  const double s = std::clamp(reversed_ ? total - sigma / scale() : sigma / scale(), 0.0, total);
  if (s == 0.0) return standard_start();
  if (s == total) return standard_end();
  const double theta = curve_.theta_of_s(s);
  return at_standard(theta, lac_position(curve_, 0.0, theta), false);
}

std::vector<LacPoint> LogAestheticSegment::sample(int n) const {
  n = std::max(n, 1);
  const double total = standard_end_length();
  std::vector<LacPoint> out;
  out.reserve(static_cast<std::size_t>(n) + 1);
  out.push_back(standard_start());
  cplx c = 0.0;
  double theta = 0.0;
  for (int j = 1; j < n; ++j) {
    const double next = curve_.theta_of_s(total * j / n);
    c += lac_position(curve_, theta, next);
    theta = next;
    out.push_back(at_standard(theta, c, false));
  }
  out.push_back(standard_end());
  if (reversed_) std::reverse(out.begin(), out.end());
  return out;
}

LogAestheticSegment LogAestheticSegment::reversed_direction() const {
  return LogAestheticSegment(curve_, theta_d_, log_end_ratio_, origin_, z_, mirrored_, !reversed_, end_position_);
}

}  // namespace gf
