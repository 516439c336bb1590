#include "geom/g2_handle_fit.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <Eigen/Dense>

#include "geom/foot_point.hpp"

namespace gf {

namespace {

constexpr int max_rounds = 40;
constexpr int max_rounds_stepped = 200;  // where each round's step is capped (G2FitFreedom::step_share)
constexpr int projection_steps = 12;
constexpr int newton_steps = 2;         // of each point's foot on its cubic, a round
constexpr int whole_offset_rounds = 4;  // first rounds fitting each point's whole offset from its foot
constexpr double settled = 1e-9;        // a round moving the handles less (of the chord sum) ends the rounds
constexpr double matched = 1e-9;        // κ continuous to this share of the larger side
constexpr double longest_handle = 1.5;  // of the chord
constexpr double shortest_handle = 1e-3;

// The unknowns x: a and b of each cubic, then the slides of the nodes that slide (node i
// starts cubic i).
struct Unknowns {
  std::span<const CubicFrame> frames;
  bool closed = false;
  std::vector<int> slide_index;  // per node: where its slide sits among the slides, or −1
  int slides = 0;
  Unknowns(std::span<const CubicFrame> f, const G2FitFreedom& freedom)
      : frames(f), closed(freedom.closed), slide_index(closed ? f.size() : f.size() + 1, -1) {
    for (std::size_t i = 0; i < slide_index.size() && i < freedom.slides.size(); ++i)
      if (freedom.slides[i]) slide_index[i] = slides++;
  }
  int handles() const { return 2 * static_cast<int>(frames.size()); }
  int size() const { return handles() + slides; }
  std::size_t end_node(std::size_t i) const { return closed ? (i + 1) % frames.size() : i + 1; }
  // Column of node `node`'s slide, or −1.
  int slide_column(std::size_t node) const {
    return slide_index[node] < 0 ? -1 : handles() + slide_index[node];
  }
  double slide(const Eigen::VectorXd& x, std::size_t node) const {
    const int c = slide_column(node);
    return c < 0 ? 0.0 : x[c];
  }
  // Cubic i's frame with its nodes slid.
  CubicFrame frame(const Eigen::VectorXd& x, std::size_t i) const {
    CubicFrame f = frames[i];
    f.start = f.start + f.start_tangent * slide(x, i), f.end = f.end + f.end_tangent * slide(x, end_node(i));
    return f;
  }
  Cubic cubic(const Eigen::VectorXd& x, std::size_t i) const { return frame(x, i).with_handles(x[2 * i], x[2 * i + 1]); }
};

// The curvature equations h(x) = 0 and their gradients.
struct CurvatureEquations {
  Eigen::VectorXd h;
  Eigen::MatrixXd grad;
  double largest_relative = 0.0;  // max |h| over the larger side's |κ| (or 1/the chord sum)
};

CurvatureEquations curvature_equations(const Unknowns& u, const Eigen::VectorXd& x, std::optional<double> start,
                                       std::optional<double> end, double chord_sum) {
  const std::size_t m = u.frames.size();
  if (u.closed) start = end = std::nullopt;
  const int rows = static_cast<int>(u.closed ? m : m - 1) + (start ? 1 : 0) + (end ? 1 : 0);
  CurvatureEquations e{Eigen::VectorXd::Zero(rows), Eigen::MatrixXd::Zero(rows, u.size())};
  int r = 0;
  const auto record = [&](double left, double right) {
    e.h[r] = left - right;
    e.largest_relative = std::max(e.largest_relative,
                                  std::abs(left - right) / std::max({std::abs(left), std::abs(right), 1.0 / chord_sum}));
  };
  const auto add_slide = [&](std::size_t node, double g) {
    if (const int c = u.slide_column(node); c >= 0) e.grad(r, c) += g;
  };
  // ∂κ0/∂a = −2κ0/a, ∂κ0/∂b = −2/3·c/a²; ∂κ3/∂b = −2κ3/b, ∂κ3/∂a = −2/3·c/b². A slide s
  // moves D = P3 − P0 along its node's tangent: T0 × D gains s_end·c, D × T3 loses s_start·c.
  const auto start_row = [&](std::size_t i, double sign) {
    const CubicFrame f = u.frame(x, i);
    const double a = x[2 * i], b = x[2 * i + 1], c = cross(f.start_tangent, f.end_tangent);
    const double k = f.start_curvature(a, b);
    e.grad(r, 2 * i) += sign * -2.0 * k / a, e.grad(r, 2 * i + 1) += sign * (-2.0 / 3.0) * c / (a * a);
    add_slide(u.end_node(i), sign * (2.0 / 3.0) * c / (a * a));
    return k;
  };
  const auto end_row = [&](std::size_t i, double sign) {
    const CubicFrame f = u.frame(x, i);
    const double a = x[2 * i], b = x[2 * i + 1], c = cross(f.start_tangent, f.end_tangent);
    const double k = f.end_curvature(a, b);
    e.grad(r, 2 * i + 1) += sign * -2.0 * k / b, e.grad(r, 2 * i) += sign * (-2.0 / 3.0) * c / (b * b);
    add_slide(i, sign * (-2.0 / 3.0) * c / (b * b));
    return k;
  };
  if (start) record(start_row(0, 1.0), *start), ++r;
  for (std::size_t i = 1; i < m; ++i) {
    const double left = end_row(i - 1, 1.0);
    record(left, start_row(i, -1.0)), ++r;
  }
  if (u.closed) {
    const double left = end_row(m - 1, 1.0);
    record(left, start_row(0, -1.0)), ++r;
  }
  if (end) record(end_row(m - 1, 1.0), *end), ++r;
  return e;
}

bool admissible(const Unknowns& u, const Eigen::VectorXd& x, double slide_reach) {
  for (std::size_t i = 0; i < u.frames.size(); ++i) {
    const double chord = distance(u.frames[i].start, u.frames[i].end);
    for (const double h : {x[2 * i], x[2 * i + 1]})
      if (!(h > shortest_handle * chord && h <= longest_handle * chord)) return false;
  }
  for (int c = u.handles(); c < u.size(); ++c)
    if (!(std::abs(x[c]) <= slide_reach)) return false;
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
                                                 std::optional<double> end, const G2FitFreedom& freedom) {
  const std::size_t m = frames.size();
  if (m == 0 || points.size() != m || initial.size() != m) return std::nullopt;
  const Unknowns unknowns(frames, freedom);
  const int n = unknowns.size();
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
  double chord_sum = 0.0;
  std::vector<std::vector<double>> feet(m);
  for (std::size_t i = 0; i < m; ++i) {
    x[2 * i] = initial[i].first, x[2 * i + 1] = initial[i].second;
    chord_sum += distance(frames[i].start, frames[i].end);
    feet[i] = chord_length_parameters(points[i]);
  }
  if (!(chord_sum > 0.0) || !admissible(unknowns, x, freedom.slide_reach)) return std::nullopt;

  const int rounds = freedom.step_share > 0.0 ? max_rounds_stepped : max_rounds;
  for (int round = 0; round < rounds; ++round) {
    // A point at parameter u is P0 (B0 + B1) + P3 (B2 + B3) + a B1 T0 − b B2 T3, linear in
    // (a, b), and in the slides s0, s3 of its nodes (P0 + s0 T0, P3 + s3 T3): its offset from
    // each point at the point's foot, then only the part across the curve (tangent distance
    // minimisation, as geom/tangent_fit).
    Eigen::MatrixXd normal = Eigen::MatrixXd::Zero(n, n);
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n);
    for (std::size_t i = 0; i < m; ++i) {
      const CubicFrame& f = frames[i];
      const Cubic c = unknowns.cubic(x, i);
      const Quad velocity = c.hodograph();
      const std::array<int, 4> columns{2 * static_cast<int>(i), 2 * static_cast<int>(i) + 1, unknowns.slide_column(i),
                                       unknowns.slide_column(unknowns.end_node(i))};
      for (std::size_t k = 0; k < points[i].size(); ++k) {
        // A sliding node's own point binds nothing: the node goes where the rest put it.
        if ((k == 0 && columns[2] >= 0) || (k + 1 == points[i].size() && columns[3] >= 0)) continue;
        double& u = feet[i][k];
        for (int step = 0; step < newton_steps && k > 0 && k + 1 < points[i].size(); ++step) {
          const FootStep s = foot_step(c, points[i][k], u);
          if (!(s.slope > 0.0)) break;
          u = std::clamp(u - s.along / s.slope, 0.0, 1.0);
        }
        const double v = 1.0 - u, b0 = v * v * v, b1 = 3.0 * v * v * u, b2 = 3.0 * v * u * u, b3 = u * u * u;
        const std::array<Vec2, 4> along{f.start_tangent * b1, f.end_tangent * -b2, f.start_tangent * (b0 + b1),
                                        f.end_tangent * (b2 + b3)};
        const Vec2 rest = points[i][k] - (f.start * (b0 + b1) + f.end * (b2 + b3));
        const auto add = [&](Vec2 across) {
          for (std::size_t p = 0; p < columns.size(); ++p) {
            if (columns[p] < 0) continue;
            const double qp = dot(along[p], across);
            rhs[columns[p]] += qp * dot(rest, across);
            for (std::size_t q = 0; q < columns.size(); ++q)
              if (columns[q] >= 0) normal(columns[p], columns[q]) += qp * dot(along[q], across);
          }
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
    // A little pull towards the unknowns as they are, so a frame its points do not determine
    // keeps them.
    const double ridge = 1e-9 * std::max(normal.diagonal().maxCoeff(), 1.0);
    normal.diagonal().array() += ridge;
    rhs += ridge * x;
    const CurvatureEquations e = curvature_equations(unknowns, x, start, end, chord_sum);
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
    // The full step, or the capped one; halved while it would leave the admissible handles.
    const double full = freedom.step_share > 0.0
                            ? std::min(1.0, freedom.step_share * chord_sum / static_cast<double>(m) /
                                                std::max(step.cwiseAbs().maxCoeff(), std::numeric_limits<double>::min()))
                            : 1.0;
    double damping = full;
    while (damping > 1e-4 * full && !admissible(unknowns, x + damping * step, freedom.slide_reach)) damping *= 0.5;
    if (damping <= 1e-4 * full) break;
    x += damping * step;
    if (damping * step.cwiseAbs().maxCoeff() < settled * chord_sum) break;
  }
  // The rounds' last linearisation leaves the curvature equations met to first order: the
  // least-norm Newton steps onto them.
  for (int step = 0; step <= projection_steps; ++step) {
    const CurvatureEquations e = curvature_equations(unknowns, x, start, end, chord_sum);
    if (e.largest_relative <= matched) {
      std::vector<Cubic> out;
      for (std::size_t i = 0; i < m; ++i) out.push_back(unknowns.cubic(x, i));
      return out;
    }
    if (step == projection_steps || e.h.size() == 0) break;
    const Eigen::VectorXd dx = -e.grad.transpose() * (e.grad * e.grad.transpose()).colPivHouseholderQr().solve(e.h);
    if (!dx.allFinite() || !admissible(unknowns, x + dx, freedom.slide_reach)) break;
    x += dx;
  }
  return std::nullopt;
}

}  // namespace gf
