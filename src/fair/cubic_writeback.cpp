#include "fair/cubic_writeback.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <span>

#include "fair/cubic_change.hpp"
#include "fair/node_curvatures.hpp"
#include "fair/path_piece.hpp"
#include "geom/curvature.hpp"
#include "geom/g2_hermite.hpp"
#include "geom/polyline_distance.hpp"
#include "geom/tangent_fit.hpp"
#include "geom/turning.hpp"

namespace gf {

namespace {

constexpr int max_depth = 6;
constexpr int cubic_samples = 48;
constexpr double fine_enough = 0.03;  // of κ per grid step at a node
constexpr double infeasible = std::numeric_limits<double>::infinity();
constexpr double no_cubic = 1e300;    // the deviation of a span no G2 Hermite cubic spans
constexpr double far_off = 4.0;       // a cubic this many budgets off: a longer one from its start is no nearer
constexpr double fold_margin = 0.5 * std::numbers::pi;  // a cubic may turn beyond its span; a cusp turns π more
constexpr double edge_margin = 0.05;  // no grid node within this share of a span's turning or length of its ends
constexpr double snap_turn = radians(10.0);  // a corner's tangent may turn onto a nearby extremum's axis
constexpr double same_grid_place = 0.5;  // units: points nearer than this round to one grid place
constexpr double snap_reach = 64.0;   // units along the chain: farther, the cubic between is long enough for the grid
constexpr int even_cut_count = 15;   // places evenly along a span no chain of grid nodes fits
// A corner's handle lengths tried for a span from it (or, from a flat end to a corner, the flat
// end's), as shares of the span's chord: from just over crowds_a_node's 3 % to the whole
// chord, evenly in their logarithm.
constexpr int corner_handles = 24;
constexpr double shortest_corner_handle = 0.04, longest_corner_handle = 1.0;
// A bound end's curvature under this share of flat_curvature is 0 itself (κ·UPM under 5e-4).
constexpr double flat_share = 1e-3;

std::array<double, corner_handles> corner_handle_lengths(double chord) {
  std::array<double, corner_handles> out;
  const double ratio = longest_corner_handle / shortest_corner_handle;
  for (int k = 0; k < corner_handles; ++k)
    out[static_cast<std::size_t>(k)] = chord * shortest_corner_handle * std::pow(ratio, double(k) / (corner_handles - 1));
  return out;
}

// What the path between two of the writeback's nodes does, so a cubic fitted to it must too:
// bend one way, and turn horizontal or vertical only at its ends.
bool bends_as_a_span(const Cubic& c) { return curvature_shape(c, 0.0).sign_changes == 0 && inner_axis_extrema(c) == 0; }

// The chain as one curve in arc length σ (σ past the end wraps round a closed chain), with a
// dense table of its points for distances.
class ChainPath {
 public:
  explicit ChainPath(const FairedChain& chain) : closed_(chain.closed) {
    pieces_ = chain_pieces(chain);
    n_ = pieces_.size();
    double start = 0.0;
    for (const PathPiece& piece : pieces_) {
      starts_.push_back(start);
      const int n = std::clamp(static_cast<int>(std::ceil(piece.length / 2.0)), 16, 256);
      const std::vector<LacPoint> pts = piece.sample(n);
      for (int k = 0; k < n; ++k) table_.push_back({start + piece.length * k / n, pts[static_cast<std::size_t>(k)].point});
      start += piece.length;
    }
    total_ = start;
    const LacPoint end = closed_ ? pieces_.front().at(0.0) : pieces_.back().at(pieces_.back().length);
    table_.push_back({total_, end.point});
  }

  double total() const { return total_; }
  std::size_t segment_count() const { return starts_.size(); }
  double segment_start(std::size_t i) const { return starts_[i]; }
  const PathPiece& piece(std::size_t i) const { return pieces_[i]; }

  /// At a junction both sides agree: point and tangent (G1), curvature by with_mean_curvature.
  /// An open chain's end whose tangent was turned (turn_end) has that tangent and κ = 0: it is
  /// a corner, which no G2 binds, and the path's own κ with the turned tangent left no cubic
  /// that fitted (Kristi's H: seven cubics for an 84-unit span within a budget of 7 units).
  LacPoint at(double sigma) const {
    LacPoint p = along(sigma);
    const std::optional<Vec2>& turned = sigma <= 0.0 ? start_tangent_ : end_tangent_;
    if (!closed_ && (sigma <= 0.0 || sigma >= total_) && turned) p.tangent = *turned, p.curvature = 0.0;
    return p;
  }

  /// Turns an open chain's tangent at its start or end (none: back to its own).
  void turn_end(SegmentEnd end, std::optional<Vec2> tangent) {
    (end == SegmentEnd::start ? start_tangent_ : end_tangent_) = tangent;
  }

  // At a junction whose solve fell short of G2, both sides get the mean curvature, so the
  // cubics meeting there agree.
  LacPoint with_mean_curvature(LacPoint p, std::size_t other, bool other_starts) const {
    if (other >= n_) return p;
    const PathPiece& o = pieces_[other];
    p.curvature = 0.5 * (p.curvature + (other_starts ? o.at(0.0) : o.at(o.length)).curvature);
    return p;
  }

  /// The chain's points over [a, b] (b may pass the seam of a closed chain), ends included.
  std::vector<Vec2> points(double a, double b) const {
    std::vector<Vec2> out{at(a).point};
    for (const double offset : {0.0, total_}) {
      auto it = std::upper_bound(table_.begin(), table_.end(), a - offset,
                                 [](double v, const std::pair<double, Vec2>& e) { return v < e.first; });
      for (; it != table_.end() && it->first + offset < b; ++it) out.push_back(it->second);
    }
    out.push_back(at(b).point);
    return out;
  }

