#include "geom/smoothing_spline.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include "geom/bspline_basis.hpp"
#include "geom/curvature.hpp"

namespace gf {

namespace {

constexpr double least_reach_share = 0.25;  // of a held control's even reach, below which it is set there
// log10 of the most smoothing, relative to the data's weight: past it the spline is its
// penalty's own shape to the last digit, and the normal equations lose the data (on a run
// shorter than its tolerance the sparse rounds climbed to 10¹⁷, and the solve put the inner
// controls at the origin: Because We Create's q).
constexpr double most_log_lambda = 8.0;
// Merging a lobe: the bends are held by a penalty this many times the data's mean weight (soft,
// so that rows which depend on each other, as three along one span's linear r'' do, stay
// solvable; 10³ left a third of a merged lobe's turning), λ may fall by up to 10^1.5, rows are
// added for up to six rounds, and the spline may end 5 % past the tolerance (as guides are
// accepted, fair/run_fairing).
constexpr double bend_weight = 1e4;
constexpr double merge_lambda_range = 1.5;
constexpr int merge_rounds = 6;
constexpr double merge_slack = 1.05;

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

// Normal equations of Σ scale·|Σ_k w_k c_k − target|² in the unknowns. Each row touches the
// four controls of one span, so h is banded (but for a closed spline's wrap) and kept sparse,
// set from the rows' entries once all are added (`finish`): dense, a guide of 320 spans cost
// whole DejaVu Sans a tenth more time in its solves.
struct Normal {
  Eigen::SparseMatrix<double> h;
  Eigen::VectorXd g;
  std::vector<Eigen::Triplet<double>> entries;
  explicit Normal(int n) : h(n, n), g(Eigen::VectorXd::Zero(n)) {}
  void add(const std::vector<Control>& controls, std::span<const int> index, std::span<const double> w, Vec2 target) {
    Vec2 rest = target;
    for (std::size_t k = 0; k < index.size(); ++k) rest -= controls[index[k]].origin * w[k];
    for (std::size_t k = 0; k < index.size(); ++k)
      controls[index[k]].for_each_unknown([&](int a, Vec2 va) {
        g[a] += w[k] * dot(va, rest);
        for (std::size_t l = 0; l < index.size(); ++l)
          controls[index[l]].for_each_unknown(
              [&](int b, Vec2 vb) { entries.emplace_back(a, b, w[k] * w[l] * dot(va, vb)); });
      });
  }
  void finish() {
    h.setFromTriplets(entries.begin(), entries.end());
    entries = {};
  }
  double trace() const { return h.diagonal().sum(); }
};

// The sparse LDLT of the normal equations, with its fill-reducing ordering (AMD) kept while
// the pattern stays: the search on λ changes only the values, and ordering anew took most of
// the factorisations' time (3.5 % of whole DejaVu Sans's). A factorisation on a kept analysis is
// what compute() gives, bit for bit.
class PatternedLdlt {
 public:
  using Factor = Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>;
  PatternedLdlt() = default;
  PatternedLdlt(const PatternedLdlt&) {}  // a copy starts with nothing analysed
  PatternedLdlt& operator=(const PatternedLdlt&) {
    outer_.clear(), inner_.clear();
    return *this;
  }
  const Factor& factorize(const Eigen::SparseMatrix<double>& h) {
    if (!same_pattern(h)) {
      factor_.analyzePattern(h);
      outer_.assign(h.outerIndexPtr(), h.outerIndexPtr() + h.outerSize() + 1);
      inner_.assign(h.innerIndexPtr(), h.innerIndexPtr() + h.nonZeros());
    }
    factor_.factorize(h);
    return factor_;
  }

 private:
  bool same_pattern(const Eigen::SparseMatrix<double>& h) const {
    return h.isCompressed() && static_cast<std::size_t>(h.outerSize()) + 1 == outer_.size() &&
           static_cast<std::size_t>(h.nonZeros()) == inner_.size() &&
           std::equal(outer_.begin(), outer_.end(), h.outerIndexPtr()) &&
           std::equal(inner_.begin(), inner_.end(), h.innerIndexPtr());
  }
  Factor factor_;
  std::vector<int> outer_, inner_;  ///< the pattern analysed, empty before the first
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
      // Held on an end's tangent line: the control next to the end, and the one after it where
      // the end is straight.
      const bool straight = ends.straight_ends && n >= 6;
      const bool start_held = !closed && (j == 1 || (straight && j == 2)) && ends.start_tangent &&
                              norm(*ends.start_tangent) > 0.0;
      const bool end_held = !closed && (j == n - 2 || (straight && j == n - 3)) && ends.end_tangent &&
                            norm(*ends.end_tangent) > 0.0;
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
        t.bend_start[k] = (c.p[2] - 2.0 * c.p[1] + c.p[0]).x;
        t.bend_end[k] = (c.p[3] - 2.0 * c.p[2] + c.p[1]).x;
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
    penalty_.finish();
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
    data_.finish();
    scale_ = data_.trace() / std::max(penalty_.trace(), 1e-300);
  }

