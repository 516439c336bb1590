#include "aesthetic/polynomial_spiral.hpp"

#include <cmath>

namespace gf {

PolynomialSpiral::PolynomialSpiral(const CurvatureEnd& start, double length, double end_curvature,
                                   double end_curvature_slope, double symmetric_bump, double odd_bump)
    : origin_(start.point),
      length_(length),
      c1_(symmetric_bump),
      c2_(odd_bump),
      ends_{{start.curvature, start.curvature_slope}, {end_curvature, end_curvature_slope}} {
  const double k0 = start.curvature, d0 = length * start.curvature_slope;
  const double k1 = end_curvature, d1 = length * end_curvature_slope;
  // Hermite basis H₀₀ = 1 − 3u² + 2u³, H₁₀ = u − 2u² + u³, H₀₁ = 3u² − 2u³, H₁₁ = u³ − u²;
  // bumps 16(u² − 2u³ + u⁴) and 20(−u² + 4u³ − 5u⁴ + 2u⁵).
  const double c[] = {k0,
                      d0,
                      -3.0 * k0 - 2.0 * d0 + 3.0 * k1 - d1 + 16.0 * c1_ - 20.0 * c2_,
                      2.0 * k0 + d0 - 2.0 * k1 + d1 - 32.0 * c1_ + 80.0 * c2_,
                      16.0 * c1_ - 100.0 * c2_,
                      40.0 * c2_};
  kappa_ = Polynomial(c);
  const double theta0[] = {start.tangent_angle}, speed[] = {length};
  speed_ = Polynomial(speed);
  theta_ = Polynomial(theta0) + length * kappa_.antiderivative();
}

LacPoint PolynomialSpiral::state(double u, Vec2 point) const {
  if (u == 0.0 || u == 1.0) {
    const double* end = ends_[u == 0.0 ? 0 : 1];
    return {point, direction_of(theta_(u)), end[0], end[1]};
  }
  return {point, direction_of(theta_(u)), kappa_(u), kappa_.derivative()(u) / length_};
}

LacPoint PolynomialSpiral::at(double sigma) const {
  const double u = std::clamp(sigma / length_, 0.0, 1.0);
  return state(u, origin_ + direction_integral(theta_, speed_, 0.0, u));
}

std::vector<LacPoint> PolynomialSpiral::sample(int n) const {
  std::vector<LacPoint> out;
  out.reserve(static_cast<std::size_t>(n) + 1);
  Vec2 point = origin_;
  out.push_back(state(0.0, point));
  for (int k = 1; k <= n; ++k) {
    point += direction_integral(theta_, speed_, double(k - 1) / n, double(k) / n);
    out.push_back(state(double(k) / n, point));
  }
  return out;
}

bool PolynomialSpiral::curvature_monotone() const { return never_turns_back(kappa_); }

SpiralFit fit_polynomial_spiral(const CurvatureEnd& start, const CurvatureEnd& end) {
  SpiralFit fit;
  const UnitChordProblem unit(start, end);
  if (unit.degenerate()) {
    fit.reason = "the end points coincide";
    return fit;
  }
  const auto residual = [&](const Eigen::Vector3d& p) {
    const PolynomialSpiral s(unit.start, p[0], unit.end.curvature, unit.end.curvature_slope, p[1], p[2]);
    return unit.miss(s.tangent_angle_at(p[0]), s.end().point);
  };
  const EndMatch m = match_end(residual, Eigen::Vector3d(unit.clothoid_length().value_or(1.0), 0.0, 0.0),
                               [](const Eigen::Vector3d& q) { return q[0] > 0.0; });
  fit.iterations = m.iterations, fit.residual = m.residual;
  if (!m.parameters) {
    fit.reason = "polynomial spiral: " + m.reason;
    return fit;
  }
  const Eigen::Vector3d& p = *m.parameters;
  // Back to font units: S scales by the chord, the bumps (curvatures) by 1 / chord.
  fit.spiral = PolynomialSpiral(start, p[0] * unit.chord, end.curvature, end.curvature_slope, p[1] / unit.chord,
                                p[2] / unit.chord);
  return fit;
}

}  // namespace gf
