#include "geom/g2_handle_fit.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

#include "geom/foot_point.hpp"

namespace gf {

namespace {

constexpr int max_rounds = 40;
constexpr int projection_steps = 12;
constexpr int newton_steps = 2;         // of each point's foot on its cubic, a round
constexpr int whole_offset_rounds = 4;  // first rounds fitting each point's whole offset from its foot
constexpr double settled = 1e-9;        // a round moving the handles less (of the chord sum) ends the rounds
constexpr double matched = 1e-9;        // κ continuous to this share of the larger side
constexpr double longest_handle = 1.5;  // of the chord
constexpr double shortest_handle = 1e-3;

// The curvature equations h(x) = 0 and their gradients, x = (a0, b0, a1, b1, …).
struct CurvatureEquations {
  Eigen::VectorXd h;
  Eigen::MatrixXd grad;
  double largest_relative = 0.0;  // max |h| over the larger side's |κ| (or 1/the chord sum)
};

CurvatureEquations curvature_equations(std::span<const CubicFrame> frames, const Eigen::VectorXd& x,
                                       std::optional<double> start, std::optional<double> end, double chord_sum) {
  const std::size_t m = frames.size();
  const int rows = static_cast<int>(m - 1) + (start ? 1 : 0) + (end ? 1 : 0);
  CurvatureEquations e{Eigen::VectorXd::Zero(rows), Eigen::MatrixXd::Zero(rows, 2 * static_cast<int>(m))};
  int r = 0;
  const auto record = [&](double left, double right) {
    e.h[r] = left - right;
    e.largest_relative = std::max(e.largest_relative,
                                  std::abs(left - right) / std::max({std::abs(left), std::abs(right), 1.0 / chord_sum}));
  };
  // ∂κ0/∂a = −2κ0/a, ∂κ0/∂b = −2/3·c/a²; ∂κ3/∂b = −2κ3/b, ∂κ3/∂a = −2/3·c/b².
  const auto start_row = [&](std::size_t i, double sign) {
    const double a = x[2 * i], b = x[2 * i + 1], c = cross(frames[i].start_tangent, frames[i].end_tangent);
    const double k = frames[i].start_curvature(a, b);
    e.grad(r, 2 * i) += sign * -2.0 * k / a, e.grad(r, 2 * i + 1) += sign * (-2.0 / 3.0) * c / (a * a);
    return k;
  };
  const auto end_row = [&](std::size_t i, double sign) {
    const double a = x[2 * i], b = x[2 * i + 1], c = cross(frames[i].start_tangent, frames[i].end_tangent);
    const double k = frames[i].end_curvature(a, b);
    e.grad(r, 2 * i + 1) += sign * -2.0 * k / b, e.grad(r, 2 * i) += sign * (-2.0 / 3.0) * c / (b * b);
    return k;
  };
  if (start) record(start_row(0, 1.0), *start), ++r;
  for (std::size_t i = 1; i < m; ++i) {
    const double left = end_row(i - 1, 1.0);
    record(left, start_row(i, -1.0)), ++r;
  }
  if (end) record(end_row(m - 1, 1.0), *end), ++r;
  return e;
}

bool admissible(std::span<const CubicFrame> frames, const Eigen::VectorXd& x) {
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const double chord = distance(frames[i].start, frames[i].end);
    for (const double h : {x[2 * i], x[2 * i + 1]})
      if (!(h > shortest_handle * chord && h <= longest_handle * chord)) return false;
  }
  return true;
}

}  // namespace

std::optional<CubicFrame> frame_of(const Cubic& c) {
  const Vec2 out = c.p[1] - c.p[0], in = c.p[3] - c.p[2];
  if (!(norm(out) > 0.0) || !(norm(in) > 0.0)) return std::nullopt;
  return CubicFrame{c.p[0], out / norm(out), c.p[3], in / norm(in)};
}