  /// Where in (a, b) the tangent has turned by `turn` from its direction at a, bisected as if
  /// the turning grew monotonically. A log-aesthetic chain's does; a chain written from its
  /// smoothing guide may bend both ways, and there the place found may not run along the
  /// grid direction asked for (DejaVu Sans's U+2765: nodes stepped 25–54° off their tangents).
  double where_turned(double a, double b, double turn) const {
    const Vec2 ta = at(a).tangent;
    double lo = a, hi = b;
    for (int it = 0; it < 60 && hi - lo > 1e-9; ++it) {
      const double m = 0.5 * (lo + hi);
      (std::abs(turning_angle(ta, at(m).tangent)) < std::abs(turn) ? lo : hi) = m;
    }
    return 0.5 * (lo + hi);
  }

 private:
  LacPoint along(double sigma) const {
    if (sigma > total_) sigma -= total_;  // a closed chain, past its seam
    std::size_t i = static_cast<std::size_t>(std::upper_bound(starts_.begin(), starts_.end(), sigma) - starts_.begin());
    i = i == 0 ? 0 : i - 1;
    const PathPiece& piece = pieces_[i];
    const double local = sigma - starts_[i];
    // Within rounding of a piece's end is its end: σ sums the lengths before it, and near an
    // inflection end κ falls to 0 so steeply that 1e-13 short of it left κ·UPM at 0.19
    // (Cantarell's U, where its bowl meets the stem).
    if (local >= piece.length * (1.0 - 1e-12))
      return with_mean_curvature(piece.at(piece.length), i + 1 < n_ ? i + 1 : (closed_ ? 0 : n_), true);
    if (local <= 0.0) return with_mean_curvature(piece.at(0.0), i == 0 ? (closed_ ? n_ - 1 : n_) : i - 1, false);
    return piece.at(local);
  }

  bool closed_;
  std::vector<PathPiece> pieces_;
  std::size_t n_ = 0;
  std::vector<double> starts_;
  std::vector<std::pair<double, Vec2>> table_;
  double total_ = 0.0;
  std::optional<Vec2> start_tangent_, end_tangent_;
};

struct RequiredNode {
  double sigma;
  std::optional<Vec2> grid_step;
};

// Where the tangent is horizontal or vertical (each segment turns by less than π, monotonically).
// A segment's ends count within `on_axis` radians: a junction at an extremum (every junction
// of a circle's chain) comes out a last bit short of the axis on one side or the other, and
// was lost to both segments (Inter Italic's i dot: one node, and its one cubic collapsed).
std::vector<RequiredNode> axis_extrema(const ChainPath& path) {
  std::vector<RequiredNode> out;
  const double quarter = std::numbers::pi / 2, on_axis = 1e-9;
  for (std::size_t i = 0; i < path.segment_count(); ++i) {
    const PathPiece& seg = path.piece(i);
    const Vec2 t0 = seg.at(0.0).tangent;
    const double phi0 = angle_of(t0);
    const double turn = turning_angle(t0, seg.at(seg.length).tangent);
    const double lo = std::min(phi0, phi0 + turn) - on_axis, hi = std::max(phi0, phi0 + turn) + on_axis;
    for (double k = std::ceil(lo / quarter); k * quarter <= hi; k += 1.0) {
      const double target = k * quarter - phi0;
      if (std::abs(target) <= on_axis && i > 0) continue;  // the previous segment's end has it
      const double start = path.segment_start(i);
      const double sigma = path.where_turned(start, start + seg.length, target);
      const Vec2 t = path.at(sigma).tangent;
      const Vec2 step = std::abs(t.x) > std::abs(t.y) ? Vec2{t.x > 0 ? 1.0 : -1.0, 0.0} : Vec2{0.0, t.y > 0 ? 1.0 : -1.0};
      out.push_back({sigma, step});
    }
  }
  return out;
}

std::vector<Vec2> cubic_points(const Cubic& c) {
  std::vector<Vec2> pts;
  for (int k = 0; k <= cubic_samples; ++k) pts.push_back(c.point_at(static_cast<double>(k) / cubic_samples));
  return pts;
}

// The two-sided distance between a cubic's points and the path's; past `stop_above`, only that
// it is past.
double cubic_deviation(std::span<const Vec2> pts, const std::vector<Vec2>& lac, double stop_above) {
  const double there = directed_hausdorff(pts, lac, stop_above);
  return there > stop_above ? there : std::max(there, directed_hausdorff(lac, pts, stop_above));
}

struct Piece {
  Cubic cubic;
  std::optional<Vec2> end_step;  ///< the grid direction of the node the cubic ends at
};

// The G2 Hermite cubic of a span nearest the path, and how far from it.
struct Fitted {
  std::optional<Cubic> cubic;
  double deviation = no_cubic;
  bool within(double budget) const { return cubic && deviation <= budget; }
};

class SpanWriter {
 public:
  /// `corners`: the ends of an open chain that are corners, whose curvature binds nothing.
  SpanWriter(const ChainPath& path, double budget, double flat_curvature, SpanCutting cutting, ChainEnds corners,
             ChainCubics& out)
      : path_(path), budget_(budget), flat_(flat_curvature), cutting_(cutting), corners_(corners), out_(out) {}

  void fit(double a, double b, std::optional<Vec2> start_step, std::optional<Vec2> end_step, int depth,
           std::vector<Piece>& pieces) {
    const std::optional<Fitted> known = fitted_as_path_has_it(a, b);
    Fitted f = known ? *known : best_cubic(a, b, start_step, end_step);
    if (f.within(budget_) || depth >= max_depth || distance(path_.at(a).point, path_.at(b).point) < cutting_.shortest_span) {
      if (!f.cubic) {  // no G2 cubic at all: the nearest to G2, else G1 with third-chord handles
        const LacPoint pa = frame(a), pb = frame(b);
        const double h = distance(pa.point, pb.point) / 3.0;
        f.cubic = nearest_to_g2(pa, pb).value_or(
            Cubic{pa.point, pa.point + pa.tangent * h, pb.point - pb.tangent * h, pb.point});
        ++out_.g1_fallbacks;
      }
      pieces.push_back({*f.cubic, end_step});
      return;
    }
    if (through_cut_places({a, start_step}, {b, end_step}, pieces)) return;
    // No chain of grid nodes fits: halve the span and try again on each half.
    const Cut cut = fallback_cut(a, b);
    fit(a, cut.sigma, start_step, cut.step, depth + 1, pieces);
    fit(cut.sigma, b, cut.step, end_step, depth + 1, pieces);
  }

