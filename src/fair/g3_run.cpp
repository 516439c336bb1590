#include "fair/g3_run.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <Eigen/Dense>

#include "geom/damped_newton.hpp"

namespace gf {

namespace {

constexpr double converged = 1e-11;  // max miss: position over chord, angle in radians
constexpr double fd_step = 1e-7;
constexpr int max_iterations = 60;

// The unknowns, scaled to O(1) by a typical segment length h: θ as is, κ·h, slide / h, L / h.
class G3System {
 public:
  G3System(std::span<const G3Node> nodes, std::span<const double> lengths, bool closed, SlopeRule rule)
      : nodes_(nodes.begin(), nodes.end()), closed_(closed), rule_(rule), m_(lengths.size()) {
    h_ = std::accumulate(lengths.begin(), lengths.end(), 0.0) / static_cast<double>(m_);
    const auto add = [&](double value, std::size_t node, int segment) {
      x0_.push_back(value);
      owner_node_.push_back(node), owner_segment_.push_back(segment);
      return static_cast<int>(x0_.size() - 1);
    };
    theta_.assign(nodes_.size(), -1), kappa_.assign(nodes_.size(), -1), slide_.assign(nodes_.size(), -1);
    for (std::size_t j = 0; j < nodes_.size(); ++j) {
      const G3Node& n = nodes_[j];
      switch (n.kind) {
        case G3NodeKind::smooth:
          theta_[j] = add(n.tangent_angle, j, -1), kappa_[j] = add(n.curvature * h_, j, -1);
          break;
        case G3NodeKind::inflection:
        case G3NodeKind::held:
          theta_[j] = add(n.tangent_angle, j, -1), slide_[j] = add(0.0, j, -1);
          break;
        case G3NodeKind::corner: kappa_[j] = add(n.curvature * h_, j, -1); break;
        case G3NodeKind::corner_held: theta_[j] = add(n.tangent_angle, j, -1); break;
        case G3NodeKind::line:
        case G3NodeKind::line_g2: slide_[j] = add(0.0, j, -1); break;
      }
      const Vec2 t = direction_of(n.tangent_angle);
      const bool across = n.kind == G3NodeKind::inflection || n.kind == G3NodeKind::held;
      slide_direction_.push_back(across ? perpendicular(t) : t);
    }
    for (std::size_t i = 0; i < m_; ++i) {
      length_.push_back(add(lengths[i] / h_, nodes_.size(), static_cast<int>(i)));
      chord_.push_back(std::max(distance(nodes_[i].point, nodes_[next(i)].point), 1e-9 * h_));
    }
  }

  std::size_t segments() const { return m_; }
  Eigen::VectorXd start() const {
    return Eigen::Map<const Eigen::VectorXd>(x0_.data(), static_cast<Eigen::Index>(x0_.size()));
  }

  Vec2 point(const Eigen::VectorXd& x, std::size_t j) const {
    return slide_[j] < 0 ? nodes_[j].point : nodes_[j].point + slide_direction_[j] * (x[at(slide_[j])] * h_);
  }
  double angle(const Eigen::VectorXd& x, std::size_t j) const {
    return theta_[j] < 0 ? nodes_[j].tangent_angle : x[at(theta_[j])];
  }
  double curvature(const Eigen::VectorXd& x, std::size_t j) const {
    if (kappa_[j] >= 0) return x[at(kappa_[j])] / h_;
    const G3NodeKind kind = nodes_[j].kind;
    return kind == G3NodeKind::held || kind == G3NodeKind::corner_held ? nodes_[j].curvature : 0.0;
  }
  double length(const Eigen::VectorXd& x, std::size_t i) const { return x[at(length_[i])] * h_; }

  /// κ′ at node j: the rule's mean of the neighbouring secants; the end secant at a corner.
  double slope(const Eigen::VectorXd& x, std::size_t j) const {
    const G3NodeKind kind = nodes_[j].kind;
    if (kind == G3NodeKind::line) return 0.0;
    if (kind == G3NodeKind::corner || kind == G3NodeKind::corner_held || kind == G3NodeKind::line_g2)
      return secant(x, j == 0 ? 0 : m_ - 1);
    const double a = secant(x, j == 0 ? m_ - 1 : j - 1), b = secant(x, j % m_);
    if (!(a * b > 0.0)) return 0.0;
    if (rule_ == SlopeRule::harmonic_mean) return 2.0 * a * b / (a + b);
    return 4.0 * (a * b) * (a * b) / ((a + b) * (a * a + b * b));
  }

