// The band a faired contour must stay in: every point within `bound` of the source and every
// source point within `bound` of it (the two-sided Hausdorff distance), answered piece by piece
// so that one piece can be replaced and checked on its own.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "geom/polyline_distance.hpp"
#include "geom/vec2.hpp"

namespace gf {

/// Each source point answers to the piece of the faired contour nearest it. A replacement for
/// piece i holds when its own points lie within `bound` of the source polyline and the source
/// points that answer to piece i lie within `bound` of it. Replacements that all hold keep the
/// whole contour within `bound` of the source both ways: a source point is no farther from the
/// contour than from its own piece. This is the exact test that the triangle inequality
/// (a piece moved by at most the bound less its own distance) only bounds from above.
class ToleranceBand {
 public:
  /// `source`: the source polyline, in order along its contour (closed where its last point is
  /// its first); `answers[k]`: the faired piece source point k answers to (nearest_pieces of the
  /// faired contour sampled, as distance_by_piece takes them).
  ToleranceBand(std::span<const Vec2> source, std::span<const NearestPiece> answers, double bound);

  double bound() const { return bound_; }

  /// Whether `replacement` (a polyline through the new piece, dense enough that its chords
  /// stay within a small part of the bound of the curve) keeps piece `piece` within the band.
  /// Its own points are measured against the stretch of source around the points that answer
  /// to the piece and `stretch_pad` bounds of it either way: never nearer than the whole
  /// source, so a replacement that holds so holds.
  bool holds(std::size_t piece, std::span<const Vec2> replacement) const;

  /// As holds, but the source points that answer to the piece may lie within `bound` of
  /// `along` instead: the replacement with the unchanged pieces beside it spliced on, where a
  /// node slid along the contour hands some of them to its neighbour.
  bool holds_along(std::size_t piece, std::span<const Vec2> replacement, std::span<const Vec2> along) const;

  static constexpr double stretch_pad = 16.0;

 private:
  std::vector<std::vector<Vec2>> answering_;  ///< per piece, the source points nearest it
  std::vector<std::vector<Vec2>> stretch_;    ///< per piece, the source polyline around them
  double bound_;
};

}  // namespace gf
