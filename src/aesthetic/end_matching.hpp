// What the G3 segments share (lac-math.md §7.1): the curve from its tangent angle, the end
// data scaled to a unit chord with the clothoid length their Newton starts from, and the 3×3
// Newton that makes a segment meet its far end.
#pragma once

#include <algorithm>
#include <cmath>
#include <complex>
#include <optional>
#include <string>

#include <Eigen/Dense>
#include <boost/math/quadrature/gauss.hpp>

#include "aesthetic/clothoid_g1.hpp"
#include "geom/damped_newton.hpp"
#include "geom/polynomial.hpp"
#include "geom/vec2.hpp"

namespace gf {

/// What a G3 join fixes at one end of a segment.
struct CurvatureEnd {
  Vec2 point;
  double tangent_angle;    ///< radians; the end's minus the start's is the segment's turning, as given
  double curvature;        ///< κ, left turns positive
  double curvature_slope;  ///< κ′ = dκ/ds
};

/// ∫_{t0}^{t1} (cos Θ, sin Θ) · speed dt for polynomial Θ(t) and speed(t): Gauss–Legendre with
/// 30 nodes on every quarter of t (Θ has degree ≤ 6 and turns by well under 2π; 4 × 40 nodes
/// reproduce the ends to 1e-15 in check_07).
inline Vec2 direction_integral(const Polynomial& theta, const Polynomial& speed, double t0, double t1) {
  using Rule = boost::math::quadrature::gauss<double, 30>;
  const auto f = [&](double t) { return std::polar(speed(t), theta(t)); };
  const int panels = std::max(1, static_cast<int>(std::ceil(4.0 * std::abs(t1 - t0))));
  std::complex<double> sum = 0.0;
  for (int k = 0; k < panels; ++k)
    sum += Rule::integrate(f, t0 + (t1 - t0) * k / panels, t0 + (t1 - t0) * (k + 1) / panels);
  return {sum.real(), sum.imag()};
}

/// p never turns back on [0, 1] (a curvature profile that is monotone, an arc length that runs
/// one way): its total variation there is |p(1) − p(0)|. A turn of p′ that moves p by less than
/// 1e-9 of p's size is rounding (a p′ = 0 end comes out as ±1e-21).
inline bool never_turns_back(const Polynomial& p) {
  const Polynomial slope = p.derivative();
  double variation = 0.0, last = p(0.0);
  for (const SignChange& turn : sign_changes_in_unit_interval(slope, 1e-12 * slope.magnitude())) {
    variation += std::abs(p(turn.t) - last);
    last = p(turn.t);
  }
  variation += std::abs(p(1.0) - last);
  return variation - std::abs(p(1.0) - p(0.0)) <= 1e-9 * p.magnitude();
}

/// The end data moved to start at the origin with a chord of 1 along +x: κ scales by the chord
/// r, κ′ by r², lengths by 1/r.
struct UnitChordProblem {
  double chord = 0.0;
  double chord_angle = 0.0;
  CurvatureEnd start, end;

  UnitChordProblem(const CurvatureEnd& s, const CurvatureEnd& e) {
    const Vec2 d = e.point - s.point;
    chord = norm(d);
    chord_angle = angle_of(d);
    const auto unit = [&](const CurvatureEnd& c, Vec2 p) {
      return CurvatureEnd{p, c.tangent_angle - chord_angle, c.curvature * chord, c.curvature_slope * chord * chord};
    };
    start = unit(s, {0.0, 0.0}), end = unit(e, {1.0, 0.0});
  }
  bool degenerate() const { return !(chord > 0.0) || !std::isfinite(chord); }
  /// The length of the G1 clothoid between the two ends (on the unit problem), where there is
  /// one: where the G3 fits' Newton starts (§7.1).
  std::optional<double> clothoid_length() const {
    const ClothoidFit c = fit_clothoid_g1({0.0, 0.0}, start.tangent_angle, {1.0, 0.0}, end.tangent_angle);
    return c.ok() ? std::optional<double>(c.arc->length) : std::nullopt;
  }
  /// F of the Newton below: how far a candidate's far end (its unwrapped tangent angle and its
  /// point, on the unit problem) misses the end's.
  Eigen::Vector3d miss(double angle, Vec2 point) const {
    return {angle - end.tangent_angle, point.x - end.point.x, point.y - end.point.y};
  }
};

struct EndMatch {
  std::optional<Eigen::Vector3d> parameters;  ///< nullopt: `reason` says why
  int iterations = 0;
  double residual = 0.0;  ///< max |F| reached
  std::string reason;
};

/// Newton on F(p) = 0, F: R³ → R³ (an end's angle and position misses), from `p`: a
/// finite-difference Jacobian, iterates kept where `admissible`, done at max |F| ≤ 1e-12
/// (geom/damped_newton.hpp; §7.1's recipe).
template <typename Residual, typename Admissible>
EndMatch match_end(Residual residual, Eigen::Vector3d p, Admissible admissible) {
  const auto jacobian = [&](const Eigen::Vector3d& at, const Eigen::Vector3d& f) {
    return forward_difference_jacobian(residual, at, f);
  };
  const NewtonRun run = damped_newton(p, residual, jacobian, admissible, 1e-12, 60);
  EndMatch m;
  m.iterations = run.iterations, m.residual = run.residual;
  switch (run.end) {
    case NewtonEnd::converged: m.parameters = p; break;
    case NewtonEnd::not_finite: m.reason = "the Newton iteration left the finite numbers"; break;
    case NewtonEnd::out_of_iterations:
      m.reason = "the Newton iteration did not reach 1e-12 in 60 steps (residual " + std::to_string(m.residual) + ")";
      break;
    case NewtonEnd::stalled: m.reason = "the Newton iteration stalled (residual " + std::to_string(m.residual) + ")"; break;
  }
  return m;
}

}  // namespace gf
