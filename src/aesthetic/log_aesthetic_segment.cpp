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
  return placed(theta, c, k_std, dk_std);
}

LacPoint LogAestheticSegment::placed(double theta, cplx c, double k_std, std::optional<double> dk_std) const {
  const double S = scale();
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

// Towards an inflection end (α < 0, κ = (|Λα| Δs)^{−1/α} with Δs the arc length left) the
// curve runs straight so fast that θ(s) reaches θ_d to the last bit while Δs is still a few
// hundredths of the segment (α = −0.1: θ_d − θ ∝ Δs¹¹), and C(θ), integrated in θ, stops there:
// the last units of the segment drew as its end point. Near the end the position is instead
// C(θ_d) − e^{iθ_d} ∫₀^Δs e^{−iΔθ(v)} dv with Δθ(v) = (|Λα| v)^p / (Λ(1 − α)), p = (α − 1)/α,
// whose series Σ (−iΔθ(Δs))^k Δs / (k! (kp + 1)) converges at once where Δθ is small.
std::optional<LacPoint> LogAestheticSegment::near_inflection_end(double before) const {
  constexpr double most_turning = 0.05;  // radians: 13 terms reach 1e-17
  const double a = curve_.alpha, L = curve_.lambda;
  if (!(std::isinf(log_end_ratio_) && log_end_ratio_ < 0.0 && a < 0.0 && L > 0.0) || before <= 0.0) return std::nullopt;
  const double p = (a - 1.0) / a, reach = -L * a * before;  // |Λα| Δs
  const double turned = std::pow(reach, p) / (L * (1.0 - a));
  if (!(turned <= most_turning)) return std::nullopt;
  cplx sum = 0.0, power = 1.0;  // (−iΔθ)^k / k!
  for (int k = 0; k < 40; ++k) {
    const cplx term = power * before / (k * p + 1.0);
    sum += term;
    if (std::abs(term) <= 1e-17 * before) break;
    power *= cplx(0.0, -turned) / static_cast<double>(k + 1);
  }
  const double k_std = std::pow(reach, -1.0 / a);  // κ and dκ/ds from Δs, not from θ
  return placed(theta_d_ - turned, end_position_ - std::polar(1.0, theta_d_) * sum, k_std,
                -L * std::pow(k_std, a + 1.0));
}

LacPoint LogAestheticSegment::at(double sigma) const {
  // The ends by σ itself: σ/scale at σ = length() can fall a last bit short of the standard
  // end, and a bit short of an inflection end κ is far from 0 (α = −23: (10⁻¹⁶)^{1/23} ≈ 0.2).
  if (sigma <= 0.0) return start();
  if (sigma >= length()) return end();
  const double total = standard_end_length();
  const double s = std::clamp(reversed_ ? total - sigma / scale() : sigma / scale(), 0.0, total);
  if (s == 0.0) return standard_start();
  if (s == total) return standard_end();
  if (const std::optional<LacPoint> tail = near_inflection_end(total - s)) return *tail;
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
    if (const std::optional<LacPoint> tail = near_inflection_end(total - total * j / n)) {
      out.push_back(*tail);
      continue;
    }
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