  /// The curvature at each of the chain's nodes (`nodes`, in order; a closed chain's last span
  /// returns to the first) chosen so that as many spans as may fit as one cubic
  /// (fair/node_curvatures); fit() then meets it.
  void free_node_curvatures(std::span<const RequiredNode> nodes, bool closed) {
    const std::size_t n = nodes.size();
    if (n < 2) return;
    const auto end_of = [&](std::size_t i) { return i + 1 < n ? nodes[i + 1].sigma : nodes[0].sigma + path_.total(); };
    std::vector<NodeCurvature> known(n);
    for (std::size_t k = 0; k < n; ++k) {
      known[k].path = path_.at(nodes[k].sigma).curvature;
      known[k].free = (closed || (k > 0 && k + 1 < n)) && std::abs(known[k].path) >= flat_;
    }
    // Each span's stretch of the path is sampled once for all it is asked. Each span is first
    // asked as the path has it, and fit() keeps that answer where no node of the span then moves.
    std::vector<std::optional<Stretch>> stretches(n);
    const auto stretch = [&](std::size_t i) -> const Stretch& {
      if (!stretches[i]) stretches[i] = stretch_of(nodes[i].sigma, end_of(i));
      return *stretches[i];
    };
    const SpanFits fits = [&](std::size_t i, double k_start, double k_end) {
      const std::size_t j = (i + 1) % n;
      const bool as_path = k_start == known[i].path && k_end == known[j].path;
      if (!as_path) chosen_ = {{nodes[i].sigma, k_start}, {nodes[j].sigma, k_end}};
      // A share of the budget is asked of the cubic best_cubic would write, not of any.
      const double share = as_path ? 1.0 : cutting_.freed_span_budget_share;
      if (share == 1.0 && !as_path) {
        const bool found = any_cubic_within(stretch(i));
        chosen_.clear();
        return found;
      }
      const Fitted f = best_cubic(stretch(i), nodes[i].grid_step, nodes[j].grid_step);
      chosen_.clear();
      if (as_path) path_fits_.push_back({nodes[i].sigma, end_of(i), f});
      return f.within(share * budget_);
    };
    const SpanSeeds seeds = [&](std::size_t i) -> std::optional<std::array<double, 2>> {
      const Stretch& s = stretch(i);
      const LacPoint &pa = s.start, &pb = s.end;
      const std::optional<Cubic> c = fit_cubic_with_end_tangents(pa.point, pa.tangent, pb.point, pb.tangent, s.points);
      if (!c) return std::nullopt;
      return std::array{node_curvature(*c, SegmentEnd::start), node_curvature(*c, SegmentEnd::end)};
    };
    const std::vector<double> kappa = choose_node_curvatures(known, closed, fits, seeds);
    for (std::size_t k = 0; k < n; ++k)
      if (kappa[k] != known[k].path) chosen_.push_back({nodes[k].sigma, kappa[k]});
    out_.freed_nodes += static_cast<int>(chosen_.size());
    std::erase_if(path_fits_, [&](const PathFit& p) { return frame_moved(p.a) || frame_moved(p.b); });
  }

 private:
  struct ChosenCurvature {
    double sigma, kappa;
  };

  // A span as the path has it, fitted while the nodes' curvatures were chosen.
  struct PathFit {
    double a, b;
    Fitted fitted;
  };

  // Whether arc length s is the node at `sigma` (s past the end of a closed chain: its first node).
  bool at_node(double sigma, double s) const { return sigma == s || sigma + path_.total() == s; }

  // Whether the node at arc length s has a chosen curvature.
  bool frame_moved(double s) const {
    return std::any_of(chosen_.begin(), chosen_.end(), [&](const ChosenCurvature& c) { return at_node(c.sigma, s); });
  }

  // The path's frame at arc length s, with the curvature chosen for a node there
  // (free_node_curvatures).
  LacPoint frame(double s) const { return with_chosen_curvature(path_.at(s), s); }

  // A frame of the path at arc length s with the curvature chosen for a node there, if any.
  LacPoint with_chosen_curvature(LacPoint p, double s) const {
    for (const ChosenCurvature& c : chosen_)
      if (at_node(c.sigma, s)) p.curvature = c.kappa;
    return p;
  }

  // The path over [a, b] as a span's fits read it: its end frames (the path's curvatures), its
  // points and how far its tangent turns.
  struct Stretch {
    double a, b;
    LacPoint start, end;
    std::vector<Vec2> points;
    double turning;
  };
  Stretch stretch_of(double a, double b) const {
    Stretch s{a, b, path_.at(a), path_.at(b), path_.points(a, b), 0.0};
    s.turning = absolute_turning(s.start.tangent, s.points, s.end.tangent);
    return s;
  }

  // What free_node_curvatures found for [a, b] as the path has it, where it asked.
  std::optional<Fitted> fitted_as_path_has_it(double a, double b) const {
    for (const PathFit& p : path_fits_)
      if (p.a == a && p.b == b) return p.fitted;
    return std::nullopt;
  }

