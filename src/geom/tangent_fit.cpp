#include "geom/tangent_fit.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "geom/foot_point.hpp"

namespace gf {

namespace {

constexpr int max_rounds = 32;
constexpr int newton_steps = 3;      // of each point's foot on the cubic, a round
constexpr double settled = 1e-9;     // a round that changes the handles less (of the chord) ends it

// The handle lengths (a, b) that meet rows a·along_a + b·along_b = rest in least squares (the
// normal equations, 2 × 2).
struct HandleSystem {
  double c11 = 0.0, c12 = 0.0, c22 = 0.0, x1 = 0.0, x2 = 0.0;
  void add(double along_a, double along_b, double rest) {
    c11 += along_a * along_a, c12 += along_a * along_b, c22 += along_b * along_b;
    x1 += along_a * rest, x2 += along_b * rest;
  }
  std::optional<std::pair<double, double>> solve() const {
    const double det = c11 * c22 - c12 * c12;
    if (!(std::abs(det) > 1e-12 * c11 * c22)) return std::nullopt;
    return std::pair{(x1 * c22 - x2 * c12) / det, (c11 * x2 - c12 * x1) / det};
  }
};

}  // namespace

std::optional<Cubic> fit_cubic_with_end_tangents(Vec2 p0, Vec2 t0, Vec2 p3, Vec2 t3, std::span<const Vec2> points) {
  const std::size_t n = points.size();
  if (n < 3) return std::nullopt;
  const double chord = distance(p0, p3);
  std::vector<double> t = chord_length_parameters(points);
  if (!(t.back() > 0.0) || !(chord > 0.0)) return std::nullopt;
  // B(u) = P0 (B0 + B1) + P3 (B2 + B3) + a B1 T0 − b B2 T3: linear in the handle lengths a, b.
  auto terms = [&](double u, Vec2 q) {
    const double v = 1.0 - u;
    const double b0 = v * v * v, b1 = 3.0 * v * v * u, b2 = 3.0 * v * u * u, b3 = u * u * u;
    struct Terms {
      Vec2 along_a, along_b, rest;
    };
    return Terms{t0 * b1, t3 * -b2, q - (p0 * (b0 + b1) + p3 * (b2 + b3))};
  };
  // First the whole residual at chord-length parameters, then, point by point, only its part
  // across the cubic at the point's foot (tangent distance minimisation: the along-curve part
  // is the parameter's error, not the shape's; Wang, Pottmann & Liu, ACM TOG 2006).
  HandleSystem first;
  for (std::size_t k = 0; k < n; ++k) {
    const auto e = terms(t[k], points[k]);
    first.add(e.along_a.x, e.along_b.x, e.rest.x);
    first.add(e.along_a.y, e.along_b.y, e.rest.y);
  }
  std::optional<std::pair<double, double>> ab = first.solve();
  for (int round = 0; ab && round < max_rounds; ++round) {
    const auto [a, b] = *ab;
    if (!(a > 0.0) || !(b > 0.0)) return std::nullopt;
    const Cubic c{p0, p0 + t0 * a, p3 - t3 * b, p3};
    const Quad velocity = c.hodograph();
    HandleSystem across;
    for (std::size_t k = 0; k < n; ++k) {
      for (int step = 0; step < newton_steps && k > 0 && k + 1 < n; ++step) {
        const FootStep f = foot_step(c, points[k], t[k]);
        if (!(f.slope > 0.0)) break;
        t[k] = std::clamp(t[k] - f.along / f.slope, 0.0, 1.0);
      }
      const Vec2 d1 = velocity.point_at(t[k]);
      const double speed = norm(d1);
      if (!(speed > 0.0)) continue;
      const Vec2 normal{-d1.y / speed, d1.x / speed};
      const auto e = terms(t[k], points[k]);
      across.add(dot(e.along_a, normal), dot(e.along_b, normal), dot(e.rest, normal));
    }
    const std::optional<std::pair<double, double>> next = across.solve();
    if (!next) break;
    const double change = std::max(std::abs(next->first - a), std::abs(next->second - b));
    ab = next;
    if (change < settled * chord) break;
  }
  if (!ab || !(ab->first > 0.0) || !(ab->second > 0.0)) return std::nullopt;
  return Cubic{p0, p0 + t0 * ab->first, p3 - t3 * ab->second, p3};
}

}  // namespace gf
