#include "geom/smoothing_spline.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include "geom/bspline_basis.hpp"

namespace gf {

namespace {

constexpr double least_reach_share = 0.25;  // of a held control's even reach, below which it is set there

// A control point as origin + Σ z[var] · direction: free (x and y), held to a line through an
// end point (one unknown along the end tangent), or fixed (an interpolated end).
struct Control {
  Vec2 origin{};
  int var = -1;
  int unknowns = 0;
  Vec2 direction{};
  template <class F>
  void for_each_unknown(F&& f) const {
    if (unknowns == 2) f(var, Vec2{1.0, 0.0}), f(var + 1, Vec2{0.0, 1.0});
    else if (unknowns == 1) f(var, direction);
  }
};

// Normal equations of Σ scale·|Σ_k w_k c_k − target|² in the unknowns.
struct Normal {
  Eigen::MatrixXd h;
  Eigen::VectorXd g;
  explicit Normal(int n) : h(Eigen::MatrixXd::Zero(n, n)), g(Eigen::VectorXd::Zero(n)) {}
  void add(const std::vector<Control>& controls, std::span<const int> index, std::span<const double> w, Vec2 target) {
    Vec2 rest = target;
    for (std::size_t k = 0; k < index.size(); ++k) rest -= controls[index[k]].origin * w[k];
    for (std::size_t k = 0; k < index.size(); ++k)
      controls[index[k]].for_each_unknown([&](int a, Vec2 va) {
        g[a] += w[k] * dot(va, rest);
        for (std::size_t l = 0; l < index.size(); ++l)
          controls[index[l]].for_each_unknown([&](int b, Vec2 vb) { h(a, b) += w[k] * w[l] * dot(va, vb); });
      });
  }
};

class SmoothingProblem {
 public:
  SmoothingProblem(std::span<const Vec2> points, int spans, bool closed, const SmoothingEnds& ends)
      : points_(points), basis_(spans, closed) {
    const int n = basis_.control_count();
    controls_.resize(static_cast<std::size_t>(n));
    int unknowns = 0;
    for (int j = 0; j < n; ++j) {
      Control& c = controls_[static_cast<std::size_t>(j)];
      if (!closed && (j == 0 || j == n - 1)) {
        c.origin = j == 0 ? points.front() : points.back();
        continue;
      }
      const bool start_held = !closed && j == 1 && ends.start_tangent && norm(*ends.start_tangent) > 0.0;
      const bool end_held = !closed && j == n - 2 && ends.end_tangent && norm(*ends.end_tangent) > 0.0;
      if (start_held || end_held) {
        const Vec2 t = start_held ? *ends.start_tangent : -*ends.end_tangent;
        c.origin = start_held ? points.front() : points.back();
        c.direction = t / norm(t);
        c.unknowns = 1;
      } else {
        c.unknowns = 2;
      }
      c.var = unknowns;
      unknowns += c.unknowns;
    }
    unknowns_ = unknowns;
    // The penalty: each span's third derivative p3 − 3p2 + 3p1 − p0 of its Bézier form (constant
    // on the span), as weights on the span's four controls. On periodic knots these are the
    // third differences of the controls; the clamped end spans differ.
    std::vector<Vec2> unit(static_cast<std::size_t>(n));
    terms_.resize(static_cast<std::size_t>(spans));
    for (int s = 0; s < spans; ++s) {
      SpanTerm& t = terms_[static_cast<std::size_t>(s)];
      const int first = basis_.at((s + 0.5) / spans).first;
      for (int k = 0; k < 4; ++k) {
        t.index[k] = basis_.control(first + k);
        unit[static_cast<std::size_t>(t.index[k])] = {1.0, 0.0};
        const Cubic c = basis_.span_cubic(unit, s);
        unit[static_cast<std::size_t>(t.index[k])] = {};
        t.w[k] = (c.p[3] - 3.0 * c.p[2] + 3.0 * c.p[1] - c.p[0]).x;
      }
    }
    weigh_spans(std::vector<double>(terms_.size(), 1.0));
    // Chord-length parameters (a closed sequence's closing chord included).
    u_.assign(points.size(), 0.0);
    for (std::size_t i = 1; i < points.size(); ++i) u_[i] = u_[i - 1] + distance(points[i], points[i - 1]);
    const double total = u_.back() + (closed ? distance(points.back(), points.front()) : 0.0);
    for (double& v : u_) v /= total;
    even_reach_ = total / (3.0 * spans);
  }

