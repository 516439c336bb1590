// Distances between sampled curves: the directed Hausdorff
// distance max_{p ∈ from} min_{q ∈ to} |p − q| with `to` taken as the polyline through its
// points (so the bound does not depend on how densely `to` was sampled along straight parts).
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <utility>
#include <vector>

#include "geom/vec2.hpp"

namespace gf {

/// max over `from` of the distance to the polyline through `to_polyline`; or, as soon as that
/// is known to exceed `stop_above`, some distance above it (for callers that only compare).
double directed_hausdorff(std::span<const Vec2> from, std::span<const Vec2> to_polyline,
                          double stop_above = std::numeric_limits<double>::infinity());

/// An axis-aligned box, for a lower bound on the distance to every segment inside it.
struct PolylineBox {
  Vec2 lo, hi;
  static PolylineBox of(Vec2 a, Vec2 b);
  PolylineBox with(Vec2 p) const;
  double squared_distance(Vec2 p) const;
};

/// A polyline with the boxes directed_hausdorff's search bounds its segments by, built once
/// for the many searches against one polyline (a cubic's samples against every candidate
/// that may replace it).
class BoxedPolyline {
 public:
  BoxedPolyline() = default;
  explicit BoxedPolyline(std::vector<Vec2> points);
  std::span<const Vec2> points() const { return points_; }
  /// Those of segments 0..i, then those of segments i..end.
  std::span<const PolylineBox> boxes() const { return boxes_; }

 private:
  std::vector<Vec2> points_;
  std::vector<PolylineBox> boxes_;
};

/// directed_hausdorff against a polyline whose boxes are built, the search for from's first
/// point starting at segment `first_segment` (where it likely lies nearest: the same answer,
/// found sooner).
double directed_hausdorff(std::span<const Vec2> from, const BoxedPolyline& to,
                          double stop_above = std::numeric_limits<double>::infinity(), std::size_t first_segment = 0);

/// A polyline bucketed on a uniform grid, for nearest-distance queries on long polylines
/// (whole contours): a query looks at rings of cells outwards until no nearer segment can be.
class PolylineGrid {
 public:
  PolylineGrid(std::vector<Vec2> polyline, double cell_size);
  const std::vector<Vec2>& points() const { return points_; }

  struct Nearest {
    double distance = 0.0;
    std::size_t segment = 0;  ///< from point `segment` to the next (0 for a single point)
  };
  Nearest nearest(Vec2 p) const { return search(p, -1.0); }
  /// The distance to the polyline where it is more than `floor`, else some distance no more
  /// than `floor`: the search stops at the first segment that near. What the largest distance
  /// over many points needs, exactly (Taha & Hanbury 2015's early break).
  double distance_past(Vec2 p, double floor) const { return search(p, floor).distance; }

 private:
  // The nearest segment, or the first found within `enough` (never, where it is negative).
  Nearest search(Vec2 p, double enough) const;
  std::pair<long, long> cell_of(Vec2 p) const;
  std::vector<Vec2> points_;
  double cell_;
  Vec2 origin_;
  long columns_ = 1, rows_ = 1;
  std::vector<std::vector<std::uint32_t>> cells_;  ///< segment indices per cell
};

/// max over `from` of the distance to the polyline in `to`; past `stop_above`, only some
/// distance past it.
double directed_hausdorff(std::span<const Vec2> from, const PolylineGrid& to,
                          double stop_above = std::numeric_limits<double>::infinity());

/// For each of `points`, the piece of a curve sampled piece by piece (`piece_of[k]`: the piece
/// whose stretch of polyline point k starts) that lies nearest it, and how far: the piece the
/// point answers to.
struct NearestPiece {
  std::size_t piece = 0;
  double distance = 0.0;
};
std::vector<NearestPiece> nearest_pieces(const PolylineGrid& curve, std::span<const std::size_t> piece_of,
                                         std::span<const Vec2> points);

/// The two-sided distance between a curve sampled piece by piece and another polyline, piece by
/// piece: each piece's own points from the other, and the other's points that answer to it
/// (`other_nearest`, nearest_pieces(curve, piece_of, other.points())). The largest is the
/// Hausdorff distance; a piece moved by at most the bound less its own keeps the whole within
/// the bound (triangle inequality through the unmoved pieces).
std::vector<double> distance_by_piece(const PolylineGrid& curve, std::span<const std::size_t> piece_of,
                                      const PolylineGrid& other, std::span<const NearestPiece> other_nearest);

/// The same, the other's nearest pieces found here.
std::vector<double> distance_by_piece(const PolylineGrid& curve, std::span<const std::size_t> piece_of,
                                      const PolylineGrid& other);

}  // namespace gf