  CurvatureEnd end_data(const Eigen::VectorXd& x, std::size_t j) const {
    return {point(x, j), angle(x, j), curvature(x, j), slope(x, j)};
  }

  PolynomialSpiral spiral(const Eigen::VectorXd& x, std::size_t i) const {
    const std::size_t k = next(i);
    return PolynomialSpiral(end_data(x, i), length(x, i), curvature(x, k), slope(x, k), 0.0, 0.0);
  }

  /// How far segment i's far end misses node i + 1: point over the chord, then the angle.
  Eigen::Vector3d miss(const Eigen::VectorXd& x, std::size_t i) const {
    const std::size_t k = next(i);
    const PolynomialSpiral s = spiral(x, i);
    const Vec2 d = (s.end().point - point(x, k)) / chord_[i];
    return {d.x, d.y, wrapped_angle(s.tangent_angle_at(s.length()) - angle(x, k))};
  }

  /// The segments whose miss unknown u moves (κ′ reaches two secants away).
  std::vector<std::size_t> touched_by(Eigen::Index unknown) const {
    const auto u = static_cast<std::size_t>(unknown);
    const int n = static_cast<int>(m_);
    const int centre = owner_segment_[u] >= 0 ? owner_segment_[u] : static_cast<int>(owner_node_[u]);
    const int lo = owner_segment_[u] >= 0 ? centre - 1 : centre - 2, hi = centre + 1;
    std::vector<std::size_t> out;
    for (int i = lo; i <= hi; ++i) {
      if (closed_) out.push_back(static_cast<std::size_t>(((i % n) + n) % n));
      else if (i >= 0 && i < n) out.push_back(static_cast<std::size_t>(i));
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  }

  /// Every length positive, and no line end slid past its room into the line (behind the
  /// start, ahead of the end).
  bool feasible(const Eigen::VectorXd& x) const {
    for (std::size_t i = 0; i < m_; ++i)
      if (!(length(x, i) > 0.0)) return false;
    for (std::size_t j = 0; j < nodes_.size(); ++j) {
      if (nodes_[j].kind != G3NodeKind::line && nodes_[j].kind != G3NodeKind::line_g2) continue;
      const double into_line = x[at(slide_[j])] * h_ * (j == 0 ? -1.0 : 1.0);
      if (into_line > nodes_[j].slide_room) return false;
    }
    return x.allFinite();
  }

 private:
  static Eigen::Index at(int index) { return index; }
  std::size_t next(std::size_t i) const { return closed_ ? (i + 1) % m_ : i + 1; }
  double secant(const Eigen::VectorXd& x, std::size_t i) const {
    return (curvature(x, next(i)) - curvature(x, i)) / length(x, i);
  }

  std::vector<G3Node> nodes_;
  bool closed_;
  SlopeRule rule_;
  std::size_t m_;
  double h_ = 1.0;
  std::vector<double> x0_;
  std::vector<std::size_t> owner_node_;
  std::vector<int> owner_segment_;
  std::vector<int> theta_, kappa_, slide_, length_;
  std::vector<Vec2> slide_direction_;
  std::vector<double> chord_;
};

Eigen::VectorXd misses(const G3System& sys, const Eigen::VectorXd& x) {
  Eigen::VectorXd f(static_cast<Eigen::Index>(3 * sys.segments()));
  for (std::size_t i = 0; i < sys.segments(); ++i) f.segment<3>(static_cast<Eigen::Index>(3 * i)) = sys.miss(x, i);
  return f;
}

}  // namespace

G3Result make_g3(const G3Problem& problem) {
  return make_g3(problem.nodes, problem.lengths, problem.closed, problem.slope_rule);
}

G3Result make_g3(std::span<const G3Node> nodes, std::span<const double> lengths, bool closed, SlopeRule rule) {
  G3Result out;
  const std::size_t m = lengths.size();
  if (m == 0 || nodes.size() != (closed ? m : m + 1)) {
    out.reason = "the G3 solve needs one node per segment end";
    return out;
  }
  const G3System sys(nodes, lengths, closed, rule);
  // The Jacobian by forward differences, each column only on the segments its unknown moves
  // (so sparse: a few segments' rows per column).
  const auto jacobian = [&](const Eigen::VectorXd& at, const Eigen::VectorXd& f) {
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(static_cast<std::size_t>(at.size()) * 12);  // three rows of up to four segments
    Eigen::VectorXd moved = at;
    for (Eigen::Index u = 0; u < at.size(); ++u) {
      moved[u] += fd_step;
      for (const std::size_t i : sys.touched_by(u)) {
        const auto row = static_cast<Eigen::Index>(3 * i);
        const Eigen::Vector3d column = (sys.miss(moved, i) - f.segment<3>(row)) / fd_step;
        for (Eigen::Index r = 0; r < 3; ++r) entries.emplace_back(row + r, u, column[r]);
      }
      moved[u] = at[u];
    }
    Eigen::SparseMatrix<double> jac(f.size(), at.size());
    jac.setFromTriplets(entries.begin(), entries.end());
    return jac;
  };
  Eigen::VectorXd x = sys.start();
  const NewtonRun run = damped_newton(
      x, [&](const Eigen::VectorXd& v) { return misses(sys, v); }, jacobian,
      [&](const Eigen::VectorXd& v) { return sys.feasible(v); }, converged, max_iterations);
  out.iterations = run.iterations, out.residual = run.residual;
  if (run.end != NewtonEnd::converged) {
    out.reason = "the G3 solve stalled " + std::to_string(out.residual) + " from meeting its junctions after " +
                 std::to_string(out.iterations) + " iterations";
    return out;
  }
  for (std::size_t j = 0; j < nodes.size(); ++j) out.ends.push_back(sys.end_data(x, j));
  for (std::size_t i = 0; i < m; ++i) out.spirals.push_back(sys.spiral(x, i));
  return out;
}

// By length and curvature: a log-aesthetic segment leaving a line stays nearly flat, then turns;
// cut at equal arc lengths, its first spiral's cubic κ turned five times too far, and the solve
// stalled (dkg Bold's v).
std::vector<double> cut_places(const PathPiece& piece, int n, CutPlacement placement) {
  std::vector<double> out{0.0};
  if (n > 1 && placement == CutPlacement::by_length) {
    for (int c = 1; c < n; ++c) out.push_back(piece.length * c / n);
  } else if (n > 1) {
    constexpr int samples = 64;
    const std::vector<LacPoint> q = piece.sample(samples);
    std::vector<double> walked{0.0};  // Σ|Δκ| up to each sample
    for (int k = 1; k <= samples; ++k) walked.push_back(walked.back() + std::abs(q[k].curvature - q[k - 1].curvature));
    const auto measure = [&](int k) {
      const double by_length = static_cast<double>(k) / samples;
      return walked.back() > 0.0 ? 0.5 * (by_length + walked[k] / walked.back()) : by_length;
    };
    int k = 0;
    for (int c = 1; c < n; ++c) {
      const double target = static_cast<double>(c) / n;
      while (k + 1 < samples && measure(k + 1) < target) ++k;
      const double a = measure(k), b = measure(k + 1);
      out.push_back(piece.length * (k + (b > a ? (target - a) / (b - a) : 0.0)) / samples);
    }
  }
  out.push_back(piece.length);
  return out;
}

std::optional<RunPieces> run_pieces(const std::vector<FairedChain>& chains) {
  RunPieces out;
  // Every chain read as pieces: its log-aesthetic segments, or its guide stretch cut where its
  // curvature changes sign and every quarter turn (a C2 spline, whose κ′ jumps at its knots:
  // re-expressed as spirals like any segment, it comes out G3 too).
  for (const FairedChain& c : chains) {
    if (c.segments.empty() && !c.guide) return std::nullopt;
    // A guide's pieces cut at its curvature extrema too, as log-aesthetic segments are: one
    // spiral's cubic κ(s) with κ′ = 0 at an extremum node follows a peak no piece straddles
    // (a–z A–Z under G3, Open Sans's inflections 1.33× → 1.17× of the source's).
    std::vector<PathPiece> own = c.guide ? guide_pieces(*c.guide, c.closed, true) : chain_pieces(c);
    out.per_chain.push_back(own.size());
    for (std::size_t k = 0; k < own.size(); ++k)
      out.at_inflection.push_back((k == 0 && c.zero_curvature_start) || own[k].after_sign_change),
          out.pieces.push_back(std::move(own[k]));
  }
  if (out.pieces.empty()) return std::nullopt;
  return out;
}

G3Problem g3_problem(const RunPieces& segments, const SmoothRun& run, std::span<const std::vector<double>> cuts,
                     bool equal_lengths) {
  G3Problem p;
  p.closed = run.closed;
  p.pieces_per_chain = segments.per_chain;
  const auto end_kind = [](RunEndKind k) { return k == RunEndKind::line ? G3NodeKind::line : G3NodeKind::corner; };
  // The run's share of the line, less 1 % so that the line keeps a length, less what the G2
  // chain already slid back into it.
  const auto room = [&](const RunEnd& e, Vec2 node, bool at_start) {
    const Vec2 source_end = at_start ? run.cubics.front().p[0] : run.cubics.back().p[3];
    const double slid_back = dot(at_start ? source_end - node : node - source_end, e.tangent);
    return std::max(0.99 * e.line_share - std::max(slid_back, 0.0), 0.0);
  };
  const std::vector<PathPiece>& pieces = segments.pieces;
  const std::size_t m = pieces.size();
  const auto start_of = [](const PathPiece& piece) { return piece.at(0.0); };
  const auto end_of = [](const PathPiece& piece) { return piece.at(piece.length); };
  double angle = angle_of(start_of(pieces.front()).tangent);
  for (std::size_t i = 0; i < m; ++i) {
    const PathPiece& seg = pieces[i];
    const std::vector<double>& at = cuts[i];
    const std::size_t n = at.size() - 1;
    LacPoint last = start_of(seg);
    for (std::size_t k = 0; k < n; ++k) {
      G3NodeKind kind = G3NodeKind::smooth;
      double kappa = last.curvature;
      if (k == 0) {
        if (segments.at_inflection[i] && (run.closed || i > 0)) kind = G3NodeKind::inflection;
        if (!run.closed && i == 0) kind = end_kind(run.start.kind);
        // κ: the mean of the two sides (equal once the G2 solve converged).
        if (i > 0 || run.closed) kappa = 0.5 * (kappa + end_of(pieces[(i + m - 1) % m]).curvature);
      }
      p.nodes.push_back({last.point, angle, kappa, kind, !run.closed && i == 0 && k == 0 ? room(run.start, last.point, true) : 0.0});
      const LacPoint next = k + 1 == n ? end_of(seg) : seg.at(at[k + 1]);
      // At equal lengths exactly L / n each, as before cuts were placed otherwise.
      p.lengths.push_back(equal_lengths ? seg.length / static_cast<double>(n) : at[k + 1] - at[k]);
      p.run_piece.push_back(i);
      angle += turning_angle(last.tangent, next.tangent);
      last = next;
    }
  }
  if (!run.closed) {
    const LacPoint end = end_of(pieces.back());
    p.nodes.push_back({end.point, angle, end.curvature, end_kind(run.end.kind), room(run.end, end.point, false)});
  }
  return p;
}

std::optional<G3Problem> g3_problem(const std::vector<FairedChain>& chains, const SmoothRun& run,
                                    std::span<const int> pieces, CutPlacement placement) {
  const std::optional<RunPieces> segments = run_pieces(chains);
  if (!segments) return std::nullopt;
  std::vector<std::vector<double>> cuts;
  for (std::size_t i = 0; i < segments->pieces.size(); ++i)
    cuts.push_back(cut_places(segments->pieces[i], i < pieces.size() ? std::max(pieces[i], 1) : 1, placement));
  return g3_problem(*segments, run, cuts, placement == CutPlacement::by_length);
}

void adopt_spirals(std::vector<FairedChain>& chains, const G3Problem& problem, std::vector<PolynomialSpiral> spirals) {
  std::size_t next = 0, first_segment = 0;
  for (std::size_t c = 0; c < chains.size(); ++c) {
    FairedChain& chain = chains[c];
    const std::size_t end_segment = first_segment + problem.pieces_per_chain[c];
    chain.spirals.clear();
    for (; next < spirals.size() && problem.run_piece[next] < end_segment; ++next)
      chain.spirals.push_back(std::move(spirals[next]));
    chain.segments.clear();
    chain.guide.reset();
    chain.max_mismatch_relative = 0.0;
    first_segment = end_segment;
  }
}

}  // namespace gf