  // The G2 Hermite cubic of [a, b] for the writeback: of those within the budget, the one whose
  // ends the grid sets finest (node_coarseness; a span often has a lopsided solution nearest
  // the path, whose short handle leaves whole steps too coarse to keep G2, and a balanced one
  // a little farther), else the nearest when one is within `cap`; else a deviation past `cap`
  // (a cubic past it is not measured to the end). At a corner end the curvature is free
  // (span_cubics).
  Fitted best_cubic(double a, double b, std::optional<Vec2> start_step, std::optional<Vec2> end_step,
                    double cap = std::numeric_limits<double>::infinity()) const {
    return best_cubic(stretch_of(a, b), start_step, end_step, cap);
  }
  Fitted best_cubic(const Stretch& stretch, std::optional<Vec2> start_step, std::optional<Vec2> end_step,
                    double cap = std::numeric_limits<double>::infinity()) const {
    const double a = stretch.a, b = stretch.b;
    const LacPoint pa = with_chosen_curvature(stretch.start, a), pb = with_chosen_curvature(stretch.end, b);
    const std::vector<Vec2>& lac = stretch.points;
    const double turning = stretch.turning;
    Fitted best;
    double finest = infeasible;
    const auto consider = [&](const Cubic& c) {
      if (crowds_a_node(c)) return;
      const bool have_within = best.within(budget_);
      const double q = std::max(node_coarseness(c, SegmentEnd::start, start_step), node_coarseness(c, SegmentEnd::end, end_step));
      if (have_within && q > finest) return;  // coarser than one already within: not measured
      const std::vector<Vec2> pts = cubic_points(c);
      if (!keeps_the_span_shape(c, pts, pa, pb, turning)) return;
      const double d = cubic_deviation(pts, lac, have_within ? budget_ : std::min(cap, std::max(best.deviation, budget_)));
      if (d <= budget_) {
        if (!have_within || q < finest || d < best.deviation) best = {c, d}, finest = q;
      } else if (!have_within) {
        if (d < best.deviation && d <= cap) best = {c, d};
        else if (!best.cubic) best.deviation = std::min(best.deviation, d);
      }
    };
    const bool at_start = a <= 0.0, at_end = b >= path_.total();
    for (const Cubic& c : span_cubics(pa, pb, at_start, at_end, lac)) consider(c);
    // Only where none of those fits: preferred to them, they took Inconsolata's curvature
    // variation from 0.91× to 0.93× of the source's (a–z A–Z).
    if (!best.within(budget_))
      for (const Cubic& c : flat_to_corner_cubics(pa, pb, at_start, at_end)) consider(c);
    return best;
  }

  // Whether any cubic best_cubic weighs for [a, b] is within the budget: all the choice of
  // node curvatures asks of a pair it tries, measured no farther than the budget and no
  // further than the first that is.
  bool any_cubic_within(const Stretch& stretch) const {
    const double a = stretch.a, b = stretch.b;
    const LacPoint pa = with_chosen_curvature(stretch.start, a), pb = with_chosen_curvature(stretch.end, b);
    const std::vector<Vec2>& lac = stretch.points;
    const double turning = stretch.turning;
    const auto fits = [&](const Cubic& c) {
      if (crowds_a_node(c)) return false;
      const std::vector<Vec2> pts = cubic_points(c);
      return keeps_the_span_shape(c, pts, pa, pb, turning) && cubic_deviation(pts, lac, budget_) <= budget_;
    };
    const bool at_start = a <= 0.0, at_end = b >= path_.total();
    for (const Cubic& c : span_cubics(pa, pb, at_start, at_end, lac))
      if (fits(c)) return true;
    for (const Cubic& c : flat_to_corner_cubics(pa, pb, at_start, at_end))
      if (fits(c)) return true;
    return false;
  }

  // Whether a cubic (sampled `pts`) draws the span from pa to pb, which turns by `turning`, as a
  // node-to-node span may. Handles that overreach fold the cubic back on itself (a loop or a
  // cusp), which may stay within the budget of the path yet turns by half a turn more than it.
  bool keeps_the_span_shape(const Cubic& c, std::span<const Vec2> pts, const LacPoint& pa, const LacPoint& pb,
                            double turning) const {
    if (absolute_turning(pa.tangent, pts, pb.tangent) > turning + fold_margin) return false;
    return !cutting_.no_inner_extrema || inner_axis_extrema_of(c).off_node == 0;
  }

  // A span from a flat end (κ = 0: a line join) to a corner: κ = 0 fixes the corner's handle,
  // so the lengths tried are the flat end's (g2_hermite_cubic_from_flat_end). Without these,
  // such a span had no cubic and was cut wherever it could be, at nodes whose small curvature
  // the grid then set to 0, with flat inflections between (Liberation Sans's W: 7 against the
  // source's 1). Each must bend one way with no extremum inside, as span_cubics' do.
  std::vector<Cubic> flat_to_corner_cubics(const LacPoint& pa, const LacPoint& pb, bool at_start, bool at_end) const {
    const bool free_start = at_start && corners_.start_corner, free_end = at_end && corners_.end_corner;
    std::vector<Cubic> out;
    if (free_start == free_end || std::abs(free_start ? pb.curvature : pa.curvature) >= flat_share * flat_) return out;
    const HermiteEnd start{pa.point, pa.tangent, 0.0}, end{pb.point, pb.tangent, 0.0};
    for (const double h : corner_handle_lengths(distance(pa.point, pb.point))) {
      // The flat end's handle lies on its line in whole steps of it, so none shorter than the
      // shortest span: a handle of a unit on a line of long step slid the line's end away when
      // rounded (DejaVu Sans's ☫: a 0.8-unit handle on a line stepping 496 units, 24 units
      // off, and the contour kept unfaired).
      if (h < cutting_.shortest_span) continue;
      const std::optional<Cubic> c =
          g2_hermite_cubic_from_flat_end(start, end, free_start ? SegmentEnd::start : SegmentEnd::end, h);
      if (c && bends_as_a_span(*c)) out.push_back(*c);
    }
    return out;
  }