  /// The penalty with span s weighed by weight[s].
  void weigh_spans(std::span<const double> weight) {
    penalty_ = Normal(unknowns_);
    for (std::size_t s = 0; s < terms_.size(); ++s) {
      double w[4];
      for (int k = 0; k < 4; ++k) w[k] = terms_[s].w[k] * std::sqrt(weight[s]);
      penalty_.add(controls_, terms_[s].index, w, {});
    }
  }

  /// The length of the third derivative on each span of the spline with these controls.
  std::vector<double> third_derivatives(std::span<const Vec2> c) const {
    std::vector<double> out;
    for (const SpanTerm& t : terms_) {
      Vec2 d{};
      for (int k = 0; k < 4; ++k) d += c[static_cast<std::size_t>(t.index[k])] * t.w[k];
      out.push_back(norm(d));
    }
    return out;
  }

  void fit_data() {
    data_ = Normal(unknowns_);
    for (std::size_t i = 0; i < points_.size(); ++i) {
      const BSplineBasis::Weights w = basis_.at(u_[i]);
      const int index[4] = {basis_.control(w.first), basis_.control(w.first + 1), basis_.control(w.first + 2),
                            basis_.control(w.first + 3)};
      data_.add(controls_, index, w.w, points_[i]);
    }
    scale_ = data_.h.trace() / std::max(penalty_.h.trace(), 1e-300);
  }

  /// The controls for λ = 10^e relative to the data's own weight. A control held on an end's
  /// tangent line that would come within a quarter of its reach on an evenly drawn line (a
  /// third of a span's length) of its end point, or behind it, is set at that reach: behind, the
  /// curve leaves its end backwards and hooks round (Because We Build's Y, where a line ends:
  /// the hook became a loop of 0.3 units in the cubics, κ·UPM 600 000), and held at a quarter
  /// of the reach it turned so tightly that rounding folded it (dkg's P).
  std::vector<Vec2> solve(double e) const {
    const double lambda = std::pow(10.0, e) * scale_;
    const Eigen::MatrixXd h = data_.h + lambda * penalty_.h;
    const Eigen::VectorXd g = data_.g + lambda * penalty_.g;
    const Eigen::LDLT<Eigen::MatrixXd> factors = h.ldlt();
    Eigen::VectorXd z = factors.solve(g);
    std::vector<Eigen::Index> held;
    for (const Control& k : controls_)
      if (k.unknowns == 1 && z[k.var] < least_reach_share * even_reach_) held.push_back(k.var);
    if (!held.empty()) {
      // The same least squares with those unknowns at the even reach (Lagrange multipliers):
      // z − H⁻¹E (EᵀH⁻¹E)⁻¹ (Eᵀz − reach), E the columns of the held unknowns.
      const Eigen::Index k = static_cast<Eigen::Index>(held.size());
      Eigen::MatrixXd e = Eigen::MatrixXd::Zero(h.rows(), k);
      for (Eigen::Index i = 0; i < k; ++i) e(held[i], i) = 1.0;
      const Eigen::MatrixXd spread = factors.solve(e);
      Eigen::MatrixXd s(k, k);
      Eigen::VectorXd short_by(k);
      for (Eigen::Index i = 0; i < k; ++i) {
        short_by[i] = z[held[i]] - even_reach_;
        for (Eigen::Index j = 0; j < k; ++j) s(i, j) = spread(held[i], j);
      }
      z -= spread * s.ldlt().solve(short_by);
    }
    std::vector<Vec2> c;
    for (const Control& k : controls_) {
      Vec2 p = k.origin;
      k.for_each_unknown([&](int a, Vec2 v) { p += v * z[a]; });
      c.push_back(p);
    }
    return c;
  }

  std::vector<Cubic> spans(std::span<const Vec2> controls) const { return basis_.span_cubics(controls); }