  /// The controls for λ = 10^e relative to the data's own weight. A control held on an end's
  /// tangent line that would come within a quarter of its reach on an evenly drawn line (a
  /// third of a span's length) of its end point, or behind it, is set at that reach: behind, the
  /// curve leaves its end backwards and hooks round (Because We Build's Y, where a line ends:
  /// the hook became a loop of 0.3 units in the cubics, κ·UPM 600 000), and held at a quarter
  /// of the reach it turned so tightly that rounding folded it (dkg's P).
  std::vector<Vec2> solve(double e) const {
    const double lambda = std::pow(10.0, e) * scale_;
    Eigen::SparseMatrix<double> h = data_.h + lambda * penalty_.h;
    Eigen::VectorXd g = data_.g + lambda * penalty_.g;
    if (held_bends_) {
      const double weight = bend_weight * data_.trace() / std::max(unknowns_, 1);
      h += weight * bends_.h;
      g += weight * bends_.g;
    }
    // Positive definite wherever the points cover every span; should the factorisation still
    // fail, the dense LDLT, which pivots.
    const PatternedLdlt::Factor& sparse = ldlt_.factorize(h);
    std::optional<Eigen::LDLT<Eigen::MatrixXd>> dense;
    if (sparse.info() != Eigen::Success) dense.emplace(Eigen::MatrixXd(h));
    const auto solve_h = [&](const Eigen::MatrixXd& rhs) -> Eigen::MatrixXd {
      return dense ? Eigen::MatrixXd(dense->solve(rhs)) : Eigen::MatrixXd(sparse.solve(rhs));
    };
    Eigen::VectorXd z = solve_h(g);
    std::vector<Eigen::Index> held;
    for (const Control& k : controls_)
      if (k.unknowns == 1 && z[k.var] < least_reach_share * even_reach_) held.push_back(k.var);
    if (!held.empty()) {
      // The same least squares with those unknowns at the even reach (Lagrange multipliers):
      // z − H⁻¹E (EᵀH⁻¹E)⁻¹ (Eᵀz − reach), E the columns of the held unknowns.
      const Eigen::Index k = static_cast<Eigen::Index>(held.size());
      Eigen::MatrixXd e = Eigen::MatrixXd::Zero(h.rows(), k);
      for (Eigen::Index i = 0; i < k; ++i) e(held[i], i) = 1.0;
      const Eigen::MatrixXd spread = solve_h(e);
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

  /// r''(t) on one span across `normal` (the bend, κ·|r'|²) held at `target`.
  struct BendRow {
    int index[4];
    double w[4];
    Vec2 normal;
    double target;
  };
  BendRow bend_row(int span, double t, Vec2 normal, double target) const {
    BendRow row{{}, {}, normal, target};
    const SpanTerm& term = terms_[static_cast<std::size_t>(span)];
    for (int k = 0; k < 4; ++k) {
      row.index[k] = term.index[k];
      row.w[k] = 6.0 * ((1.0 - t) * term.bend_start[k] + t * term.bend_end[k]);
    }
    return row;
  }
  /// Every later solve holds these bends (each row scaled to unit length in the unknowns).
  void hold_bends(std::span<const BendRow> rows) {
    bends_ = Normal(unknowns_);
    for (const BendRow& row : rows) {
      std::vector<std::pair<int, double>> a;
      double fixed = 0.0, length = 0.0;
      for (int k = 0; k < 4; ++k) {
        const Control& c = controls_[static_cast<std::size_t>(row.index[k])];
        fixed += row.w[k] * dot(c.origin, row.normal);
        c.for_each_unknown([&](int v, Vec2 dir) { a.emplace_back(v, row.w[k] * dot(dir, row.normal)); });
      }
      for (const auto& [v, x] : a) length += x * x;
      if (length <= 0.0) continue;
      for (const auto& [v, x] : a) {
        bends_.g[v] += x * (row.target - fixed) / length;
        for (const auto& [u, y] : a) bends_.entries.emplace_back(v, u, x * y / length);
      }
    }
    bends_.finish();
    held_bends_ = !rows.empty();
  }

 private:
  std::span<const Vec2> points_;
  BSplineBasis basis_;
  std::vector<Control> controls_;
  // A span's four controls and their weights in its third derivative (constant on the span)
  // and in its second derivative over 6 at its ends (linear between them), in Bézier form.
  struct SpanTerm {
    int index[4];
    double w[4];
    double bend_start[4], bend_end[4];
  };
  std::vector<SpanTerm> terms_;
  int unknowns_ = 0;
  std::vector<double> u_;
  double even_reach_ = 0.0;  ///< of a control held on an end's tangent line, on an evenly drawn line
  Normal data_{0}, penalty_{0}, bends_{0};
  bool held_bends_ = false;
  double scale_ = 1.0;
  mutable PatternedLdlt ldlt_;  // a cache: solve() is const in what it answers
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

// The largest λ = 10^e, e in [lo, min(hi, most_log_lambda)], that keeps every point within the
// tolerance, by bisection on e; each round moves the points' parameters to their feet on the
// curve and narrows around the last choice. Returns e (lo when none does).
double choose_lambda(SmoothingProblem& problem, double tolerance, double lo, double hi, int rounds) {
  std::vector<double> feet, best_feet;
  hi = std::min(hi, most_log_lambda);
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
    lo = chosen - 1.5, hi = std::min(chosen + 1.5, most_log_lambda);
  }
  return chosen;
}

// A fit: its controls, λ = 10^e, and the largest distance of a point from it.
struct Fitted {
  std::vector<Vec2> controls;
  double e = 0.0;
  double residual = 0.0;
};

// The controls at λ = 10^e on the parameters as they are.
Fitted solve_at(SmoothingProblem& problem, double e) {
  problem.fit_data();
  Fitted f{problem.solve(e), e, 0.0};
  std::vector<double> feet;
  f.residual = problem.project(problem.spans(f.controls), feet);
  return f;
}

// A stretch of the spline where κ keeps one sign: [u0, u1] in its parameter (u0 < 0 where a
// closed spline's lobe runs across the seam), how far it turns, and the sign.
struct Lobe {
  double u0, u1;
  double turning;
  int sign;
};

std::vector<Lobe> lobes_of(std::span<const Cubic> spans, bool closed) {
  constexpr int per_span = 8;
  const double n = static_cast<double>(spans.size());
  std::vector<Lobe> out;
  Vec2 last{};
  for (std::size_t j = 0; j < spans.size(); ++j)
    for (int i = 0; i <= per_span; ++i) {
      if (i == per_span && (closed || j + 1 < spans.size())) break;
      const double t = static_cast<double>(i) / per_span;
      const Derivatives d = derivatives_at(spans[j], t);
      const double u = (static_cast<double>(j) + t) / n, ds = out.empty() ? 0.0 : distance(d.point, last);
      last = d.point;
      const std::optional<double> k = curvature(d);
      if (!k) continue;
      const int sign = *k > 0.0 ? 1 : (*k < 0.0 ? -1 : 0);
      if (!out.empty() && (sign == 0 || out.back().sign == sign)) {
        out.back().u1 = u, out.back().turning += *k * ds;
        continue;
      }
      if (sign != 0) out.push_back({u, u, *k * ds, sign});
    }
  if (closed && out.size() > 1 && out.front().sign == out.back().sign) {
    out.front().u0 = out.back().u0 - 1.0;
    out.front().turning += out.back().turning;
    out.pop_back();
  }
  return out;
}

// Lobes turning less than `merging.least_turning`, smallest first, each merged into its
// neighbours while that keeps the spline within the tolerance (and 5 %) and leaves it fewer
// lobes: every half-span point is held to bend the way its lobe now does (at least
// least_curvature), except within three quarters of a span of a sign change that stays, by an
// active set (the points that bend the wrong way are held, the spline fitted again, for a few
// rounds), with λ free to fall a little.
void merge_small_lobes(SmoothingProblem& problem, Fitted& fit, double tolerance, int spans, bool closed,
                       const LobeMerging& merging) {
  const std::vector<Lobe> lobes = lobes_of(problem.spans(fit.controls), closed);
  const std::size_t count = lobes.size();
  if (count < 2) return;
  std::vector<int> sign(count);
  for (std::size_t i = 0; i < count; ++i) sign[i] = lobes[i].sign;
  // u in [first lobe's u0, + 1) on a closed spline.
  const auto unwrap = [&](double u) {
    if (closed && u < lobes[0].u0) return u + 1.0;
    if (closed && u >= lobes[0].u0 + 1.0) return u - 1.0;
    return u;
  };
  // The half-span points and the lobe each lies in.
  struct Point {
    int span;
    double t, u;
    std::size_t lobe;
  };
  std::vector<Point> points;
  for (int j = 0; j < spans; ++j)
    for (const double t : {0.0, 0.5}) {
      const double u = unwrap((j + t) / spans);
      std::size_t i = 0;
      while (i + 1 < count && u >= lobes[i + 1].u0) ++i;
      points.push_back({j, t, u, i});
    }
  std::size_t lobes_now = count;
  const auto attempt = [&] {
    std::vector<double> kept;  // the sign changes that stay
    for (std::size_t i = 0; i + 1 < count || (closed && i < count); ++i) {
      const std::size_t k = (i + 1) % count;
      if (sign[i] != sign[k]) kept.push_back(0.5 * (lobes[i].u1 + lobes[k].u0 + (k == 0 ? 1.0 : 0.0)));
    }
    const double margin = 0.75 / spans;
    const auto near_kept = [&](const Point& p) {
      return std::any_of(kept.begin(), kept.end(), [&](double v) {
        const double d = std::abs(p.u - v);
        return std::min(d, closed ? std::abs(1.0 - d) : d) < margin;
      });
    };
    const SmoothingProblem before = problem;
    std::vector<SmoothingProblem::BendRow> rows;
    // Held already, or left free next to a sign change that stays.
    std::vector<bool> settled(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) settled[i] = near_kept(points[i]);
    Fitted f = fit;
    for (int round = 0; round < merge_rounds; ++round) {
      const std::vector<Cubic> now = problem.spans(f.controls);
      const std::size_t before_rows = rows.size();
      for (std::size_t i = 0; i < points.size(); ++i) {
        if (settled[i]) continue;
        const Point& p = points[i];
        const int way = sign[p.lobe];
        const Derivatives d = derivatives_at(now[static_cast<std::size_t>(p.span)], p.t);
        const double speed = norm(d.d1);
        if (speed <= 0.0) continue;
        const Vec2 normal = perpendicular(d.d1 / speed);
        const double least = way * merging.least_curvature * speed * speed;
        if (way * (dot(d.d2, normal) - least) >= 0.0) continue;
        rows.push_back(problem.bend_row(p.span, p.t, normal, least));
        settled[i] = true;
      }
      if (rows.size() == before_rows) break;
      problem.hold_bends(rows);
      f = solve_at(problem, choose_lambda(problem, tolerance, f.e - merge_lambda_range, f.e, 2));
      if (f.residual > merge_slack * tolerance) break;
    }
    const std::size_t after = lobes_of(problem.spans(f.controls), closed).size();
    if (f.residual <= merge_slack * tolerance && after < lobes_now) {
      fit = std::move(f), lobes_now = after;
      return true;
    }
    problem = before;
    return false;
  };
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < count; ++i)
    if (std::abs(lobes[i].turning) < merging.least_turning) order.push_back(i);
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return std::abs(lobes[a].turning) < std::abs(lobes[b].turning); });
  for (const std::size_t i : order) {
    sign[i] = -sign[i];
    if (!attempt()) sign[i] = -sign[i];
  }
}

}  // namespace

