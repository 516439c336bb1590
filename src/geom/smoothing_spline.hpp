// The fairest cubic B-spline within a distance of a point sequence: least squares plus
// λ·Σ|Δ³c|² over the control points, with λ as large as keeps every point within the
// tolerance. On uniform knots Δ³c is the spline's third derivative on a span, so the penalty is
// a discrete ∫|r'''|², which grows with the change of curvature: wobbles go first, the drawn
// shape stays. The fairing of handwriting builds on it (seed 000 [0038]–[0045] fits a spline
// to the pen's points; this one also smooths them). The sparse penalty approaches λ·Σ|Δ³c|
// instead (the L1 norm, as in L1 trend filtering): the change of curvature gathers in few
// spans, so fewer curvature extrema and inflections survive the same tolerance.
#pragma once

#include <optional>
#include <span>

#include "geom/bspline_fit.hpp"

namespace gf {

enum class SmoothingPenalty {
  squared,  ///< λ·Σ|Δ³c|²
  sparse,   ///< λ·Σ|Δ³c|, by two rounds of reweighted least squares
};

struct SmoothingEnds {
  /// Held when given (open sequences only), and left forwards: a control on the tangent line
  /// that would lie behind the end point or within a twelfth of a span's length of it is put
  /// a third of a span's length ahead, so the curve cannot follow points that double back
  /// there and hook round.
  std::optional<Vec2> start_tangent, end_tangent;
  /// Where a tangent is held, κ = 0 there too: the next control is held on the tangent line as
  /// well (r'' along r'), as a curve leaving a line with κ = 0 does. Only on a spline of three
  /// spans or more, whose two ends then hold different controls.
  bool straight_ends = false;
};

/// Lobes of the curvature (stretches where it keeps one sign) that turn less than
/// `least_turning` (radians) are merged into their neighbours, smallest first, where the spline
/// can bend their way there (by at least `least_curvature`, 1/unit) within 5 % past the
/// tolerance: a scanned stroke's wobble across its straight line costs two inflections
/// wherever the least smoothing within the tolerance still follows it. 0: none merged.
struct LobeMerging {
  double least_turning = 0.0;
  double least_curvature = 0.0;
  bool operator==(const LobeMerging&) const = default;
};

/// `span_count` uniform spans (reduced when there are too few points). Open: clamped knots,
/// the end points interpolated. Closed (the first point not repeated at the end): periodic
/// knots, C2 everywhere, no seam. λ is found by bisection on log λ with the points'
/// parameters corrected to their feet on the curve; max_residual is the largest distance of a
/// point from the curve, above `tolerance` only when even the least smoothing exceeds it (or,
/// by up to 5 %, where lobes were merged).
BSplineFit fit_smoothing_spline(std::span<const Vec2> points, double tolerance, int span_count, bool closed,
                                const SmoothingEnds& ends = {},
                                SmoothingPenalty penalty = SmoothingPenalty::squared,
                                const LobeMerging& merging = {});

}  // namespace gf
