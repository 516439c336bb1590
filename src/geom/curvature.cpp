#include "geom/curvature.hpp"

#include <cmath>

namespace gf {

namespace {

template <int N>
Derivatives derivatives_of(const Bezier<N>& b, double t) {
  Derivatives d{b.point_at(t), {}, {}, {}};
  if constexpr (N >= 1) {
    const auto h1 = b.hodograph();
    d.d1 = h1.point_at(t);
    if constexpr (N >= 2) {
      const auto h2 = h1.hodograph();
      d.d2 = h2.point_at(t);
      if constexpr (N >= 3) d.d3 = h2.hodograph().p[0];
    }
  }
  return d;
}

std::optional<double> finite(double v) {
  if (!std::isfinite(v)) return std::nullopt;
  return v;
}

}  // namespace

Derivatives derivatives_at(const Segment& s, double t) {
  return std::visit([t](const auto& b) { return derivatives_of(b, t); }, s);
}

std::optional<double> curvature(const Derivatives& d) {
  const double f = dot(d.d1, d.d1);
  if (f == 0.0) return std::nullopt;
  return finite(cross(d.d1, d.d2) / (f * std::sqrt(f)));
}

std::optional<double> curvature_derivative(const Derivatives& d) {
  const double f = dot(d.d1, d.d1);
  if (f == 0.0) return std::nullopt;
  const double numerator = cross(d.d1, d.d3) * f - 3.0 * cross(d.d1, d.d2) * dot(d.d1, d.d2);
  return finite(numerator / (f * f * f));
}

std::optional<Vec2> end_tangent(const Segment& s, SegmentEnd end) {
  std::optional<Vec2> result;
  std::visit(
      [&](const auto& b) {
        constexpr int n = std::decay_t<decltype(b)>::degree;
        for (int k = 1; k <= n && !result; ++k) {
          const Vec2 v = end == SegmentEnd::start ? b.p[k] - b.p[0] : b.p[n] - b.p[n - k];
          if (v.x != 0.0 || v.y != 0.0) result = v / norm(v);
        }
      },
      s);
  return result;
}

EndCurvature end_curvature(const Segment& s, SegmentEnd end) {
  const double t = end == SegmentEnd::start ? 0.0 : 1.0;
  const Derivatives d = derivatives_at(s, t);
  if (d.d1.x != 0.0 || d.d1.y != 0.0) return {curvature(d), curvature_derivative(d)};
  // Retracted handle: C'(t0) = 0 and near t0, C' ≈ a·τ + b·τ²/2 with a = C'', b = C'''.
  // Then κ ≈ (a × b) / (2 |a|^3 τ): unbounded unless a × b = 0, when the curve leaves straight.
  const double scale = norm(d.d2) * norm(d.d3);
  const bool straight = std::abs(cross(d.d2, d.d3)) <= 1e-12 * scale;
  if (straight) return {0.0, 0.0};
  return {std::nullopt, std::nullopt};
}

}  // namespace gf
