#include "aesthetic/segment_fit.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <numbers>

#include <boost/math/tools/toms748_solve.hpp>

#include "aesthetic/lac_position.hpp"

namespace gf {

namespace {

using cplx = std::complex<double>;

cplx cx(Vec2 v) { return {v.x, v.y}; }

// Λ for end-curvature ratio r = e^x of the forward segment θ ∈ [0, θ_d] (§2.1).
double lambda_of(double alpha, double theta_d, double x) {
  if (x == 0.0) return 0.0;
  if (alpha == 1.0) return -x / theta_d;
  return std::expm1((1.0 - alpha) * x) / ((alpha - 1.0) * theta_d);
}

// C(θ_d) of the standard segment with end curvature ratio e^x, exact at the end.
cplx standard_end(const NormalisedLac& curve, double theta_d, double x) {
  return lac_position(curve, 0.0, theta_d, singular_distance_at_ratio(curve, x));
}

struct Triangle {
  cplx p0, p2;
  double theta_d;  ///< |turning| in (0, π)
  double theta_e;  ///< angle at p0 between the tangent and the chord
  double theta_f;  ///< the same at p2
  bool mirrored;   ///< turning right
};

// Angles of the control triangle; nullopt with a reason when it has none.
std::optional<Triangle> triangle(Vec2 a, Vec2 b, Vec2 c, std::string& reason) {
  const cplx p0 = cx(a), p1 = cx(b), p2 = cx(c);
  const cplx t0 = p1 - p0, t1 = p2 - p1, chord = p2 - p0;
  if (std::abs(t0) == 0.0 || std::abs(t1) == 0.0) {
    reason = "P1 coincides with an end point, so a tangent is undefined";
    return std::nullopt;
  }
  if (std::abs(chord) == 0.0) {
    reason = "the end points coincide";
    return std::nullopt;
  }
  const double turning = wrapped_angle(std::arg(t1) - std::arg(t0));
  if (std::abs(turning) < 1e-14) {
    reason = "the control points are collinear: a straight line, not an aesthetic curve";
    return std::nullopt;
  }
  if (std::abs(turning) >= std::numbers::pi - 1e-14) {
    reason = "the tangents turn by π or more";
    return std::nullopt;
  }
  const double e = std::abs(wrapped_angle(std::arg(chord) - std::arg(t0)));
  const double f = std::abs(wrapped_angle(std::arg(t1) - std::arg(chord)));
  return Triangle{p0, p2, std::abs(turning), e, f, turning < 0};
}

// The similarity that takes the standard chord C(θ_d) onto P0 → P2 (§2.3).
LogAestheticSegment place(const NormalisedLac& curve, double theta_d, double x, const Triangle& t, bool reversed,
                          cplx c_end) {
  const cplx z = (t.p2 - t.p0) / (t.mirrored ? std::conj(c_end) : c_end);
  return LogAestheticSegment(curve, theta_d, x, t.p0, z, t.mirrored, reversed, c_end);
}

template <typename F>
double solve_increasing(F&& f, double lo, double hi) {
  std::uintmax_t iterations = 200;
  const auto [a, b] = boost::math::tools::toms748_solve(f, lo, hi, boost::math::tools::eps_tolerance<double>(52),
                                                        iterations);
  return 0.5 * (a + b);
}

}  // namespace

double drawable_limit(double alpha, double theta_d) {
  if (alpha >= 0.0 && alpha <= 1.0) return theta_d;
  const double p = 1.0 / (alpha - 1.0);
  // α < 0: the limit segment ends at an inflection, ρ ∝ (θ_d − ψ)^p;
  // α > 1: it starts at a ρ = 0 point, ρ ∝ ψ^p.
  const cplx limit = alpha < 0.0 ? singular_power_integral(theta_d, -1.0, 1.0, p, 0.0, theta_d)
                                 : singular_power_integral(0.0, 1.0, 1.0, p, 0.0, theta_d);
  return std::arg(limit);
}

SegmentFit fit_three_point(Vec2 p0, Vec2 p1, Vec2 p2, double alpha, std::optional<double> near_log_end_ratio,
                           double min_end_curvature_ratio) {
  SegmentFit fit;
  if (!std::isfinite(alpha)) {
    fit.reason = "α is not a finite number";
    return fit;
  }
  std::optional<Triangle> t = triangle(p0, p1, p2, fit.reason);
  if (!t) return fit;
  // Curvature must fall from the standard start: start at the end with the larger angle.
  const bool reversed = t->theta_e < t->theta_f;
  if (reversed) t = triangle(p2, p1, p0, fit.reason);
  const double td = t->theta_d, target = t->theta_e;
  if (target - t->theta_f > 1e-15 * td) {
    const double limit = drawable_limit(alpha, td);
    if (target >= limit) {
      fit.reason = "outside the drawable region of α = " + std::to_string(alpha) + ": the angle at the sharper end is " +
                   std::to_string(target / td) + " of the turning, the limit is " + std::to_string(limit / td);
      return fit;
    }
    // The chord angle E falls from θ_d/2 (x = 0) toward its limit as x → −∞ (§2.1): solve
    // E(x) = θ_e with TOMS 748 in a bracket grown from [−1, 0]. Each evaluation is a
    // quadrature: the bracket's values are passed on, and the last C(θ_d) is kept.
    cplx last_end = 0.0;
    double last_x = 1.0;
    const auto excess = [&](double xx) {
      last_x = xx;
      last_end = standard_end(NormalisedLac{alpha, lambda_of(alpha, td, xx)}, td, xx);
      return target - std::arg(last_end);
    };
    // The ratio r = e^x may be astronomically small near the edge (0 ≤ α ≤ 1 reach it only as
    // r → 0): the exact end distance and the series keep E accurate until u_end = r^{1−α}
    // would leave the range of double.
    // (Also keeps δ_end^{p+1}, the size of the integral, finite: |(1−α)(p+1)| = |α|.)
    const double x_min = -700.0 / std::max({std::abs(1.0 - alpha), std::abs(alpha), 1.0});
    const double f_arc = target - 0.5 * td;  // E(0) = θ_d/2: the arc
    // The excess rises with x. A bracket grown from [−1, 0], or outwards from a nearby fit's x
    // in steps from a millionth of it (the G2 solve's finite differences move x by about that).
    const bool near = near_log_end_ratio && *near_log_end_ratio < 0.0 && *near_log_end_ratio > x_min;
    double lo = near ? *near_log_end_ratio : -1.0, hi = 0.0, f_lo = excess(lo), f_hi = f_arc;
    double step = near ? 1e-6 * std::max(1.0, -lo) : 0.0;
    if (near && f_lo > 0.0) {
      hi = lo, f_hi = f_lo;
      lo = std::max(hi - step, x_min), f_lo = excess(lo);
    } else if (near && f_lo < 0.0) {
      while (true) {
        const double up = std::min(lo + step, 0.0);
        const double f_up = up == 0.0 ? f_arc : excess(up);
        if (f_up >= 0.0) {
          hi = up, f_hi = f_up;
          break;
        }
        lo = up, f_lo = f_up, step *= 8.0;
      }
    }
    // The end curvature ratio is e^x: below x_wanted no fit is wanted. Where the bracket would
    // grow past it, one evaluation there says whether the root lies beyond.
    const double x_wanted = min_end_curvature_ratio > 0.0 ? std::log(min_end_curvature_ratio) : x_min;
    const auto too_uneven = [&] {
      char bound[32];
      std::snprintf(bound, sizeof bound, "%g", 1.0 / min_end_curvature_ratio);
      fit.reason = std::string("its end curvatures would differ by more than a factor of ") + bound;
      return fit;
    };
    while (f_lo > 0.0) {
      hi = lo, f_hi = f_lo;
      if (near) step *= 8.0;
      const double next = std::max(near ? lo - step : 2.0 * lo, x_min);
      if (next < x_wanted && hi > x_wanted && excess(x_wanted) > 0.0) return too_uneven();
      lo = next;
      if (hi == x_min) {
        fit.reason = "too close to the edge of α's drawable region: the end curvature ratio would be below 1e-300";
        return fit;
      }
      f_lo = excess(lo);
    }
    if (!std::isfinite(f_lo)) {
      fit.reason = "too close to the edge of α's drawable region for double precision";
      return fit;
    }
    // x to 40 bits (about 1e-12 of itself): end curvatures a thousand times finer than the G2
    // solve's 1e-9, at a tenth less of the whole fairing's time than 50 bits.
    std::uintmax_t iterations = 100;
    const auto [a, b] = boost::math::tools::toms748_solve(excess, lo, hi, f_lo, f_hi,
                                                          boost::math::tools::eps_tolerance<double>(40), iterations);
    const double x = 0.5 * (a + b);
    if (x < x_wanted) return too_uneven();
    const NormalisedLac curve{alpha, lambda_of(alpha, td, x)};
    fit.segment = place(curve, td, x, *t, reversed, x == last_x ? last_end : standard_end(curve, td, x));
    return fit;
  }
  const NormalisedLac curve{alpha, 0.0};  // the circular arc
  fit.segment = place(curve, td, 0.0, *t, reversed, standard_end(curve, td, 0.0));
  return fit;
}

// E(q, Θ) = arg Σ (iΘ)^n / (n! (n + q)): the chord angle at the inflection end (§3.1).
double inflection_chord_angle(double q, double big_theta) {
  cplx sum = 0.0, factor = 1.0;
  for (int n = 0; n < 120; ++n) {
    const cplx term = factor / (n + q);
    sum += term;
    if (n > 3 && std::norm(term) < 1e-36 * std::norm(sum)) break;
    factor = times_i(factor, big_theta) / double(n + 1);
  }
  return std::arg(sum);
}

SegmentFit fit_inflection_start(Vec2 p0, Vec2 p1, Vec2 p2) {
  SegmentFit fit;
  const std::optional<Triangle> t = triangle(p0, p1, p2, fit.reason);
  if (!t) return fit;
  const double big = t->theta_d, target = t->theta_e;
  if (!(target < 0.5 * big - 1e-15 * big)) {
    fit.reason = "no segment with an inflection at P0: it needs |P0P1| > |P1P2| (the angle at P0 below half the turning)";
    return fit;
  }
  // E rises with q from 0 (q → 0, α → 0−) to Θ/2 (q → 1, α → −∞, the circle).
  const double q = solve_increasing([&](double qq) { return inflection_chord_angle(qq, big) - target; }, 1e-300, 1.0);
  if (!(q > 0.0 && q < 1.0)) {
    fit.reason = "the inflection-end segment degenerates (α would be 0 or −∞)";
    return fit;
  }
  const double alpha = q / (q - 1.0);
  // In the normalised form the inflection is ψ* = θ_d when Λ = 1/((1−α)θ_d): the standard
  // segment ends there (ratio 0), so the user's P0 is its end.
  const NormalisedLac curve{alpha, 1.0 / ((1.0 - alpha) * big)};
  const std::optional<Triangle> from_p2 = triangle(p2, p1, p0, fit.reason);
  const double x = -std::numeric_limits<double>::infinity();
  fit.segment = place(curve, big, x, *from_p2, true, standard_end(curve, big, x));
  return fit;
}

}  // namespace gf
