#include "fair/initial_tangents.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

namespace gf {

namespace {

constexpr double wedge_margin = 0.1;     // of a junction's wedge between its chords, kept clear at either side
constexpr double bisector_weight = 0.01;  // only decides where the balance alone does not (an even closed chain)

double near(double angle, double reference) {
  return reference + wrapped_angle(angle - reference);
}

}  // namespace

std::vector<double> balanced_tangents(const std::vector<Vec2>& points, bool closed, std::optional<double> start_angle,
                                      std::optional<double> end_angle, bool zero_curvature_start,
                                      bool zero_curvature_end) {
  const std::size_t n = points.size(), m = closed ? n : n - 1;
  // Chord directions, unwrapped along the chain; `total` continues them past a closed seam.
  std::vector<double> c(m);
  for (std::size_t i = 0; i < m; ++i) {
    const Vec2 d = points[(i + 1) % n] - points[i];
    const double a = angle_of(d);
    c[i] = i == 0 ? a : near(a, c[i - 1]);
  }
  const double total = closed ? near(c[0], c[m - 1]) - c[0] : 0.0;  // ≈ ±2π for a closed chain
  // φ_j ≈ the bisector (c_{j−1} + c_j)/2; unknowns: every φ of a closed chain, the interior ones of an open chain.
  std::vector<double> bisector(n);
  for (std::size_t j = 0; j < n; ++j) {
    if (!closed && j == 0) bisector[j] = c[0];
    else if (!closed && j + 1 == n) bisector[j] = c[m - 1];
    else if (j == 0) bisector[j] = 0.5 * (c[m - 1] - total + c[0]);
    else bisector[j] = 0.5 * (c[j - 1] + c[j]);
  }
  std::vector<double> phi = bisector;
  if (!closed) {
    if (start_angle) phi[0] = near(*start_angle, c[0]);
    if (end_angle) phi[n - 1] = near(*end_angle, c[m - 1]);
  }
  const std::size_t first = closed ? 0 : 1, unknowns = closed ? n : n - 2;
  if (unknowns == 0) return phi;
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(m + unknowns), static_cast<Eigen::Index>(unknowns));
  Eigen::VectorXd b = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(m + unknowns));
  auto column = [&](std::size_t j) -> std::optional<Eigen::Index> {
    if (j < first || j >= first + unknowns) return std::nullopt;
    return static_cast<Eigen::Index>(j - first);
  };
  for (std::size_t i = 0; i < m; ++i) {
    const auto row = static_cast<Eigen::Index>(i);
    const std::size_t j0 = i, j1 = (i + 1) % n;
    const double shift = closed && j1 == 0 ? total : 0.0;  // φ at the end of the seam segment
    // (φ_{i+1} − c_i) = −r (φ_i − c_i): r = 1 balanced, r = 2 from a κ = 0 start, ½ towards a κ = 0 end.
    const bool zero_here_start = !closed && i == 0 && zero_curvature_start;
    const bool zero_here_end = !closed && i + 1 == m && zero_curvature_end;
    const double w0 = zero_here_start ? 2.0 : 1.0, w1 = zero_here_end && !zero_here_start ? 2.0 : 1.0;
    double rhs = (w0 + w1) * c[i] - w1 * shift;
    if (const auto k = column(j0)) A(row, *k) += w0;
    else rhs -= w0 * phi[j0];
    if (const auto k = column(j1)) A(row, *k) += w1;
    else rhs -= w1 * phi[j1];
    b(row) = rhs;
  }
  for (std::size_t k = 0; k < unknowns; ++k) {
    const auto row = static_cast<Eigen::Index>(m + k);
    A(row, static_cast<Eigen::Index>(k)) = bisector_weight;
    b(row) = bisector_weight * bisector[first + k];
  }
  const Eigen::VectorXd x = A.colPivHouseholderQr().solve(b);
  for (std::size_t k = 0; k < unknowns; ++k) phi[first + k] = x(static_cast<Eigen::Index>(k));
  return phi;
}

void keep_tangents_between_chords(const std::vector<Vec2>& points, bool closed, double way,
                                  std::vector<double>& angles, bool zero_curvature_start, bool zero_curvature_end) {
  const std::size_t n = points.size();
  if (n < 3) return;
  for (std::size_t j = 0; j < n; ++j) {
    if (!closed && (j == 0 || j + 1 == n || (j == 1 && zero_curvature_start) || (j + 2 == n && zero_curvature_end)))
      continue;
    const Vec2 before = points[j] - points[(j + n - 1) % n], after = points[(j + 1) % n] - points[j];
    const double chord = angle_of(before), wedge = wrapped_angle(angle_of(after) - chord);
    if (wedge * way <= 0.0) continue;
    const double lo = std::min(wedge_margin * wedge, (1.0 - wedge_margin) * wedge);
    const double hi = std::max(wedge_margin * wedge, (1.0 - wedge_margin) * wedge);
    const double off = wrapped_angle(angles[j] - chord);
    angles[j] += std::clamp(off, lo, hi) - off;
  }
}

}  // namespace gf