  // The cubics a span from pa to pb may be: the G2 Hermite cubics of its ends and, where one
  // end (`at_start`, `at_end`: the chain's own ends) is a corner, whose curvature binds nothing,
  // those that meet only the other end's curvature, the corner's handle tried at lengths
  // from short to the chord, or, with corners at both, the one nearest the path (its
  // points `lac`). Each of those must bend one way and turn horizontal or vertical only at its
  // ends, as the path between two nodes of the writeback does: fitted to a nearly straight
  // span, a free end's curvature otherwise took an S (DejaVu Sans a–z A–Z: 10 inflections
  // against the source's 4). With corners free, a–z A–Z rounded: EB Garamond's curvature
  // variation 0.96× → 0.91× of the source's, FreeSerif's 0.82× → 0.73×.
  std::vector<Cubic> span_cubics(const LacPoint& pa, const LacPoint& pb, bool at_start, bool at_end,
                                 const std::vector<Vec2>& lac) const {
    const HermiteEnd start{pa.point, pa.tangent, pa.curvature}, end{pb.point, pb.tangent, pb.curvature};
    std::vector<Cubic> out = g2_hermite_cubics(start, end);
    const bool free_start = at_start && corners_.start_corner, free_end = at_end && corners_.end_corner;
    if (!free_start && !free_end) return out;
    std::vector<Cubic> free;
    if (free_start && free_end) {
      if (const std::optional<Cubic> c = fit_cubic_with_end_tangents(pa.point, pa.tangent, pb.point, pb.tangent, lac))
        free.push_back(*c);
    } else {
      for (const double h : corner_handle_lengths(distance(pa.point, pb.point)))
        if (const std::optional<Cubic> c =
                g2_hermite_cubic_with_free_end(start, end, free_start ? SegmentEnd::start : SegmentEnd::end, h))
          free.push_back(*c);
    }
    for (const Cubic& c : free)
      if (bends_as_a_span(c)) out.push_back(c);
    return out;
  }

  // Where no cubic meets both ends' curvatures (a short, nearly straight span whose curvature
  // falls by a quarter while it turns 2°: DejaVu Sans's Q tail, 30 units), the one that meets
  // one end's and comes nearest the other's, bending one way: one jump, the least, where G1
  // handles leave two. Of those meeting one end, the other end's handle at the lengths tried
  // for a corner.
  std::optional<Cubic> nearest_to_g2(const LacPoint& pa, const LacPoint& pb) const {
    const HermiteEnd start{pa.point, pa.tangent, pa.curvature}, end{pb.point, pb.tangent, pb.curvature};
    std::optional<Cubic> best;
    double least = infeasible;
    for (const SegmentEnd free : {SegmentEnd::start, SegmentEnd::end}) {
      const double wanted = free == SegmentEnd::start ? pa.curvature : pb.curvature;
      for (const double h : corner_handle_lengths(distance(pa.point, pb.point))) {
        const std::optional<Cubic> c = g2_hermite_cubic_with_free_end(start, end, free, h);
        if (!c || !bends_as_a_span(*c)) continue;
        const double got = node_curvature(*c, free);
        const double miss = std::abs(got - wanted) / std::max({std::abs(got), std::abs(wanted), 1e-300});
        if (miss < least) least = miss, best = c;
      }
    }
    return best;
  }

  // The places a span may be cut at, tried in this order: where the tangent runs along one of
  // the short grid directions (fine_), along one of those up to (3, 2) (all_), along one up to
  // (10, 0) (long_), or, with SpanCutting::evenly, at those and evenly along the span
  // (even_cuts). Each pass measures its pairs of places afresh, those of the passes before it
  // too: a span comes this far only where the shorter directions found no chain.
  enum class CutPlaces { short_directions, all_directions, long_directions, evenly };
  static constexpr std::array cut_places{CutPlaces::short_directions, CutPlaces::all_directions,
                                         CutPlaces::long_directions, CutPlaces::evenly};

  const std::vector<Vec2>& directions_of(CutPlaces places) const {
    return places == CutPlaces::short_directions ? fine_ : places == CutPlaces::all_directions ? all_ : long_;
  }

  struct Cut {
    double sigma;
    std::optional<Vec2> step;
    double turn_fraction = 0.0;  ///< of the span's turning, at a grid cut
  };

  // How coarsely whole grid steps set the curvature κ at a node whose handle is h long
  // (fair/handle_steps.hpp): κ = (2/3)·c/h², c the far handle's integer offset, so a step of
  // the far handle moves κ by about (2/3)·√2/(h²·|κ|) of itself and a step d of h by 2·|d|/h.
  // Where κ is flat (a line join) other means set it (handles_near_line): 0.
  double node_coarseness(const Cubic& c, SegmentEnd end, std::optional<Vec2> step) const {
    const double kappa = std::abs(node_curvature(c, end));
    if (kappa < flat_) return 0.0;
    const double h = end == SegmentEnd::start ? distance(c.p[0], c.p[1]) : distance(c.p[2], c.p[3]);
    return std::max((2.0 / 3.0) * std::sqrt(2.0) / (h * h * kappa), 2.0 * (step ? norm(*step) : 1.0) / h);
  }

