#include "geom/polyline_distance.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace gf {

namespace {

// Squared distances throughout, one square root at the end: the inner loops are the fairing's
// hottest.
double squared_distance_to_segment(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 d = b - a;
  const double len2 = dot(d, d);
  const double t = len2 > 0.0 ? std::clamp(dot(p - a, d) / len2, 0.0, 1.0) : 0.0;
  const Vec2 r = p - (a + d * t);
  return dot(r, r);
}

double squared_distance_to_polyline(Vec2 p, std::span<const Vec2> polyline) {
  if (polyline.size() == 1) return dot(p - polyline[0], p - polyline[0]);
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i + 1 < polyline.size(); ++i)
    best = std::min(best, squared_distance_to_segment(p, polyline[i], polyline[i + 1]));
  return best;
}

// An axis-aligned box, for a lower bound on the distance to everything inside it.
struct Box {
  Vec2 lo, hi;
  static Box of(Vec2 a, Vec2 b) { return Box{a, a}.with(b); }
  Box with(Vec2 p) const {
    return {{std::min(lo.x, p.x), std::min(lo.y, p.y)}, {std::max(hi.x, p.x), std::max(hi.y, p.y)}};
  }
  double squared_distance(Vec2 p) const {
    const double dx = std::max({lo.x - p.x, 0.0, p.x - hi.x});
    const double dy = std::max({lo.y - p.y, 0.0, p.y - hi.y});
    return dx * dx + dy * dy;
  }
};

}  // namespace

double directed_hausdorff(std::span<const Vec2> from, std::span<const Vec2> to_polyline, double stop_above) {
  const double stop2 = stop_above * stop_above;
  // A lone point (or polyline): every segment, without the boxes a search needs.
  if (to_polyline.size() < 2 || from.size() == 1) {
    double worst = 0.0;
    for (const Vec2 p : from) worst = std::max(worst, squared_distance_to_polyline(p, to_polyline));
    return std::sqrt(worst);
  }
  // Exact, with an early exit (Taha & Hanbury 2015): a point with any segment nearer than the
  // worst so far cannot raise it. Segments are tried outwards from the one nearest the
  // previous point, so along two curves traced the same way the exit comes at once; a
  // direction stops where the box of every segment left that way is no nearer than the
  // nearest found. Pieces between extrema run monotone in x and y, where those boxes are tight.
  const std::size_t segments = to_polyline.size() - 1;
  // Boxes of segments 0..i and i..end; on the stack for the short polylines of the rounding's
  // cubic checks (two calls per candidate), where two heap blocks cost as much as the search.
  constexpr std::size_t on_stack = 32;
  std::array<Box, 2 * on_stack> stack_boxes;
  std::vector<Box> heap_boxes(segments > on_stack ? 2 * segments : 0);
  Box* const boxes = segments > on_stack ? heap_boxes.data() : stack_boxes.data();
  const std::span<Box> before(boxes, segments), after(boxes + segments, segments);
  before[0] = Box::of(to_polyline[0], to_polyline[1]);
  for (std::size_t i = 1; i < segments; ++i) before[i] = before[i - 1].with(to_polyline[i + 1]);
  after[segments - 1] = Box::of(to_polyline[segments - 1], to_polyline[segments]);
  for (std::size_t i = segments - 1; i-- > 0;) after[i] = after[i + 1].with(to_polyline[i]);
  double worst = 0.0;
  std::size_t hint = 0;
  for (const Vec2 p : from) {
    double nearest = squared_distance_to_segment(p, to_polyline[hint], to_polyline[hint + 1]);
    std::size_t nearest_at = hint;
    // Segment i, unless everything from it on (`rest`) is no nearer; whether to go on.
    const auto visit = [&](std::size_t i, const Box& rest) {
      if (rest.squared_distance(p) >= nearest) return false;
      const double d = squared_distance_to_segment(p, to_polyline[i], to_polyline[i + 1]);
      if (d < nearest) nearest = d, nearest_at = i;
      return true;
    };
    bool up = hint + 1 < segments, down = hint > 0;
    for (std::size_t step = 1; nearest > worst && (up || down); ++step) {
      if (up) up = visit(hint + step, after[hint + step]) && hint + step + 1 < segments;
      if (down && nearest > worst) down = visit(hint - step, before[hint - step]) && hint - step > 0;
    }
    hint = nearest_at;
    worst = std::max(worst, nearest);
    if (worst > stop2) break;
  }
  return std::sqrt(worst);
}

