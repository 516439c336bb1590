#include "geom/bspline_fit.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

#include "geom/bspline_basis.hpp"
#include "geom/foot_point.hpp"

namespace gf {

BSplineFit fit_cubic_bspline(std::span<const Vec2> points, int span_count, bool closed) {
  BSplineFit fit;
  const int m = static_cast<int>(points.size());
  if (span_count < 1 || m < span_count + 3) return fit;
  std::vector<double> u = chord_length_parameters(points);
  if (u.back() == 0.0) return fit;

  const BSplineBasis basis(span_count, false);
  const int n = basis.control_count();
  std::vector<Vec2> control(static_cast<std::size_t>(n));
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
      const BSplineBasis::Weights w = basis.at(u[i]);
      for (int k = 0; k < 4; ++k) a(i, w.first + k) = w.w[k];
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
    fit.spans = basis.span_cubics(control);
    for (int i = 1; i + 1 < m; ++i) u[i] = basis.foot_parameter(fit.spans, points[i], u[i], 1);
  }
  for (int i = 0; i < m; ++i) fit.max_residual = std::max(fit.max_residual, distance(basis.point_at(control, u[i]), points[i]));
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
