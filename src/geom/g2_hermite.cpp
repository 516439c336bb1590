#include "geom/g2_hermite.hpp"

#include <cmath>

#include "geom/polynomial.hpp"

namespace gf {

namespace {

Cubic with_handles(const HermiteEnd& s, const HermiteEnd& e, double a, double b) {
  return Cubic{s.point, s.point + s.tangent * a, e.point - e.tangent * b, e.point};
}

}  // namespace

std::vector<Cubic> g2_hermite_cubics(const HermiteEnd& start, const HermiteEnd& end, double max_handle) {
  const Vec2 d = end.point - start.point;
  const double chord = norm(d);
  std::vector<Cubic> out;
  if (!(chord > 0.0)) return out;
  if (!(max_handle > 0.0)) max_handle = 2.0 * chord;
  const double c = cross(start.tangent, end.tangent);
  const double u = cross(start.tangent, d), v = cross(d, end.tangent);
  const double k0 = 1.5 * start.curvature, k3 = 1.5 * end.curvature;
  auto accept = [&](double a, double b) {
    if (a > 0.0 && b > 0.0 && a <= max_handle && b <= max_handle) out.push_back(with_handles(start, end, a, b));
  };
  if (std::abs(c) < 1e-9) {
    // Parallel end tangents: the two equations decouple, k0 a² = u and k3 b² = v.
    if (k0 * u > 0.0 && k3 * v > 0.0) accept(std::sqrt(u / k0), std::sqrt(v / k3));
    return out;
  }
  // a = A t, t ∈ [0, 1]; b(t) = (u − k0 A² t²)/c; f(t) = k3 b(t)² + c A t − v = 0.
  const double A = max_handle;
  const double b_coef[] = {u / c, 0.0, -k0 * A * A / c};
  const Polynomial b_of_t(b_coef);
  const double lin[] = {-v, c * A};
  const Polynomial f = k3 * (b_of_t * b_of_t) + Polynomial(lin);
  const double scale = std::abs(k3) * (u * u / (c * c) + k0 * k0 * A * A * A * A / (c * c)) + std::abs(c * A) + std::abs(v);
  for (const SignChange& r : sign_changes_in_unit_interval(f, 1e-13 * scale)) accept(A * r.t, b_of_t(r.t));
  return out;
}

namespace {

// What a cubic with one free end needs of its ends: the bound end's cross term, T0 × D for a
// free end or D × T3 for a free start, c = T0 × T3 and the longest handle (2 |D| by default).
// None where the ends coincide or the given handle is not positive.
struct OneFreeEnd {
  double bound_cross, c, max_handle;
};

std::optional<OneFreeEnd> one_free_end(const HermiteEnd& start, const HermiteEnd& end, SegmentEnd free,
                                       double given_handle, double max_handle) {
  const Vec2 d = end.point - start.point;
  const double chord = norm(d);
  if (!(chord > 0.0) || !(given_handle > 0.0)) return std::nullopt;
  const double bound_cross = free == SegmentEnd::start ? cross(d, end.tangent) : cross(start.tangent, d);
  return OneFreeEnd{bound_cross, cross(start.tangent, end.tangent), max_handle > 0.0 ? max_handle : 2.0 * chord};
}

}  // namespace

std::optional<Cubic> g2_hermite_cubic_with_free_end(const HermiteEnd& start, const HermiteEnd& end, SegmentEnd free,
                                                    double free_handle, double max_handle) {
  const std::optional<OneFreeEnd> p = one_free_end(start, end, free, free_handle, max_handle);
  if (!p) return std::nullopt;
  // κ3 b² = 2/3 (D × T3 − a c) for a free start; κ0 a² = 2/3 (T0 × D − b c) for a free end.
  const bool free_start = free == SegmentEnd::start;
  const double kappa = free_start ? end.curvature : start.curvature;
  const double rhs = (2.0 / 3.0) * (p->bound_cross - free_handle * p->c);
  if (kappa == 0.0 || !(rhs / kappa > 0.0)) return std::nullopt;
  const double other = std::sqrt(rhs / kappa);
  if (other > p->max_handle) return std::nullopt;
  return free_start ? with_handles(start, end, free_handle, other) : with_handles(start, end, other, free_handle);
}

std::optional<Cubic> g2_hermite_cubic_from_flat_end(const HermiteEnd& start, const HermiteEnd& end, SegmentEnd free,
                                                    double flat_handle, double max_handle) {
  const std::optional<OneFreeEnd> p = one_free_end(start, end, free, flat_handle, max_handle);
  if (!p || std::abs(p->c) < 1e-12) return std::nullopt;
  // κ0 = 0 ⇔ T0 × D = b c; κ3 = 0 ⇔ D × T3 = a c (the equations above).
  const double fixed = p->bound_cross / p->c;
  if (!(fixed > 0.0) || fixed > p->max_handle || flat_handle > p->max_handle) return std::nullopt;
  return free == SegmentEnd::start ? with_handles(start, end, fixed, flat_handle) : with_handles(start, end, flat_handle, fixed);
}

}  // namespace gf