std::optional<std::vector<Cubic>> fit_g2_handles(std::span<const CubicFrame> frames,
                                                 std::span<const std::vector<Vec2>> points,
                                                 std::span<const std::pair<double, double>> initial, std::optional<double> start,
                                                 std::optional<double> end) {
  const std::size_t m = frames.size();
  if (m == 0 || points.size() != m || initial.size() != m) return std::nullopt;
  const int n = 2 * static_cast<int>(m);
  Eigen::VectorXd x(n);
  double chord_sum = 0.0;
  std::vector<std::vector<double>> feet(m);
  for (std::size_t i = 0; i < m; ++i) {
    x[2 * i] = initial[i].first, x[2 * i + 1] = initial[i].second;
    chord_sum += distance(frames[i].start, frames[i].end);
    feet[i] = chord_length_parameters(points[i]);
  }
  if (!(chord_sum > 0.0) || !admissible(frames, x)) return std::nullopt;

  for (int round = 0; round < max_rounds; ++round) {
    // A point at parameter u is P0 (B0 + B1) + P3 (B2 + B3) + a B1 T0 − b B2 T3, linear in
    // (a, b): its offset from each point at the point's foot, then only the part across the
    // curve (tangent distance minimisation, as geom/tangent_fit).
    Eigen::MatrixXd normal = Eigen::MatrixXd::Zero(n, n);
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n);
    for (std::size_t i = 0; i < m; ++i) {
      const CubicFrame& f = frames[i];
      const Cubic c = f.with_handles(x[2 * i], x[2 * i + 1]);
      const Quad velocity = c.hodograph();
      for (std::size_t k = 0; k < points[i].size(); ++k) {
        double& u = feet[i][k];
        for (int step = 0; step < newton_steps && k > 0 && k + 1 < points[i].size(); ++step) {
          const FootStep s = foot_step(c, points[i][k], u);
          if (!(s.slope > 0.0)) break;
          u = std::clamp(u - s.along / s.slope, 0.0, 1.0);
        }
        const double v = 1.0 - u, b0 = v * v * v, b1 = 3.0 * v * v * u, b2 = 3.0 * v * u * u, b3 = u * u * u;
        const Vec2 along_a = f.start_tangent * b1, along_b = f.end_tangent * -b2;
        const Vec2 rest = points[i][k] - (f.start * (b0 + b1) + f.end * (b2 + b3));
        const int ia = 2 * static_cast<int>(i), ib = ia + 1;
        const auto add = [&](Vec2 across) {
          const double qa = dot(along_a, across), qb = dot(along_b, across), r = dot(rest, across);
          normal(ia, ia) += qa * qa, normal(ia, ib) += qa * qb, normal(ib, ia) += qa * qb, normal(ib, ib) += qb * qb;
          rhs[ia] += qa * r, rhs[ib] += qb * r;
        };
        const Vec2 d1 = velocity.point_at(u);
        const double speed = norm(d1);
        // The whole offset while the feet settle, and where a foot sits on an end (a point
        // beyond it along the tangent is no nearer for that); else only its part across.
        if (round < whole_offset_rounds || u <= 0.0 || u >= 1.0 || !(speed > 0.0)) {
          add({1.0, 0.0}), add({0.0, 1.0});
          continue;
        }
        add({-d1.y / speed, d1.x / speed});
      }
    }
    // A little pull towards the handles as they are, so a frame its points do not determine
    // keeps them.
    const double ridge = 1e-9 * std::max(normal.diagonal().maxCoeff(), 1.0);
    normal.diagonal().array() += ridge;
    rhs += ridge * x;
    const CurvatureEquations e = curvature_equations(frames, x, start, end, chord_sum);
    const int q = static_cast<int>(e.h.size());
    Eigen::MatrixXd kkt = Eigen::MatrixXd::Zero(n + q, n + q);
    Eigen::VectorXd b(n + q);
    kkt.topLeftCorner(n, n) = normal;
    kkt.topRightCorner(n, q) = e.grad.transpose();
    kkt.bottomLeftCorner(q, n) = e.grad;
    b.head(n) = rhs;
    b.tail(q) = e.grad * x - e.h;
    const Eigen::VectorXd target = kkt.colPivHouseholderQr().solve(b).head(n);
    if (!target.allFinite()) return std::nullopt;
    const Eigen::VectorXd step = target - x;
    double damping = 1.0;
    while (damping > 1e-4 && !admissible(frames, x + damping * step)) damping *= 0.5;
    if (damping <= 1e-4) break;
    x += damping * step;
    if (damping * step.cwiseAbs().maxCoeff() < settled * chord_sum) break;
  }
  // The rounds' last linearisation leaves the curvature equations met to first order: the
  // least-norm Newton steps onto them.
  for (int step = 0; step <= projection_steps; ++step) {
    const CurvatureEquations e = curvature_equations(frames, x, start, end, chord_sum);
    if (e.largest_relative <= matched) {
      std::vector<Cubic> out;
      for (std::size_t i = 0; i < m; ++i) out.push_back(frames[i].with_handles(x[2 * i], x[2 * i + 1]));
      return out;
    }
    if (step == projection_steps || e.h.size() == 0) break;
    const Eigen::VectorXd dx = -e.grad.transpose() * (e.grad * e.grad.transpose()).colPivHouseholderQr().solve(e.h);
    if (!dx.allFinite() || !admissible(frames, x + dx)) break;
    x += dx;
  }
  return std::nullopt;
}

}  // namespace gf