PolylineGrid::PolylineGrid(std::vector<Vec2> polyline, double cell_size) : points_(std::move(polyline)), cell_(cell_size) {
  if (points_.empty()) return;
  Vec2 lo = points_[0], hi = points_[0];
  for (const Vec2 p : points_) lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)}, hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
  origin_ = lo;
  // No more than about 4096 cells, however small the cell asked for.
  cell_ = std::max({cell_, (hi.x - lo.x) / 64.0, (hi.y - lo.y) / 64.0, 1e-9});
  columns_ = static_cast<long>((hi.x - lo.x) / cell_) + 1;
  rows_ = static_cast<long>((hi.y - lo.y) / cell_) + 1;
  cells_.resize(static_cast<std::size_t>(columns_ * rows_));
  for (std::size_t i = 0; i + 1 < points_.size(); ++i) {
    const auto [c0, r0] = cell_of(points_[i]);
    const auto [c1, r1] = cell_of(points_[i + 1]);
    for (long r = std::min(r0, r1); r <= std::max(r0, r1); ++r)
      for (long c = std::min(c0, c1); c <= std::max(c0, c1); ++c)
        cells_[static_cast<std::size_t>(r * columns_ + c)].push_back(static_cast<std::uint32_t>(i));
  }
}

std::pair<long, long> PolylineGrid::cell_of(Vec2 p) const {
  const long c = std::clamp(static_cast<long>(std::floor((p.x - origin_.x) / cell_)), 0L, columns_ - 1);
  const long r = std::clamp(static_cast<long>(std::floor((p.y - origin_.y) / cell_)), 0L, rows_ - 1);
  return {c, r};
}

PolylineGrid::Nearest PolylineGrid::nearest(Vec2 p) const {
  if (points_.size() == 1) return {distance(p, points_[0]), 0};
  double best = std::numeric_limits<double>::infinity();  // squared
  std::size_t best_at = 0;
  const auto [pc, pr] = cell_of(p);
  // The query's own distance to the grid's box, so rings far outside start counting right.
  const long extent = std::max(columns_, rows_);
  for (long ring = 0; ring <= extent; ++ring) {
    for (long r = pr - ring; r <= pr + ring; ++r) {
      if (r < 0 || r >= rows_) continue;
      for (long c = pc - ring; c <= pc + ring; ++c) {
        if (c < 0 || c >= columns_) continue;
        if (std::max(std::abs(r - pr), std::abs(c - pc)) != ring) continue;
        for (const std::uint32_t i : cells_[static_cast<std::size_t>(r * columns_ + c)]) {
          const double d = squared_distance_to_segment(p, points_[i], points_[i + 1]);
          if (d < best) best = d, best_at = i;
        }
      }
    }
    // Every segment not yet seen lies in cells beyond this ring: at least `ring` cells from p's
    // (clamped) cell, and, for p inside the grid, beyond the nearest side of the block of cells
    // the ring closes, which adds p's distance to its own cell's side (often most of a cell:
    // DejaVu Sans a–z A–Z ran 8 % fewer instructions).
    const double left = p.x - (origin_.x + static_cast<double>(pc - ring) * cell_);
    const double right = origin_.x + static_cast<double>(pc + ring + 1) * cell_ - p.x;
    const double below = p.y - (origin_.y + static_cast<double>(pr - ring) * cell_);
    const double above = origin_.y + static_cast<double>(pr + ring + 1) * cell_ - p.y;
    const double reach = std::max(static_cast<double>(ring) * cell_, std::min({left, right, below, above}));
    if (best <= reach * reach) break;
  }
  return {std::sqrt(best), best_at};
}

std::vector<NearestPiece> nearest_pieces(const PolylineGrid& curve, std::span<const std::size_t> piece_of,
                                         std::span<const Vec2> points) {
  std::vector<NearestPiece> out;
  if (curve.points().empty()) return out;
  out.reserve(points.size());
  for (const Vec2 p : points) {
    const PolylineGrid::Nearest n = curve.nearest(p);
    out.push_back({piece_of[n.segment], n.distance});
  }
  return out;
}

std::vector<double> distance_by_piece(const PolylineGrid& curve, std::span<const std::size_t> piece_of,
                                      const PolylineGrid& other, std::span<const NearestPiece> other_nearest) {
  std::vector<double> d(piece_of.empty() ? 0 : *std::max_element(piece_of.begin(), piece_of.end()) + 1, 0.0);
  if (curve.points().empty() || other.points().empty()) return d;
  for (std::size_t k = 0; k < curve.points().size(); ++k)
    d[piece_of[k]] = std::max(d[piece_of[k]], other.distance_to(curve.points()[k]));
  for (const NearestPiece& n : other_nearest) d[n.piece] = std::max(d[n.piece], n.distance);
  return d;
}

std::vector<double> distance_by_piece(const PolylineGrid& curve, std::span<const std::size_t> piece_of,
                                      const PolylineGrid& other) {
  return distance_by_piece(curve, piece_of, other, nearest_pieces(curve, piece_of, other.points()));
}

double directed_hausdorff(std::span<const Vec2> from, const PolylineGrid& to) {
  double m = 0.0;
  for (const Vec2 p : from) m = std::max(m, to.distance_to(p));
  return m;
}

}  // namespace gf
