#include "fair/g2_chain.hpp"

#include <algorithm>
#include <cmath>
#include <span>

#include <Eigen/Dense>
#include <boost/math/tools/toms748_solve.hpp>

#include "aesthetic/segment_fit.hpp"
#include "geom/tangent_crossing.hpp"

namespace gf {

namespace {

constexpr double min_end_curvature_ratio = 1e-2;

// D_j where segment `into` meets segment `out_of`.
double curvature_jump(const LogAestheticSegment& into, const LogAestheticSegment& out_of) {
  return into.end().curvature - out_of.start().curvature;
}

double sum_squares(const std::vector<double>& v) {
  double m = 0.0;
  for (const double x : v) m += x * x;
  return m;
}

double max_abs(const std::vector<double>& v) {
  double m = 0.0;
  for (const double x : v) m = std::max(m, std::abs(x));
  return m;
}

// The two segments either side of junction j (turning φ_j moves only them); nullopt where one
// does not exist. `near`, when given, the chain's segments before φ_j moved by a little.
struct AroundJunction {
  std::size_t before, after;  ///< segment indices
  LogAestheticSegment into, out_of;
};
std::optional<AroundJunction> segments_around(const LacChain& chain, std::size_t j,
                                              std::span<const LogAestheticSegment> near = {}) {
  const std::size_t n = chain.segment_count(), before = (j + n - 1) % n, after = j % n;
  const auto near_ratio = [&](std::size_t k) {
    return near.empty() ? std::nullopt : std::optional<double>(near[k].log_end_ratio());
  };
  // The cheap test of both first; the second fit only when the first exists.
  if (!tangents_meet_in_front(chain, before) || !tangents_meet_in_front(chain, after)) return std::nullopt;
  SegmentFit a = build_chain_segment(chain, before, near_ratio(before));
  if (!a.ok()) return std::nullopt;
  SegmentFit b = build_chain_segment(chain, after, near_ratio(after));
  if (!b.ok()) return std::nullopt;
  return AroundJunction{before, after, std::move(*a.segment), std::move(*b.segment)};
}

// D_j as a function of φ_j alone (set in `chain`, a scratch copy); nullopt where a
// neighbouring segment does not exist.
std::optional<double> junction_mismatch(LacChain& chain, std::size_t j, double phi) {
  chain.tangent_angles[j] = phi;
  const std::optional<AroundJunction> s = segments_around(chain, j);
  if (!s) return std::nullopt;
  return curvature_jump(s->into, s->out_of);
}

std::optional<double> solve_junction(const LacChain& given, std::size_t j) {
  LacChain chain = given;
  const double phi0 = chain.tangent_angles[j];
  const std::optional<double> d0 = junction_mismatch(chain, j, phi0);
  if (!d0) return std::nullopt;
  // D_j grows with φ_j: walk towards the root until the sign changes, each step at least 1.6
  // times the last and half as far again as where the secant through the last two values meets
  // zero. Where feasibility ends first, the angle stays as it was (an angle at the edge of the
  // drawable region bends its segments into an inflection).
  const double direction = *d0 > 0.0 ? -1.0 : 1.0;
  double inside = phi0, d_inside = *d0, step = 1e-3;
  std::optional<double> outside;
  double d_outside = 0.0;
  for (int it = 0; it < 40; ++it) {
    const double trial = inside + direction * step;
    const std::optional<double> dt = junction_mismatch(chain, j, trial);
    if (!dt) {  // infeasible: shrink the step from the last feasible angle, down to 1e-6 rad
      if (step < 1e-6) return std::nullopt;
      step /= 4.0;
      continue;
    }
    if ((*dt > 0.0) != (*d0 > 0.0)) {
      outside = trial, d_outside = *dt;
      break;
    }
    const double slope = (*dt - d_inside) / (trial - inside);
    const double to_root = slope != 0.0 ? std::abs(*dt / slope) : 0.0;
    inside = trial, d_inside = *dt;
    step = std::max(1.6 * step, std::min(1.5 * to_root, 1.0));
  }
  if (!outside) return inside;
  // TOMS 748 on the bracket: D_j is smooth and monotone there, so it needs a handful of the
  // evaluations (two segment fits each) bisection to the same width took forty of. An
  // infeasible angle inside the bracket ends the search.
  bool infeasible = false;
  const auto mismatch = [&](double phi) {
    const std::optional<double> d = junction_mismatch(chain, j, phi);
    infeasible = infeasible || !d;
    return d.value_or(0.0);  // 0: the solver stops at once
  };
  std::uintmax_t iterations = 60;
  const bool rising = inside < *outside;
  const auto [lo, hi] = boost::math::tools::toms748_solve(
      mismatch, rising ? inside : *outside, rising ? *outside : inside, rising ? d_inside : d_outside,
      rising ? d_outside : d_inside, boost::math::tools::eps_tolerance<double>(48), iterations);
  if (infeasible) return std::nullopt;
  return 0.5 * (lo + hi);
}

}  // namespace

bool tangents_meet_in_front(const LacChain& chain, std::size_t i) {
  const std::size_t j = (i + 1) % chain.points.size();
  return tangent_crossing(chain.points[i], direction_of(chain.tangent_angles[i]), chain.points[j],
                          direction_of(chain.tangent_angles[j]))
      .has_value();
}

SegmentFit build_chain_segment(const LacChain& chain, std::size_t i, std::optional<double> near_log_end_ratio) {
  const std::size_t n = chain.points.size();
  const std::size_t j = (i + 1) % n;
  const Vec2 q0 = chain.points[i], q1 = chain.points[j];
  const std::optional<Vec2> p1 =
      tangent_crossing(q0, direction_of(chain.tangent_angles[i]), q1, direction_of(chain.tangent_angles[j]));
  if (!p1) return {std::nullopt, "its tangents do not meet in front of both ends"};
  const bool last = i + 1 == chain.segment_count();
  if (!chain.closed && i == 0 && chain.zero_curvature_start) return fit_inflection_start(q0, *p1, q1);
  if (!chain.closed && last && chain.zero_curvature_end) {
    SegmentFit fit = fit_inflection_start(q1, *p1, q0);
    if (fit.ok()) fit.segment = fit.segment->reversed_direction();
    return fit;
  }
  // Near the edge of the drawable region one end's curvature runs off towards 0 or ∞: a
  // segment no glyph wants, and one that is slow and ill-conditioned to evaluate.
  return fit_three_point(q0, *p1, q1, chain.alphas[i], near_log_end_ratio, min_end_curvature_ratio);
}

ChainSegments build_chain(const LacChain& chain, std::size_t first_to_fit) {
  const std::size_t count = chain.segment_count();
  const auto fail = [](std::size_t i, const std::string& reason) {
    return ChainSegments{{}, "segment " + std::to_string(i) + ": " + reason, i};
  };
  for (std::size_t i = 0; i < count; ++i)
    if (!tangents_meet_in_front(chain, i)) return fail(i, "its tangents do not meet in front of both ends");
  std::vector<std::optional<LogAestheticSegment>> fitted(count);
  for (std::size_t k = 0; k < count; ++k) {
    const std::size_t i = (first_to_fit + k) % count;
    SegmentFit fit = build_chain_segment(chain, i);
    if (!fit.ok()) return fail(i, fit.reason);
    fitted[i] = std::move(fit.segment);
  }
  ChainSegments out;
  out.segments.reserve(count);
  for (std::optional<LogAestheticSegment>& s : fitted) out.segments.push_back(std::move(*s));
  return out;
}

std::vector<double> curvature_mismatch(const LacChain& chain, const std::vector<LogAestheticSegment>& segments) {
  std::vector<double> d;
  const std::size_t n = segments.size();
  for (std::size_t k = 0; k < chain.free_junction_count(); ++k) {
    const std::size_t j = chain.first_free_junction() + k;  // between segment j−1 and j
    d.push_back(curvature_jump(segments[(j + n - 1) % n], segments[j % n]));
  }
  return d;
}

G2Result make_g2(LacChain chain, G2Tolerance tolerance_spec, int max_iterations) {
  G2Result result;
  ChainSegments built = build_chain(chain);
  if (!built.ok()) {
    result.reason = built.reason;
    result.chain = std::move(chain);
    return result;
  }
  for (const LogAestheticSegment& s : built.segments)
    result.curvature_scale = std::max({result.curvature_scale, std::abs(s.start().curvature), std::abs(s.end().curvature)});
  const double tolerance = std::max(tolerance_spec.absolute, tolerance_spec.relative * result.curvature_scale);
  std::vector<double> d = curvature_mismatch(chain, built.segments);
  const int m = static_cast<int>(d.size());
  const std::size_t first = chain.first_free_junction(), n = chain.segment_count();
  constexpr double h = 1e-7;
  for (result.iterations = 0; result.iterations < max_iterations && max_abs(d) > tolerance; ++result.iterations) {
    Eigen::MatrixXd jacobian = Eigen::MatrixXd::Zero(m, m);
    LacChain moved = chain;
    for (int c = 0; c < m; ++c) {
      const std::size_t j = first + static_cast<std::size_t>(c);
      moved.tangent_angles[j] = chain.tangent_angles[j] + h;
      const std::optional<AroundJunction> around = segments_around(moved, j, built.segments);
      moved.tangent_angles[j] = chain.tangent_angles[j];
      if (!around) {
        result.reason = "junction " + std::to_string(j) + " sits at the edge of its feasible range";
        break;
      }
      // φ_j moves segments j−1 and j only, so D_{j−1}, D_j and D_{j+1} only (cyclically for a
      // closed chain).
      const auto probe = [&](std::size_t k) -> const LogAestheticSegment& {
        return k == around->after ? around->out_of : k == around->before ? around->into : built.segments[k];
      };
      for (int r = 0; r < m; ++r) {
        const int gap = std::abs(r - c);
        if (!(gap <= 1 || (chain.closed && gap == m - 1))) continue;
        const std::size_t at = first + static_cast<std::size_t>(r);
        jacobian(r, c) = (curvature_jump(probe((at + n - 1) % n), probe(at % n)) - d[r]) / h;
      }
    }
    if (!result.reason.empty()) break;
    const Eigen::VectorXd step = jacobian.fullPivLu().solve(-Eigen::Map<const Eigen::VectorXd>(d.data(), m));
    bool improved = false;
    std::size_t failed = 0;
    for (double lambda = 1.0; lambda > 1e-6; lambda *= 0.5) {
      LacChain trial = chain;
      for (int j = 0; j < m; ++j) trial.tangent_angles[first + static_cast<std::size_t>(j)] += lambda * step(j);
      ChainSegments attempt = build_chain(trial, failed);
      if (!attempt.ok()) {
        failed = attempt.failed_segment;
        continue;
      }
      const std::vector<double> dt = curvature_mismatch(trial, attempt.segments);
      if (sum_squares(dt) < sum_squares(d)) {
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
  if (max_abs(d) > tolerance) {
    // The seeds' method where Newton stalls at the edge of the feasible region: junction by
    // junction, the worst first, bisect D_j(φ_j) = 0 within φ_j's feasible run (D_j grows with
    // φ_j, lac-math.md §6.1), the other angles fixed. One sweep, kept when the whole chain
    // still exists.
    std::vector<int> order(static_cast<std::size_t>(m));
    for (int k = 0; k < m; ++k) order[static_cast<std::size_t>(k)] = k;
    std::sort(order.begin(), order.end(), [&](int a, int b) { return std::abs(d[a]) > std::abs(d[b]); });
    LacChain swept = chain;
    for (const int k : order) {
      const std::size_t j = first + static_cast<std::size_t>(k);
      if (const std::optional<double> phi = solve_junction(swept, j)) swept.tangent_angles[j] = *phi;
    }
    if (ChainSegments again = build_chain(swept); again.ok()) {
      chain = std::move(swept);
      built = std::move(again);
      d = curvature_mismatch(chain, built.segments);
    }
    if (max_abs(d) <= tolerance) result.reason.clear();
  }
  result.max_mismatch = max_abs(d);
  result.converged = result.max_mismatch <= tolerance;
  if (!result.converged && result.reason.empty()) result.reason = "no convergence in " + std::to_string(max_iterations) + " iterations";
  result.chain = std::move(chain);
  result.segments = std::move(built.segments);
  result.mismatches = std::move(d);
  return result;
}

}  // namespace gf