  /// Each point's foot on the curve (three Newton steps from its parameter) and the largest distance.
  double project(std::span<const Cubic> spans, std::vector<double>& feet) const {
    feet.resize(points_.size());
    double worst = 0.0;
    for (std::size_t i = 0; i < points_.size(); ++i) {
      feet[i] = basis_.foot_parameter(spans, points_[i], u_[i], 3);
      worst = std::max(worst, distance(basis_.point_on_spans(spans, feet[i]), points_[i]));
    }
    return worst;
  }

  void move_parameters(std::vector<double> feet) { u_ = std::move(feet); }

 private:
  std::span<const Vec2> points_;
  BSplineBasis basis_;
  std::vector<Control> controls_;
  struct SpanTerm {
    int index[4];
    double w[4];
  };
  std::vector<SpanTerm> terms_;
  int unknowns_ = 0;
  std::vector<double> u_;
  double even_reach_ = 0.0;  ///< of a control held on an end's tangent line, on an evenly drawn line
  Normal data_{0}, penalty_{0};
  double scale_ = 1.0;
};

// Iteratively reweighted least squares towards Σ|r'''_s|: each span's weight 1/(|r'''_s| + ε),
// ε a tenth of the mean (so a straight stretch does not take all the weight), scaled to a mean
// of 1 so λ keeps its scale.
std::vector<double> sparse_weights(std::span<const double> third) {
  double mean = 0.0;
  for (const double v : third) mean += v;
  mean /= static_cast<double>(third.size());
  std::vector<double> weight;
  double total = 0.0;
  for (const double v : third) total += weight.emplace_back(1.0 / (v + 0.1 * mean + 1e-300));
  for (double& w : weight) w *= static_cast<double>(weight.size()) / total;
  return weight;
}

}  // namespace

BSplineFit fit_smoothing_spline(std::span<const Vec2> points, double tolerance, int span_count, bool closed,
                                const SmoothingEnds& ends, SmoothingPenalty penalty) {
  BSplineFit fit;
  if (closed && points.size() > 1 && points.back() == points.front()) points = points.first(points.size() - 1);
  const int m = static_cast<int>(points.size());
  const int spans = std::min(span_count, m - 3);
  if (spans < (closed ? 4 : 1)) return fit;
  SmoothingProblem problem(points, spans, closed, ends);
  // log10 λ (relative): low smoothing to high; each round narrows around the last choice.
  std::vector<double> feet, best_feet;
  const auto choose = [&](double lo, double hi, int rounds) {
    double chosen = lo;
    for (int round = 0; round < rounds; ++round) {
      problem.fit_data();
      const int steps = round == 0 ? 14 : 8;
      bool any = false;
      for (int k = 0; k < steps; ++k) {
        const double e = 0.5 * (lo + hi);
        const std::vector<Vec2> c = problem.solve(e);
        if (problem.project(problem.spans(c), feet) <= tolerance) lo = e, any = true, best_feet = feet;
        else hi = e;
      }
      chosen = lo;
      if (!any) {
        const std::vector<Vec2> c = problem.solve(lo);
        problem.project(problem.spans(c), best_feet);
      }
      problem.move_parameters(best_feet);
      lo = chosen - 1.5, hi = chosen + 1.5;
    }
    return chosen;
  };
  // The controls at λ = 10^e on the parameters as they are, and the largest distance.
  const auto solve_at = [&](double e) {
    problem.fit_data();
    std::vector<Vec2> c = problem.solve(e);
    const double r = problem.project(problem.spans(c), feet);
    return std::pair{std::move(c), r};
  };
  double chosen = choose(-8.0, 4.0, 3);
  auto [controls, residual] = solve_at(chosen);
  if (penalty == SmoothingPenalty::sparse && residual <= tolerance)
    for (int round = 0; round < 2; ++round) {
      const SmoothingProblem before = problem;
      problem.weigh_spans(sparse_weights(problem.third_derivatives(controls)));
      const double e = choose(chosen - 8.0, chosen + 4.0, 2);
      auto [c, r] = solve_at(e);
      if (r > tolerance) {  // no λ within the tolerance: the round before stands
        problem = before;
        break;
      }
      chosen = e, controls = std::move(c), residual = r;
    }
  fit.spans = problem.spans(controls);
  fit.max_residual = residual;
  return fit;
}

}  // namespace gf
