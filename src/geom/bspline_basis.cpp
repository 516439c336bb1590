#include "geom/bspline_basis.hpp"

#include <algorithm>
#include <cmath>

#include "geom/foot_point.hpp"

namespace gf {

BSplineBasis::BSplineBasis(int spans, bool periodic) : spans_(spans), periodic_(periodic) {
  if (periodic) return;
  for (int i = 0; i < 4; ++i) knots_.push_back(0.0);
  for (int i = 1; i < spans; ++i) knots_.push_back(double(i) / spans);
  for (int i = 0; i < 4; ++i) knots_.push_back(1.0);
}

BSplineBasis::Weights BSplineBasis::at(double u) const {
  if (periodic_) {
    // The uniform cubic B-spline's four pieces at the local parameter t.
    const double x = (u - std::floor(u)) * spans_;
    const int s = std::min(static_cast<int>(x), spans_ - 1);
    const double t = x - s, t2 = t * t, t3 = t2 * t;
    return {s, {(1 - t) * (1 - t) * (1 - t) / 6.0, (3 * t3 - 6 * t2 + 4) / 6.0, (-3 * t3 + 3 * t2 + 3 * t + 1) / 6.0,
                t3 / 6.0}};
  }
  // Cox–de Boor on the clamped knots.
  const int k = std::clamp(static_cast<int>(u * spans_), 0, spans_ - 1) + 3;
  std::array<double, 4> n{1.0, 0.0, 0.0, 0.0};
  std::array<double, 4> left{}, right{};
  for (int j = 1; j <= 3; ++j) {
    left[j] = u - knots_[k + 1 - j];
    right[j] = knots_[k + j] - u;
    double saved = 0.0;
    for (int r = 0; r < j; ++r) {
      const double temp = n[r] / (right[r + 1] + left[j - r]);
      n[r] = saved + right[r + 1] * temp;
      saved = left[j - r] * temp;
    }
    n[j] = saved;
  }
  return {k - 3, n};
}

Vec2 BSplineBasis::point_at(std::span<const Vec2> controls, double u) const {
  const Weights w = at(u);
  Vec2 p{};
  for (int k = 0; k < 4; ++k) p += controls[static_cast<std::size_t>(control(w.first + k))] * w.w[k];
  return p;
}

std::vector<Cubic> BSplineBasis::span_cubics(std::span<const Vec2> controls) const {
  std::vector<Cubic> out;
  for (int s = 0; s < spans_; ++s) out.push_back(span_cubic(controls, s));
  return out;
}

Cubic BSplineBasis::span_cubic(std::span<const Vec2> controls, int s) const {
  const double a0 = double(s) / spans_, a1 = double(s + 1) / spans_;
  // The end of the last periodic span is u = 1 ≡ 0; evaluate it as the start of span 0.
  const Vec2 q0 = point_at(controls, a0), q1 = point_at(controls, a0 + (a1 - a0) / 3.0),
             q2 = point_at(controls, a0 + 2.0 * (a1 - a0) / 3.0),
             q3 = periodic_ && s + 1 == spans_ ? point_at(controls, 0.0) : point_at(controls, a1);
  // B(1/3) = q1 and B(2/3) = q2: [4/9 2/9; 2/9 4/9] [c1; c2] = [r1; r2].
  const Vec2 r1 = q1 - q0 * (8.0 / 27.0) - q3 * (1.0 / 27.0);
  const Vec2 r2 = q2 - q0 * (1.0 / 27.0) - q3 * (8.0 / 27.0);
  return Cubic{q0, (r1 * 4.0 - r2 * 2.0) * 0.75, (r2 * 4.0 - r1 * 2.0) * 0.75, q3};
}

namespace {

// The span holding u and the local parameter on it.
std::pair<std::size_t, double> span_at(double u, int spans) {
  const int s = std::clamp(static_cast<int>(u * spans), 0, spans - 1);
  return {static_cast<std::size_t>(s), u * spans - s};
}

}  // namespace

Vec2 BSplineBasis::point_on_spans(std::span<const Cubic> spans, double u) const {
  const auto [s, t] = span_at(u, spans_);
  return spans[s].point_at(t);
}

double BSplineBasis::foot_parameter(std::span<const Cubic> spans, Vec2 p, double u, int steps) const {
  for (int step = 0; step < steps; ++step) {
    const auto [s, t] = span_at(u, spans_);
    const FootStep f = foot_step(spans[s], p, t);
    const double move = f.along / f.slope;
    if (!std::isfinite(move)) break;
    u -= move / spans_;
    u = periodic_ ? u - std::floor(u) : std::clamp(u, 0.0, 1.0);
  }
  return u;
}

}  // namespace gf
