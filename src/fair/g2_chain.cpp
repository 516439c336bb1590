#include "fair/g2_chain.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

#include "aesthetic/segment_fit.hpp"

namespace gf {

namespace {

// Where Q0 + t·d0 = Q1 − u·d1 with t, u > 0 (the control point in front of both ends).
std::optional<Vec2> tangent_intersection(Vec2 q0, Vec2 d0, Vec2 q1, Vec2 d1) {
  const double det = cross(d0, d1);
  if (std::abs(det) < 1e-14) return std::nullopt;
  const Vec2 r = q1 - q0;
  const double t = cross(r, d1) / det, u = cross(d0, r) / det;
  if (!(t > 0.0 && u > 0.0)) return std::nullopt;
  return q0 + d0 * t;
}

double max_abs(const std::vector<double>& v) {
  double m = 0.0;
  for (const double x : v) m = std::max(m, std::abs(x));
  return m;
}

}  // namespace

ChainSegments build_chain(const LacChain& chain) {
  ChainSegments out;
  const std::size_t n = chain.points.size();
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const Vec2 d0{std::cos(chain.tangent_angles[i]), std::sin(chain.tangent_angles[i])};
    const Vec2 d1{std::cos(chain.tangent_angles[i + 1]), std::sin(chain.tangent_angles[i + 1])};
    const std::optional<Vec2> p1 = tangent_intersection(chain.points[i], d0, chain.points[i + 1], d1);
    if (!p1) {
      out.segments.clear();
      out.reason = "segment " + std::to_string(i) + ": its tangents do not meet in front of both ends";
      return out;
    }
    SegmentFit fit = fit_three_point(chain.points[i], *p1, chain.points[i + 1], chain.alphas[i]);
    if (!fit.ok()) {
      out.segments.clear();
      out.reason = "segment " + std::to_string(i) + ": " + fit.reason;
      return out;
    }
    out.segments.push_back(std::move(*fit.segment));
  }
  return out;
}

std::vector<double> curvature_mismatch(const std::vector<LogAestheticSegment>& segments) {
  std::vector<double> d;
  for (std::size_t j = 1; j < segments.size(); ++j) d.push_back(segments[j - 1].end().curvature - segments[j].start().curvature);
  return d;
}

G2Result make_g2(LacChain chain, double tolerance, int max_iterations) {
  G2Result result;
  ChainSegments built = build_chain(chain);
  if (!built.ok()) {
    result.reason = built.reason;
    result.chain = std::move(chain);
    return result;
  }
  std::vector<double> d = curvature_mismatch(built.segments);
  const int m = static_cast<int>(d.size());  // interior junctions 1 … m
  constexpr double h = 1e-7;
  for (result.iterations = 0; result.iterations < max_iterations && max_abs(d) > tolerance; ++result.iterations) {
    Eigen::MatrixXd jacobian = Eigen::MatrixXd::Zero(m, m);
    for (int c = 0; c < m; ++c) {
      LacChain moved = chain;
      moved.tangent_angles[static_cast<std::size_t>(c) + 1] += h;
      const ChainSegments probe = build_chain(moved);
      if (!probe.ok()) {
        result.reason = "junction " + std::to_string(c + 1) + " sits at the edge of its feasible range";
        break;
      }
      const std::vector<double> dp = curvature_mismatch(probe.segments);
      // D_j depends on φ_{j−1}, φ_j, φ_{j+1} only: a tridiagonal Jacobian.
      for (int r = std::max(0, c - 1); r <= std::min(m - 1, c + 1); ++r) jacobian(r, c) = (dp[r] - d[r]) / h;
    }
    if (!result.reason.empty()) break;
    const Eigen::VectorXd step = jacobian.fullPivLu().solve(-Eigen::Map<const Eigen::VectorXd>(d.data(), m));
    bool improved = false;
    for (double lambda = 1.0; lambda > 1e-6; lambda *= 0.5) {
      LacChain trial = chain;
      for (int j = 0; j < m; ++j) trial.tangent_angles[static_cast<std::size_t>(j) + 1] += lambda * step(j);
      ChainSegments attempt = build_chain(trial);
      if (!attempt.ok()) continue;
      const std::vector<double> dt = curvature_mismatch(attempt.segments);
      if (max_abs(dt) < max_abs(d)) {
        chain = std::move(trial);
        built = std::move(attempt);
        d = dt;
        improved = true;
        break;
      }
    }
    if (!improved) {
      result.reason = "the line search found no better feasible angles";
      break;
    }
  }
  result.max_mismatch = max_abs(d);
  result.converged = result.max_mismatch <= tolerance;
  if (!result.converged && result.reason.empty()) result.reason = "no convergence in " + std::to_string(max_iterations) + " iterations";
  result.chain = std::move(chain);
  result.segments = std::move(built.segments);
  return result;
}

}  // namespace gf
