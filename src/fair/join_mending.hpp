// The last pass over a rounded text contour: each smooth join whose curvature still jumps as the
// check counts it, or that still kinks, searched for on the grid around it with the contour
// measured exactly against the source. Rounding's own passes (fair/node_seats, fair/handle_steps)
// move one node or its handles at a time, each cubic within what its unrounded self leaves of
// the tolerance (the triangle inequality); here the join, its direction, its handles, the far
// handles of both its cubics and, where a curve meets a line, the line's end and the curve's far
// node move together, anywhere the whole contour stays within the tolerance of the source.
// Noto Serif's W: a curve leaving a (−8, 27) leg with κ·UPM 0.149, mended by its near handle two
// of the leg's steps long and its far node a unit over, turned to (−3, 7). Where no such move
// mends a line join and the curve runs on to another line within two cubics, the curve is
// redrawn as two cubics seated on both lines, their node anywhere along it (TeX Gyre Pagella's
// W); its second line may go, the curve then reaching that line's far corner along it. Where
// the curve runs on into a smooth node between cubics instead (an extremum), the cubic from the
// line is redrawn as two, the first running on along the line (Quicksand's x).
#pragma once

#include <cstddef>

#include "fair/outline_faults.hpp"
#include "fair/sampled_contour.hpp"
#include "geom/contour.hpp"

namespace gf {

struct JoinMendingLimits {
  double tolerance_units = 1.25;  ///< two-sided, from the source (the fairing's tolerance)
  double units_per_em = 1000.0;
  int node_reach = 2;            ///< grid units a join between two cubics may move either way
  int far_node_reach = 3;        ///< the same for a line join's curve's far node
  int line_slide_steps = 3;      ///< a line's end: whole steps of the line either way along it,
  int line_end_reach = 6;        ///< and, after a corner, grid points this far either way ...
  double line_end_offset = 0.6;  ///< ... within this of the line (units)
  int longest_step = 30;         ///< the longest component of a grid direction tried at a join
  int longest_line_step = 40;    ///< and of a line's primitive step a curve's handle is put on
  double most_turn_rad = 0.2;    ///< how far a join's direction may turn from its tangent
  int far_handle_reach = 3;      ///< whole steps a far handle may move either way
  std::size_t most_judged = 400; ///< candidates per join measured against the source, cheapest first
  /// Whether a curve from a line may be redrawn as two new cubics: seated on both lines where it
  /// runs on to another (mend_curve_between_lines), else into the node it reaches
  /// (mend_curve_from_line).
  bool curves_between_lines = true;
};

/// `rounded`, a closed contour on the integer grid, with each smooth join that jumps or kinks
/// as the check counts it (fair/outline_faults) mended where the search finds integer points
/// that hold G1 exactly and G2 within the check's rule there, break no join beside it that held,
/// add no inflection, H/V extremum, fold or overreach to the cubics they change, and keep the
/// contour within the tolerance of `sampled_source`. Returns how many joins it mended.
int mend_jumping_joins(Contour& rounded, const SampledContour& sampled_source, const JoinMendingLimits& limits);

/// A contour's faults once its joins are mended, and how many joins were.
struct MendedJoins {
  OutlineFaults faults;
  int mended = 0;  ///< 0: the contour as it was
};

/// `rounded`, whose faults as `counter` counts them are `faults`, with its jumping joins mended
/// (mend_jumping_joins) where that leaves fewer faults (fewer_faults), else as it was.
MendedJoins mend_where_fewer_faults(Contour& rounded, const OutlineFaults& faults, const FaultCounter& counter,
                                    const SampledContour& sampled_source, const JoinMendingLimits& limits);

}  // namespace gf
