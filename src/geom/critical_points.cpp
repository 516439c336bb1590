#include "geom/critical_points.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "geom/curvature.hpp"

namespace gf {

namespace {

// Relative size below which a computed polynomial is cancellation noise, i.e. identically zero.
constexpr double cancellation = 1e-12;

// The segment moved to the origin and scaled to unit size: t-values are unchanged, and the
// polynomial coefficients are O(1), so relative thresholds mean the same for every glyph.
struct Normalised {
  PolynomialCurve d1, d2, d3;
  bool empty = false;
};

Normalised normalise(const Segment& s) {
  const Vec2 origin = start_point(s);
  double size = 0.0;
  for_each_point(s, [&](Vec2 p) { size = std::max({size, std::abs(p.x - origin.x), std::abs(p.y - origin.y)}); });
  if (size == 0.0) return {{}, {}, {}, true};
  Segment unit = s;
  std::visit([&](auto& b) { for (Vec2& p : b.p) p = (p - origin) / size; }, unit);
  const PolynomialCurve c = polynomial_of(unit);
  Normalised n;
  n.d1 = c.derivative();
  n.d2 = n.d1.derivative();
  n.d3 = n.d2.derivative();
  return n;
}

double product_scale(const PolynomialCurve& a, const PolynomialCurve& b) {
  return (a.x.magnitude() + a.y.magnitude()) * (b.x.magnitude() + b.y.magnitude());
}

bool strictly_inside(double t) { return t > 0.0 && t < 1.0; }

std::vector<double> inside(const std::vector<SignChange>& roots) {
  std::vector<double> ts;
  for (const SignChange r : roots)
    if (strictly_inside(r.t)) ts.push_back(r.t);
  return ts;
}

std::vector<double> inflections_of(const Normalised& n) {
  if (n.empty) return {};
  const Polynomial g = cross(n.d1, n.d2);
  return inside(sign_changes_in_unit_interval(g, cancellation * product_scale(n.d1, n.d2)));
}

std::vector<AxisExtremum> axis_extrema_of(const Normalised& n) {
  std::vector<AxisExtremum> out;
  if (n.empty) return out;
  const double scale = n.d1.x.magnitude() + n.d1.y.magnitude();
  for (const double t : inside(sign_changes_in_unit_interval(n.d1.y, cancellation * scale)))
    out.push_back({t, Axis::horizontal});
  for (const double t : inside(sign_changes_in_unit_interval(n.d1.x, cancellation * scale)))
    out.push_back({t, Axis::vertical});
  std::sort(out.begin(), out.end(), [](AxisExtremum a, AxisExtremum b) { return a.t < b.t; });
  return out;
}

// Where the speed |C'| vanishes within 1e-4 of t: the root of ḟ = d|C'|²/dt there, if C' is
// zero at it to rounding (below 1e-9 of its scale); nullopt for an ordinary point.
std::optional<double> speed_minimum_near(const PolynomialCurve& d1, const Polynomial& f_dot, double t) {
  double lo = std::max(0.0, t - 1e-4), hi = std::min(1.0, t + 1e-4);
  const double flo = f_dot(lo), fhi = f_dot(hi);
  if (flo > 0.0 || fhi < 0.0) return std::nullopt;  // f has no minimum in the bracket
  for (int i = 0; i < 200 && lo < hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    (f_dot(mid) <= 0.0 ? lo : hi) = mid;
  }
  const double at = 0.5 * (lo + hi);
  if (norm(d1(at)) > 1e-9 * (d1.x.magnitude() + d1.y.magnitude())) return std::nullopt;
  return at;
}

}  // namespace

std::vector<double> inflections(const Segment& s) { return inflections_of(normalise(s)); }

std::vector<AxisExtremum> axis_extrema(const Segment& s) { return axis_extrema_of(normalise(s)); }

CriticalPoints critical_points(const Segment& s) {
  CriticalPoints out;
  const Normalised n = normalise(s);
  if (n.empty) return out;
  out.inflections = inflections_of(n);
  out.axis_extrema = axis_extrema_of(n);

  const Polynomial f = dot(n.d1, n.d1);
  const Polynomial f_dot = 2.0 * dot(n.d1, n.d2);
  const Polynomial g = cross(n.d1, n.d2);
  const Polynomial g_dot = cross(n.d1, n.d3);
  const Polynomial h = 2.0 * g_dot * f - 3.0 * g * f_dot;
  const double scale_h = 2.0 * g_dot.magnitude() * f.magnitude() + 3.0 * g.magnitude() * f_dot.magnitude();
  const Polynomial h_dot = h.derivative();
  for (const double t : inside(sign_changes_in_unit_interval(h, cancellation * scale_h))) {
    // h vanishes where the speed does (f = g = 0), with multiplicity three, so t is only
    // good to ~eps^(1/3) there. ḟ has a simple root at such a point: find it and look.
    if (const std::optional<double> stop = speed_minimum_near(n.d1, f_dot, t)) {
      const bool at_end = (*stop < 1e-6 && f(0.0) == 0.0) || (*stop > 1.0 - 1e-6 && f(1.0) == 0.0);
      if (!at_end && strictly_inside(*stop)) out.cusps.push_back(*stop);  // a retracted handle's end is a node
      continue;
    }
    const std::optional<double> k = curvature(derivatives_at(s, t));
    if (!k) continue;
    // dκ/dt has the sign of h; κ has a maximum where h falls through zero.
    const bool kappa_max = h_dot(t) < 0.0;
    out.curvature_extrema.push_back({t, *k, (*k >= 0.0) == kappa_max});
  }
  return out;
}

}  // namespace gf