  // The span as the fewest cubics whose inner nodes sit where the tangent runs along a grid
  // direction (so rounding keeps each node's handles collinear in whole steps) and, among as
  // few, the ones whose coarsest node the grid sets finest: a shortest path over the grid
  // nodes, by count and then by the coarsest node. The short directions first; the longer
  // ones only where no chain of short ones fits (CutPlaces). False when none fits.
  bool through_cut_places(Cut a, Cut b, std::vector<Piece>& pieces) const {
    std::vector<Cut> cuts;  // the last pass's grid cuts, which the even places join
    for (const CutPlaces places : cut_places) {
      if (places == CutPlaces::evenly && !cutting_.evenly) break;
      if (places == CutPlaces::evenly) {
        for (const Cut& c : even_cuts(a.sigma, b.sigma)) cuts.push_back(c);
        std::sort(cuts.begin(), cuts.end(), [](const Cut& x, const Cut& y) { return x.sigma < y.sigma; });
      } else {
        cuts = grid_cuts(a.sigma, b.sigma, directions_of(places));
      }
      std::vector<Cut> nodes{a};
      nodes.insert(nodes.end(), cuts.begin(), cuts.end());
      nodes.push_back(b);
      const std::size_t n = nodes.size();
      if (n == 2) continue;
      // best[j][c]: the finest chain of c cubics from the span's start to node j.
      struct Best {
        double coarsest = infeasible;
        std::size_t from = 0;
        std::optional<Cubic> cubic;
      };
      std::vector<std::vector<Best>> best(n, std::vector<Best>(n));
      best[0][0].coarsest = 0.0;
      for (std::size_t i = 0; i + 1 < n; ++i) {
        if (std::none_of(best[i].begin(), best[i].end(), [](const Best& b) { return b.coarsest < infeasible; })) continue;
        for (std::size_t j = i + 1; j < n; ++j) {
          if (i == 0 && j == n - 1) break;  // the whole span: the caller found it too far
          const Fitted f = best_cubic(nodes[i].sigma, nodes[j].sigma, nodes[i].step, nodes[j].step, far_off * budget_);
          // Far off, a longer cubic from i fares no better (where no G2 cubic exists, it may).
          if (f.deviation > far_off * budget_ && f.deviation < no_cubic) break;
          if (!f.within(budget_)) continue;
          // A node placed anywhere has its tangent off the axes: a cubic between such nodes may
          // cross one inside, which no node would mark (dkg's q: a stem 3° off the vertical).
          if (places == CutPlaces::evenly && inner_axis_extrema_of(*f.cubic).off_node > 0) continue;
          const double q = std::max(node_coarseness(*f.cubic, SegmentEnd::start, nodes[i].step),
                                    node_coarseness(*f.cubic, SegmentEnd::end, nodes[j].step));
          for (std::size_t c = 0; c + 1 < n; ++c) {
            const double via = std::max(best[i][c].coarsest, q);
            if (via < best[j][c + 1].coarsest) best[j][c + 1] = {via, i, f.cubic};
          }
        }
      }
      // The fewest cubics, or one more where that sets the coarsest node much finer.
      const std::vector<Best>& end = best[n - 1];
      std::size_t count = 0;
      while (count < n && end[count].coarsest == infeasible) ++count;
      if (count == n) continue;
      if (count + 1 < n && end[count].coarsest > fine_enough && end[count + 1].coarsest < 0.5 * end[count].coarsest) ++count;
      std::vector<Piece> chosen;
      for (std::size_t j = n - 1, c = count; j > 0; --c) {
        const Best& b = best[j][c];
        chosen.push_back({*b.cubic, nodes[j].step});
        j = b.from;
      }
      pieces.insert(pieces.end(), chosen.rbegin(), chosen.rend());
      return true;
    }
    return false;
  }

  // Where the tangent runs along one of `directions` strictly inside the span's turning and
  // not at its very ends, in order along the span.
  std::vector<Cut> grid_cuts(double a, double b, const std::vector<Vec2>& directions) const {
    const Vec2 ta = path_.at(a).tangent, tb = path_.at(b).tangent;
    const double turn = turning_angle(ta, tb);
    std::vector<Cut> out;
    if (std::abs(turn) < 1e-6) return out;
    for (const Vec2 d : directions) {
      // A whole step longer than a third of the span is longer than a node's handles there can
      // be: rounding sets them to none or far past their cubics (Quicksand's A: a node on (1, 9)
      // 4 units before a corner, its 2-unit handles set 9 units long, and the cubic to the
      // corner folded back 3 units, κ·UPM 95,000).
      if (norm(d) > (b - a) / 3.0) continue;
      const double rel = turning_angle(ta, d / norm(d));
      const double f = rel / turn;
      if (f <= edge_margin || f >= 1.0 - edge_margin) continue;
      const double sigma = path_.where_turned(a, b, rel);
      const double g = (sigma - a) / (b - a);
      if (g > edge_margin && g < 1.0 - edge_margin) out.push_back({sigma, d, f});
    }
    std::sort(out.begin(), out.end(), [](const Cut& x, const Cut& y) { return x.sigma < y.sigma; });
    return out;
  }

  // Evenly along a span, no closer than the shortest span: where no chain of grid nodes fits
  // (a long span turning too little for any grid direction), the places its fewest cubics may
  // meet, their nodes' directions left to rounding.
  std::vector<Cut> even_cuts(double a, double b) const {
    const int count = std::min(even_cut_count, static_cast<int>(std::floor((b - a) / cutting_.shortest_span)) - 1);
    std::vector<Cut> out;
    for (int k = 1; k <= count; ++k) out.push_back({a + (b - a) * k / (count + 1), std::nullopt});
    return out;
  }

  // Where a span no chain of grid nodes fits is halved: where the tangent runs along a grid
  // direction nearest the middle of its turning, else at the chain junction nearest the
  // middle of its length, else at the middle.
  Cut fallback_cut(double a, double b) const {
    std::optional<Cut> nearest_half;
    double off = 0.3;
    for (const Cut& c : grid_cuts(a, b, all_))
      if (std::abs(c.turn_fraction - 0.5) < off) off = std::abs(c.turn_fraction - 0.5), nearest_half = c;
    if (nearest_half) return *nearest_half;
    const double mid = 0.5 * (a + b), width = b - a;
    double cut = mid, nearest = 0.3 * width;
    for (std::size_t i = 1; i < path_.segment_count(); ++i)
      for (const double offset : {0.0, path_.total()}) {
        const double j = path_.segment_start(i) + offset;
        if (std::abs(j - mid) < nearest) nearest = std::abs(j - mid), cut = j;
      }
    return {cut, std::nullopt};
  }