BSplineFit fit_smoothing_spline(std::span<const Vec2> points, double tolerance, int span_count, bool closed,
                                const SmoothingEnds& ends, SmoothingPenalty penalty, const LobeMerging& merging) {
  BSplineFit fit;
  if (closed && points.size() > 1 && points.back() == points.front()) points = points.first(points.size() - 1);
  const int m = static_cast<int>(points.size());
  const int spans = std::min(span_count, m - 3);
  if (spans < (closed ? 4 : 1)) return fit;
  SmoothingProblem problem(points, spans, closed, ends);
  // log10 λ (relative): low smoothing to high.
  Fitted best = solve_at(problem, choose_lambda(problem, tolerance, -8.0, 4.0, 3));
  if (penalty == SmoothingPenalty::sparse && best.residual <= tolerance)
    for (int round = 0; round < 2; ++round) {
      const SmoothingProblem before = problem;
      problem.weigh_spans(sparse_weights(problem.third_derivatives(best.controls)));
      Fitted f = solve_at(problem, choose_lambda(problem, tolerance, best.e - 8.0, best.e + 4.0, 2));
      if (f.residual > tolerance) {  // no λ within the tolerance: the round before stands
        problem = before;
        break;
      }
      best = std::move(f);
    }
  if (merging.least_turning > 0.0 && best.residual <= tolerance)
    merge_small_lobes(problem, best, tolerance, spans, closed, merging);
  fit.spans = problem.spans(best.controls);
  fit.max_residual = best.residual;
  return fit;
}

}  // namespace gf
