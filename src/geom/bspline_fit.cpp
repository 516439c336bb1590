#include "geom/bspline_fit.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

namespace gf {

namespace {

// Cubic B-spline basis on the clamped uniform knot vector of `spans` spans (Cox–de Boor).
struct Basis {
  std::vector<double> knots;
  int count;  // spans + 3 basis functions

  explicit Basis(int spans) : count(spans + 3) {
    for (int i = 0; i < 4; ++i) knots.push_back(0.0);
    for (int i = 1; i < spans; ++i) knots.push_back(double(i) / spans);
    for (int i = 0; i < 4; ++i) knots.push_back(1.0);
  }

  int span_of(double u) const {
    const int spans = count - 3;
    return std::clamp(static_cast<int>(u * spans), 0, spans - 1) + 3;
  }

  // The four non-zero basis values at u and the index of the first.
  std::array<double, 4> values(double u, int& first) const {
    const int k = span_of(u);
    first = k - 3;
    std::array<double, 4> n{1.0, 0.0, 0.0, 0.0};
    std::array<double, 4> left{}, right{};
    for (int j = 1; j <= 3; ++j) {
      left[j] = u - knots[k + 1 - j];
      right[j] = knots[k + j] - u;
      double saved = 0.0;
      for (int r = 0; r < j; ++r) {
        const double temp = n[r] / (right[r + 1] + left[j - r]);
        n[r] = saved + right[r + 1] * temp;
        saved = left[j - r] * temp;
      }
      n[j] = saved;
    }
    return n;
  }
};

}  // namespace

BSplineFit fit_cubic_bspline(std::span<const Vec2> points, int span_count, bool closed) {
  BSplineFit fit;
  const int m = static_cast<int>(points.size());
  if (span_count < 1 || m < span_count + 3) return fit;
  std::vector<double> u(points.size(), 0.0);
  for (int i = 1; i < m; ++i) u[i] = u[i - 1] + distance(points[i], points[i - 1]);
  if (u.back() == 0.0) return fit;
  for (double& v : u) v /= u.back();

  const Basis basis(span_count);
  const int n = basis.count;
  std::vector<Vec2> control(static_cast<std::size_t>(n));
  const auto evaluate = [&](double t) {
    int first = 0;
    const auto values = basis.values(t, first);
    Vec2 p{};
    for (int k = 0; k < 4; ++k) p += control[first + k] * values[k];
    return p;
  };
  // Each span is a cubic polynomial: its Bézier form from four of its points (exact).
  const auto to_spans = [&] {
    fit.spans.clear();
    for (int s = 0; s < span_count; ++s) {
      const double a0 = double(s) / span_count, a1 = double(s + 1) / span_count;
      const Vec2 q0 = evaluate(a0), q1 = evaluate(a0 + (a1 - a0) / 3.0), q2 = evaluate(a0 + 2.0 * (a1 - a0) / 3.0),
                 q3 = evaluate(a1);
      // B(1/3) = q1 and B(2/3) = q2: [4/9 2/9; 2/9 4/9] [c1; c2] = [r1; r2].
      const Vec2 r1 = q1 - q0 * (8.0 / 27.0) - q3 * (1.0 / 27.0);
      const Vec2 r2 = q2 - q0 * (1.0 / 27.0) - q3 * (8.0 / 27.0);
      fit.spans.push_back(Cubic{q0, (r1 * 4.0 - r2 * 2.0) * 0.75, (r2 * 4.0 - r1 * 2.0) * 0.75, q3});
    }
  };
  // Least squares for the controls with the end conditions as constraints, solved with
  // Lagrange multipliers (the KKT system [2AᵀA Cᵀ; C 0] [c; λ] = [2Aᵀb; d]): the clamped ends
  // interpolate the first and last points, and a closed sequence also leaves its first point
  // in the direction it arrives (c₁ − c₀ = c_{n−1} − c_{n−2}), so the seam is G1. Then
  // parameter correction: each point's parameter moves to its foot on the curve (Newton), and
  // the fit is solved again (Hoschek's iteration).
  const int constraints = closed ? 3 : 2;
  for (int iteration = 0; iteration < 6; ++iteration) {
    Eigen::MatrixXd a = Eigen::MatrixXd::Zero(m, n);
    Eigen::MatrixXd rhs(m, 2);
    for (int i = 0; i < m; ++i) {
      int first = 0;
      const auto values = basis.values(u[i], first);
      for (int k = 0; k < 4; ++k) a(i, first + k) = values[k];
      rhs(i, 0) = points[i].x;
      rhs(i, 1) = points[i].y;
    }
    Eigen::MatrixXd kkt = Eigen::MatrixXd::Zero(n + constraints, n + constraints);
    Eigen::MatrixXd right = Eigen::MatrixXd::Zero(n + constraints, 2);
    kkt.topLeftCorner(n, n) = 2.0 * a.transpose() * a;
    right.topRows(n) = 2.0 * a.transpose() * rhs;
    auto constrain = [&](int row, std::initializer_list<std::pair<int, double>> terms, Vec2 value) {
      for (const auto& [j, w] : terms) kkt(n + row, j) = kkt(j, n + row) = w;
      right(n + row, 0) = value.x;
      right(n + row, 1) = value.y;
    };
    constrain(0, {{0, 1.0}}, points.front());
    constrain(1, {{n - 1, 1.0}}, points.back());
    if (closed) constrain(2, {{1, 1.0}, {0, -1.0}, {n - 1, -1.0}, {n - 2, 1.0}}, {0.0, 0.0});
    const Eigen::MatrixXd solution = kkt.fullPivLu().solve(right);
    for (int j = 0; j < n; ++j) control[j] = {solution(j, 0), solution(j, 1)};
    control.front() = points.front();  // equal already, up to the solver's rounding
    control.back() = points.back();
    to_spans();
    for (int i = 1; i + 1 < m; ++i) {
      const int s = std::clamp(static_cast<int>(u[i] * span_count), 0, span_count - 1);
      const Cubic& c = fit.spans[static_cast<std::size_t>(s)];
      const double t = u[i] * span_count - s;
      const auto h1 = c.hodograph();
      const auto h2 = h1.hodograph();
      const Vec2 d = c.point_at(t) - points[i], d1 = h1.point_at(t), d2 = h2.point_at(t);
      const double step = dot(d, d1) / (dot(d1, d1) + dot(d, d2));
      if (std::isfinite(step)) u[i] = std::clamp(u[i] - step / span_count, 0.0, 1.0);
    }
  }
  for (int i = 0; i < m; ++i) fit.max_residual = std::max(fit.max_residual, distance(evaluate(u[i]), points[i]));
  return fit;
}

BSplineFit fit_cubic_bspline_within(std::span<const Vec2> points, double tolerance, bool closed) {
  BSplineFit fit;
  for (int spans = closed ? 2 : 1; spans + 3 <= static_cast<int>(points.size()); spans *= 2) {
    fit = fit_cubic_bspline(points, spans, closed);
    if (fit.max_residual <= tolerance) break;
  }
  return fit;
}

}  // namespace gf
