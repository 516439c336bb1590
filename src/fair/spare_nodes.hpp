// Nodes the writeback leaves that a designer would not draw: a smooth node between two cubics
// that is neither a horizontal or vertical extremum nor an inflection. The writeback puts one
// where a span's G2 Hermite cubic strays (fair/cubic_writeback) and between two log-aesthetic
// segments at a curvature extremum, though a cubic may well turn through such an extremum
// inside. One cubic through both, its handles and those of the cubic either side fitted again
// to the outline under G2 (geom/g2_handle_fit), often draws the two within the budget: Linux
// Libertine's D drew its counter's quarters in two cubics each, where the source draws one.
#pragma once

#include <cstddef>
#include <vector>

#include "fair/outline_nodes.hpp"
#include "fair/sampled_contour.hpp"

namespace gf {

struct SpareNodeLimits {
  double budget_units = 1.25;  ///< two-sided, from the source: what the outline may spend of the tolerance
  double units_per_em = 1000.0;
  /// Where the window of cubics fitted again ends at an inflection node and no fit with it
  /// as it stands is taken, the node's tangent may turn (up to 4°), the cubics beyond it
  /// fitted again too, κ = 0 there on both sides.
  bool turn_inflection_nodes = false;
  /// After the windows, each run of cubics between inflection nodes, corners and lines that
  /// keeps spare nodes fitted again whole to the source without them, the nodes inside it
  /// sliding along their tangents.
  bool fit_runs = true;
};

/// How many spare nodes went, and how many of them only with an inflection node's tangent
/// turned (0° among the turns: the cubics past it fitted again).
struct SpareNodeRemoval {
  int removed = 0, turned = 0;
  int in_runs = 0;  ///< of those removed, how many with their run fitted again whole
};

/// Whether node k of `nodes` is spare: smooth, between two cubics, its tangent on neither axis,
/// and its curvature on both sides of one sign and at least 0.05/UPM (not an inflection).
bool is_spare_node(const std::vector<OutlineNode>& nodes, bool closed, std::size_t k, double units_per_em);

/// Removes each spare node whose two cubics one cubic can draw: that cubic's handles, and
/// those of the cubic either side across a smooth node that is no inflection, fitted again to
/// the outline with κ continuous at every node they touch and the curvature beyond them kept.
/// Only where the cubics so changed gain no extremum, inflection, fold, overreach or crowded
/// handle (fair/shape_traits), take on at most three times their curvature variation and
/// 0.05/UPM, and the contour stays within the budget of `sampled_source`. Then, where `limits`
/// ask, each run of such cubics without its spare nodes left, fitted to the source under the
/// same limits. Tangents stay, but an inflection node's where `limits` let it turn; nodes stay,
/// but a run's inner ones slide along their tangents.
SpareNodeRemoval remove_spare_nodes(std::vector<OutlineNode>& nodes, bool closed, const SampledContour& sampled_source,
                                    const SpareNodeLimits& limits);

}  // namespace gf