  const ChainPath& path_;
  double budget_;
  double flat_;
  SpanCutting cutting_;
  ChainEnds corners_;
  ChainCubics& out_;
  // The short directions first; up to (3, 2) where none of them is near a span's middle.
  std::vector<Vec2> fine_ = grid_directions(5), all_ = grid_directions(13), long_ = grid_directions(100);
  std::vector<ChosenCurvature> chosen_;  ///< the nodes whose curvature is not the path's
  std::vector<PathFit> path_fits_;       ///< spans whose nodes keep the path's curvature
};

// The cubics of the spans between consecutive required nodes, in order (a closed chain's last
// span runs on past its seam, `total`, to the first node).
std::vector<Piece> write_spans(SpanWriter& writer, std::span<const RequiredNode> nodes, bool closed, double total) {
  std::vector<Piece> pieces;
  const std::size_t n = nodes.size(), spans = closed ? n : n - 1;
  for (std::size_t i = 0; i < spans; ++i) {
    const RequiredNode& next = nodes[(i + 1) % n];
    const double b = i + 1 < n ? next.sigma : next.sigma + total;
    writer.fit(nodes[i].sigma, b, nodes[i].grid_step, next.grid_step, 0, pieces);
  }
  return pieces;
}

// An open chain's extremum next to its end at a corner, when turning the corner's tangent onto
// the extremum's axis (by at most snap_turn) writes the two spans on either side of the
// extremum as no more cubics, none with the extremum inside: the corner becomes the extremum
// (its handle along the axis) and the extremum's node goes. Corner and extremum a few units
// apart left a cubic so short that whole grid steps could only make it straight, against the
// curvature beyond it. A corner drawn that may not turn so keeps its tangent, and loses the
// extremum's node only where the two are one grid place across the axis; one too far off the
// axis to turn, only where they are also within a unit of each other. Where no cubic may
// carry an extremum off its nodes, the node goes only where the corner takes it.
void snap_extremum_to_corner(ChainPath& path, double budget, double flat_curvature, SpanCutting cutting,
                             ChainEnds corners, std::vector<RequiredNode>& nodes, SegmentEnd end) {
  const std::size_t n = nodes.size();
  const bool corner = end == SegmentEnd::start ? corners.start_corner : corners.end_corner;
  if (!corner || n < 3) return;
  const bool start = end == SegmentEnd::start;
  const std::size_t e = start ? 1 : n - 2, far = start ? 2 : n - 3;
  const std::size_t at = start ? 0 : n - 1;
  if (!nodes[e].grid_step || std::abs(nodes[e].sigma - nodes[at].sigma) > snap_reach) return;
  const Vec2 axis = *nodes[e].grid_step;
  const Vec2 tangent = path.at(nodes[at].sigma).tangent;
  const Vec2 from_corner = path.at(nodes[e].sigma).point - path.at(nodes[at].sigma).point;
  // An extremum within half a unit of the corner across its axis is the corner's on the grid:
  // where the corner keeps its tangent, its node goes, and the cubic to the corner carries it,
  // as the source draws it. As a node it left a cubic of a few units the grid could only
  // straighten, a jump against the curve before (Bonum's e: 4 units, 0.15 across; Quicksand's
  // v 0.16 under its baseline).
  const auto drop_within_one_grid_place = [&] {
    if (!cutting.no_inner_extrema && std::abs(cross(axis / norm(axis), from_corner)) < same_grid_place)
      nodes.erase(nodes.begin() + static_cast<std::ptrdiff_t>(e));
  };
  // Where no cubic may carry an extremum off its nodes (handwriting), the node stays, or, within
  // a unit of the corner, the corner takes it however it turns: turned onto the axis, its
  // cubic arrives along it (Delphine's F: 0.10 across but 0.55 along, dropped for its corner,
  // a cusp, the cubic leaning back 23° carried it 0.67 off the corner, 1.16 once rounded).
  const bool beside = cutting.no_inner_extrema && norm(from_corner) < 1.0;
  if (!beside && std::abs(turning_angle(tangent, axis)) > snap_turn) {
    // Too far off the axis to turn onto it, the corner keeps its tangent; an extremum within a
    // unit of it goes too, where rounding would put the two on one or neighbouring grid points
    // (Junicode's u: the bowl's extremum 0.68 units from the serif's corner, 12° off the level,
    // rounded into a 1-unit cubic whose handles zigzagged, κ·UPM 292 against 0 beyond it).
    // Farther, the cubic carrying it would leave it more than half a unit off its nodes.
    if (norm(from_corner) < 1.0) drop_within_one_grid_place();
    return;
  }
  // Nor a corner drawn turning by the kink limit or more (one the check counts) past its floor
  // (kept_corner_angle): a designed corner, not a stroke's end a degree off the axis.
  // Accanthis's serif tips turn by 14°, faired by 9°, and turned onto the axis were left a kink
  // the kink pass made smooth; TeX Gyre Bonum's e, Quicksand's v, w and M turn by 4.4° to 7.1°
  // (before stop 90 only corners drawn turning by snap_turn or more were kept so).
  const RunEnd& end_as_planned = start ? corners.start_run_end : corners.end_run_end;
  const bool drawn_as_corner = end_as_planned.beyond != Vec2{} &&
                               std::abs(turning_angle(end_as_planned.beyond, end_as_planned.tangent)) >=
                                   radians(kink_limit_deg);
  if (!beside && drawn_as_corner) {
    const double onto = angle_of(axis);
    const std::optional<double> kept = kept_corner_angle(end_as_planned, start, angle_of(tangent), onto);
    if (!kept || std::abs(wrapped_angle(*kept - onto)) > 1e-12) {
      drop_within_one_grid_place();
      return;
    }
  }
  ChainCubics trials;  // what the trial fits count is not the chain's
  SpanWriter writer(path, budget, flat_curvature, cutting, corners, trials);  // it reads the path as turned below
  const std::array<RequiredNode, 3> kept = start ? std::array{nodes[at], nodes[e], nodes[far]}
                                                 : std::array{nodes[far], nodes[e], nodes[at]};
  const std::size_t before = write_spans(writer, kept, false, path.total()).size();
  path.turn_end(end, axis / norm(axis));
  RequiredNode corner_node = nodes[at];
  corner_node.grid_step = axis;
  const std::array<RequiredNode, 2> snapped = start ? std::array{corner_node, nodes[far]} : std::array{nodes[far], corner_node};
  const std::vector<Piece> after = write_spans(writer, snapped, false, path.total());
  // Not where the extremum comes back inside a cubic (the path between turns away and back).
  const bool inside = std::any_of(after.begin(), after.end(), [](const Piece& p) { return inner_axis_extrema(p.cubic) > 0; });
  if (after.size() > before || inside) {
    path.turn_end(end, std::nullopt);
    return;
  }
  nodes[at] = corner_node;
  nodes.erase(nodes.begin() + static_cast<std::ptrdiff_t>(e));
}

// The axis extremum of `path` nearest its end `end`, within snap_reach of it.
std::optional<RequiredNode> extremum_near_end(const ChainPath& path, SegmentEnd end) {
  const std::vector<RequiredNode> extrema = axis_extrema(path);
  if (extrema.empty()) return std::nullopt;
  const RequiredNode e = end == SegmentEnd::start ? extrema.front() : extrema.back();
  const double from_end = end == SegmentEnd::start ? e.sigma : path.total() - e.sigma;
  if (from_end > snap_reach || from_end < 0.5) return std::nullopt;  // within half a unit it is the end
  return e;
}

// Turns an end onto an axis, which it takes as its step, and drops the node of the extremum
// next to it (the one extremum_near_end found: `nodes` are the chain's ends and extrema).
void turn_end_onto_axis(ChainPath& path, std::vector<RequiredNode>& nodes, SegmentEnd end, Vec2 axis) {
  path.turn_end(end, axis);
  const bool start = end == SegmentEnd::start;
  (start ? nodes.front() : nodes.back()).grid_step = axis;
  if (nodes.size() < 3) return;
  const std::size_t next = start ? 1 : nodes.size() - 2;
  const double from_end = start ? nodes[next].sigma : path.total() - nodes[next].sigma;
  if (nodes[next].grid_step == axis && from_end <= snap_reach) nodes.erase(nodes.begin() + static_cast<std::ptrdiff_t>(next));
}

}  // namespace

std::optional<Vec2> flat_inflection_axis(const FairedChain& before, const FairedChain& after, double budget) {
  if (before.closed || after.closed) return std::nullopt;
  const ChainPath b(before), a(after);
  const std::optional<RequiredNode> e1 = extremum_near_end(b, SegmentEnd::end), e2 = extremum_near_end(a, SegmentEnd::start);
  if (!e1 || !e2 || !e1->grid_step || e2->grid_step != e1->grid_step) return std::nullopt;
  // Turning one way onto the axis and back the other: an overshoot across an inflection.
  const LacPoint p1 = b.at(e1->sigma), p2 = a.at(e2->sigma);
  if (!(p1.curvature * p2.curvature < 0.0)) return std::nullopt;
  const Vec2 axis = *e1->grid_step, across{-axis.y, axis.x};
  if (std::abs(dot(p1.point - p2.point, across)) > budget) return std::nullopt;
  if (std::abs(turning_angle(b.at(b.total()).tangent, axis)) > snap_turn) return std::nullopt;
  return axis;
}

ChainCubics write_chain_as_cubics(const FairedChain& chain, double budget, double flat_curvature, ChainEnds ends,
                                  SpanCutting cutting) {
  ChainCubics out;
  ChainPath path(chain);
  const double total = path.total();
  std::vector<RequiredNode> nodes;
  if (!chain.closed) nodes.push_back({0.0, std::nullopt});
  for (const RequiredNode& e : axis_extrema(path)) nodes.push_back(e);
  if (!chain.closed) nodes.push_back({total, std::nullopt});
  std::sort(nodes.begin(), nodes.end(), [](const RequiredNode& a, const RequiredNode& b) { return a.sigma < b.sigma; });
  // An extremum within half a unit of another node is on that node already.
  std::vector<RequiredNode> distinct;
  for (const RequiredNode& n : nodes) {
    if (!distinct.empty() && n.sigma - distinct.back().sigma < 0.5) {
      if (n.sigma == total) distinct.back() = n;  // the chain's end stays exact
      continue;
    }
    distinct.push_back(n);
  }
  if (chain.closed && distinct.size() > 1 && distinct.front().sigma + total - distinct.back().sigma < 0.5) distinct.pop_back();
  // A closed chain needs two spans at least: one cubic cannot close on itself.
  if (chain.closed && distinct.empty()) distinct.push_back({0.0, std::nullopt});
  if (chain.closed && distinct.size() == 1) distinct.push_back({distinct.front().sigma + 0.5 * total, std::nullopt});

  if (!chain.closed) {
    if (ends.start_axis) turn_end_onto_axis(path, distinct, SegmentEnd::start, *ends.start_axis);
    if (ends.end_axis) turn_end_onto_axis(path, distinct, SegmentEnd::end, *ends.end_axis);
    snap_extremum_to_corner(path, budget, flat_curvature, cutting, ends, distinct, SegmentEnd::start);
    snap_extremum_to_corner(path, budget, flat_curvature, cutting, ends, distinct, SegmentEnd::end);
  }
  SpanWriter writer(path, budget, flat_curvature, cutting, chain.closed ? ChainEnds{} : ends, out);
  if (cutting.free_node_curvatures) writer.free_node_curvatures(distinct, chain.closed);
  const std::vector<Piece> pieces = write_spans(writer, distinct, chain.closed, total);
  // Nodes: the start of every cubic (and an open chain's last end); a node's grid step is the
  // end step of the cubic before it.
  const std::size_t m = pieces.size();
  for (std::size_t k = 0; k < m; ++k) {
    const Piece& prev = pieces[(k + m - 1) % m];
    OutlineNode node;
    node.point = pieces[k].cubic.p[0];
    node.out_handle = pieces[k].cubic.p[1];
    if (chain.closed || k > 0) {
      node.in_handle = prev.cubic.p[2];
      node.grid_step = prev.end_step;
    } else {
      node.grid_step = distinct.front().grid_step;
    }
    out.nodes.push_back(node);
  }
  if (!chain.closed) {
    OutlineNode last;
    last.point = pieces.back().cubic.p[3];
    last.in_handle = pieces.back().cubic.p[2];
    last.grid_step = pieces.back().end_step;
    out.nodes.push_back(last);
  }
  return out;
}

}  // namespace gf
