#include "aesthetic/clothoid_g1.hpp"

#include <cmath>
#include <numbers>

#include <boost/math/quadrature/gauss.hpp>

namespace gf {

FresnelMoments generalised_fresnel(double a, double b, double c) {
  // Gauss–Legendre on [0, ½] and [½, 1], one cos/sin per node for all three moments.
  using Rule = boost::math::quadrature::gauss<double, 30>;
  const auto& x = Rule::abscissa();
  const auto& w = Rule::weights();
  FresnelMoments m{};
  const auto add = [&](double t, double weight) {
    const double phase = 0.5 * a * t * t + b * t + c;
    const double cs = weight * std::cos(phase), sn = weight * std::sin(phase);
    m.x[0] += cs, m.y[0] += sn;
    m.x[1] += t * cs, m.y[1] += t * sn;
    m.x[2] += t * t * cs, m.y[2] += t * t * sn;
  };
  for (const double mid : {0.25, 0.75}) {
    // The rule stores the non-negative abscissae of [−1, 1] (0 once, when present).
    for (std::size_t k = 0; k < x.size(); ++k) {
      const double weight = 0.25 * w[k];
      add(mid + 0.25 * x[k], weight);
      if (x[k] != 0.0) add(mid - 0.25 * x[k], weight);
    }
  }
  return m;
}

namespace {

// The initial A of Bertolazzi & Frego's fit (lac-math.md §7.2), good to a few per cent.
double initial_a(double phi0, double phi1) {
  constexpr double c[] = {2.989696028701907,  0.716228953608281, -0.458969738821509,
                          -0.502821153340377, 0.261062141752652, -0.045854475238709};
  const double pi = std::numbers::pi;
  const double x = (phi0 / pi) * (phi0 / pi), y = (phi1 / pi) * (phi1 / pi), xy = phi0 * phi1 / (pi * pi);
  return (phi0 + phi1) * (c[0] + xy * (c[1] + xy * c[2]) + (c[3] + xy * c[4]) * (x + y) + c[5] * (x * x + y * y));
}

}  // namespace

ClothoidFit fit_clothoid_g1(Vec2 p0, double theta0, Vec2 p1, double theta1) {
  ClothoidFit fit;
  const Vec2 chord = p1 - p0;
  const double r = norm(chord);
  if (!(r > 0.0) || !std::isfinite(r)) {
    fit.reason = "the end points coincide";
    return fit;
  }
  const double phi = angle_of(chord);
  const double phi0 = wrapped_angle(theta0 - phi), phi1 = wrapped_angle(theta1 - phi), delta = phi1 - phi0;
  // g(A) = Y₀(2A, δ − A, φ₀) = 0 puts P1 on the chord; g′(A) = X₂ − X₁.
  double a = initial_a(phi0, phi1);
  constexpr double tolerance = 1e-12;
  constexpr int max_iterations = 10;
  for (fit.iterations = 1; fit.iterations <= max_iterations; ++fit.iterations) {
    const FresnelMoments m = generalised_fresnel(2.0 * a, delta - a, phi0);
    if (std::abs(m.y[0]) <= tolerance) {
      if (!(m.x[0] > 0.0)) break;
      const double length = r / m.x[0];
      fit.arc = ClothoidArc{length, (delta - a) / length, 2.0 * a / (length * length)};
      return fit;
    }
    const double slope = m.x[2] - m.x[1];
    if (!(std::abs(slope) > 0.0)) break;
    a -= m.y[0] / slope;
  }
  fit.reason = "the G1 clothoid's Newton iteration found no solution to 1e-12 in " + std::to_string(max_iterations) +
               " steps";
  return fit;
}

}  // namespace gf
