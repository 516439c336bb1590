#include "aesthetic/curvature_profile_segment.hpp"

#include <cmath>

#include <boost/math/tools/roots.hpp>

namespace gf {

namespace {

// The power basis of the cubic Bézier with control values c₀…c₃.
Polynomial cubic_bezier(double c0, double c1, double c2, double c3) {
  const double a[] = {c0, 3.0 * (c1 - c0), 3.0 * (c0 - 2.0 * c1 + c2), -c0 + 3.0 * c1 - 3.0 * c2 + c3};
  return Polynomial(a);
}

}  // namespace

CurvatureProfileSegment::CurvatureProfileSegment(const CurvatureEnd& start, double length, double start_leg,
                                                 double end_leg, double end_curvature, double end_curvature_slope)
    : origin_(start.point), length_(length), start_leg_(start_leg), end_leg_(end_leg) {
  s_ = cubic_bezier(0.0, start_leg, length - end_leg, length);
  kappa_ = cubic_bezier(start.curvature, start.curvature + start_leg * start.curvature_slope,
                        end_curvature - end_leg * end_curvature_slope, end_curvature);
  const double theta0[] = {start.tangent_angle};
  theta_ = Polynomial(theta0) + (kappa_ * s_.derivative()).antiderivative();
}

LacPoint CurvatureProfileSegment::state(double t, Vec2 point) const {
  const double speed = s_.derivative()(t);
  LacPoint p{point, direction_of(theta_(t)), kappa_(t), std::nullopt};
  if (speed > 0.0) p.curvature_derivative = kappa_.derivative()(t) / speed;
  return p;
}

LacPoint CurvatureProfileSegment::at_parameter(double t) const {
  return state(t, origin_ + direction_integral(theta_, s_.derivative(), 0.0, t));
}

double CurvatureProfileSegment::parameter_at(double sigma) const {
  if (sigma <= 0.0) return 0.0;
  if (sigma >= length_) return 1.0;
  const Polynomial speed = s_.derivative();
  std::uintmax_t iterations = 60;
  return boost::math::tools::newton_raphson_iterate(
      [&](double t) { return std::make_pair(s_(t) - sigma, speed(t)); }, sigma / length_, 0.0, 1.0, 50, iterations);
}

LacPoint CurvatureProfileSegment::at(double sigma) const { return at_parameter(parameter_at(sigma)); }

std::vector<LacPoint> CurvatureProfileSegment::sample(int n) const {
  std::vector<LacPoint> out;
  out.reserve(static_cast<std::size_t>(n) + 1);
  Vec2 point = origin_;
  double t = 0.0;
  out.push_back(state(0.0, point));
  for (int k = 1; k <= n; ++k) {
    const double next = k == n ? 1.0 : parameter_at(length_ * k / n);
    point += direction_integral(theta_, s_.derivative(), t, next);
    t = next;
    out.push_back(state(t, point));
  }
  return out;
}

bool CurvatureProfileSegment::arc_length_monotone() const {
  if (!(start_leg_ > 0.0 && end_leg_ > 0.0 && length_ > 0.0)) return false;
  return never_turns_back(s_);
}

bool CurvatureProfileSegment::curvature_monotone() const { return never_turns_back(kappa_); }

ProfileFit fit_curvature_profile(const CurvatureEnd& start, const CurvatureEnd& end) {
  ProfileFit fit;
  const UnitChordProblem unit(start, end);
  if (unit.degenerate()) {
    fit.reason = "the end points coincide";
    return fit;
  }
  const auto residual = [&](const Eigen::Vector3d& p) {
    const CurvatureProfileSegment s(unit.start, p[0], p[1], p[2], unit.end.curvature, unit.end.curvature_slope);
    return unit.miss(s.tangent_angle_at_parameter(1.0), s.end().point);
  };
  // Start from the G1 clothoid's length (§7.1: naive guesses fail in 3 of 4 tries), legs S/3;
  // where that converges to a profile that runs backwards, from other legs. Iterates may leave
  // the valid region on the way (§7.1); only S > 0 is kept.
  const double turning = std::abs(unit.end.tangent_angle - unit.start.tangent_angle);
  const double guess = unit.clothoid_length().value_or(turning > 1e-3 ? 0.5 * turning / std::sin(std::min(0.5 * turning, 1.5)) : 1.0);
  constexpr double leg_starts[][2] = {{1.0 / 3, 1.0 / 3}, {0.2, 0.2}, {0.45, 0.45}, {0.2, 0.45}, {0.45, 0.2}};
  for (const auto& legs : leg_starts) {
    const EndMatch m = match_end(residual, Eigen::Vector3d(guess, legs[0] * guess, legs[1] * guess),
                                 [](const Eigen::Vector3d& q) { return q[0] > 0.0; });
    fit.iterations += m.iterations, fit.residual = m.residual;
    if (!m.parameters) {
      fit.reason = "curvature profile: " + m.reason;
      continue;
    }
    const Eigen::Vector3d& p = *m.parameters;
    const double r = unit.chord;
    const CurvatureProfileSegment segment(start, p[0] * r, p[1] * r, p[2] * r, end.curvature, end.curvature_slope);
    if (segment.arc_length_monotone()) {
      fit.segment = segment;
      fit.reason.clear();
      return fit;
    }
    fit.reason = "the profiles found run backwards in arc length (a leg ≤ 0 or s′ ≤ 0)";
  }
  return fit;
}

}  // namespace gf
