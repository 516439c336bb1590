// Bézier curves of degree 1 (Line), 2 (Quad) and 3 (Cubic) with exact evaluation, hodographs
// and the power-basis polynomials that the analysis solves.
#pragma once

#include <algorithm>
#include <array>
#include <cassert>
#include <cstddef>
#include <initializer_list>

#include "geom/polynomial.hpp"
#include "geom/vec2.hpp"

namespace gf {

/// A polynomial curve t -> (x(t), y(t)) in the power basis.
struct PolynomialCurve {
  Polynomial x, y;
  Vec2 operator()(double t) const { return {x(t), y(t)}; }
  PolynomialCurve derivative() const { return {x.derivative(), y.derivative()}; }
};

inline Polynomial dot(const PolynomialCurve& a, const PolynomialCurve& b) {
  return a.x * b.x + a.y * b.y;
}
inline Polynomial cross(const PolynomialCurve& a, const PolynomialCurve& b) {
  return a.x * b.y - a.y * b.x;
}

template <int Degree>
struct Bezier {
  static_assert(Degree >= 0 && Degree <= 3);
  static constexpr int degree = Degree;
  std::array<Vec2, Degree + 1> p{};

  constexpr Bezier() = default;
  /// The control points in order: Cubic{p0, p1, p2, p3}.
  constexpr Bezier(std::initializer_list<Vec2> points) {
    assert(points.size() == p.size());
    std::copy_n(points.begin(), std::min(points.size(), p.size()), p.begin());
  }

  Vec2 start() const { return p.front(); }
  Vec2 end() const { return p.back(); }

  /// de Casteljau: stable for every t, exact at t = 0 and t = 1.
  Vec2 point_at(double t) const {
    if (t == 0.0) return p.front();
    if (t == 1.0) return p.back();
    auto w = p;
    for (int k = Degree; k > 0; --k)
      for (int i = 0; i < k; ++i) w[i] = lerp(w[i], w[i + 1], t);
    return w[0];
  }

  /// The same curve traversed the other way: its control points in reverse order.
  Bezier reversed() const {
    Bezier r;
    std::reverse_copy(p.begin(), p.end(), r.p.begin());
    return r;
  }

  /// The derivative curve (hodograph), a Bézier of one degree less.
  Bezier<(Degree > 0 ? Degree - 1 : 0)> hodograph() const {
    Bezier<(Degree > 0 ? Degree - 1 : 0)> h;
    if constexpr (Degree > 0)
      for (int i = 0; i < Degree; ++i) h.p[i] = (p[i + 1] - p[i]) * double(Degree);
    return h;
  }

  /// The same curve, same parameter, in the power basis.
  PolynomialCurve polynomial() const {
    // c_k = C(n,k) * sum_i (-1)^(k-i) C(k,i) P_i
    std::array<double, Degree + 1> cx{}, cy{};
    double cnk = 1.0;
    for (int k = 0; k <= Degree; ++k) {
      Vec2 sum{};
      double cki = 1.0;
      for (int i = 0; i <= k; ++i) {
        const double sign = ((k - i) % 2 == 0) ? 1.0 : -1.0;
        sum += p[i] * (sign * cki);
        cki = cki * (k - i) / (i + 1);
      }
      cx[k] = cnk * sum.x;
      cy[k] = cnk * sum.y;
      cnk = cnk * (Degree - k) / (k + 1);
    }
    return {Polynomial(cx), Polynomial(cy)};
  }

  /// Split at t into the parts before and after.
  std::array<Bezier, 2> split(double t) const {
    Bezier a, b;
    auto w = p;
    for (int k = 0; k <= Degree; ++k) {
      a.p[k] = w[0];
      b.p[Degree - k] = w[Degree - k];
      for (int i = 0; i < Degree - k; ++i) w[i] = lerp(w[i], w[i + 1], t);
    }
    return {a, b};
  }

  /// The part of the curve for t in [t0, t1].
  Bezier subsegment(double t0, double t1) const {
    if (t0 == 0.0 && t1 == 1.0) return *this;
    const Bezier tail = t0 == 0.0 ? *this : split(t0)[1];
    if (t1 == 1.0) return tail;
    return tail.split((t1 - t0) / (1.0 - t0))[0];
  }

  friend bool operator==(const Bezier&, const Bezier&) = default;
};

using Line = Bezier<1>;
using Quad = Bezier<2>;
using Cubic = Bezier<3>;

/// Degree elevation: the same parametric curve as a cubic (exact up to rounding of 1/3, 2/3).
inline Cubic to_cubic(const Line& l) {
  return {{l.p[0], lerp(l.p[0], l.p[1], 1.0 / 3.0), lerp(l.p[0], l.p[1], 2.0 / 3.0), l.p[1]}};
}
inline Cubic to_cubic(const Quad& q) {
  return {{q.p[0], q.p[0] + (q.p[1] - q.p[0]) * (2.0 / 3.0), q.p[2] + (q.p[1] - q.p[2]) * (2.0 / 3.0),
           q.p[2]}};
}
inline Cubic to_cubic(const Cubic& c) { return c; }

}  // namespace gf
