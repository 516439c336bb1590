// G3 carried into the written cubics (--continuity g3): the writeback's G2 Hermite cubics match
// κ at every smooth node but leave dκ/ds to fall where it may (a jump near 100 % at most nodes).
// Each run of cubics joined at smooth nodes is solved again as a G3 cubic spline: its inner
// nodes may move and, off the grid directions, turn; every handle length is free; κ stays
// continuous (0 at inflections and line joins) and dκ/ds is asked to match, more strongly step
// by step, while every cubic stays within its allowance of the one it replaces and gains no
// inflection, horizontal/vertical extremum, loop, cusp or overreaching handle. Where the run
// cannot be G3 within that, its worst cubic is cut in two (a node more, within the contour's
// budget) and the run solved again; a run that still cannot keeps the most G3 state that
// stayed within.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "fair/outline_nodes.hpp"

namespace gf {

struct G3CubicSettings {
  /// |κ| (1/unit) below which a node counts as flat: an inflection, or a line join's κ = 0.
  double flat_curvature = 5e-4;
  /// How many nodes the contour may gain by cuts.
  int node_budget = 0;
};

struct G3CubicReport {
  int runs = 0;         ///< runs of two or more cubics joined at smooth nodes
  int runs_g3 = 0;      ///< of them, those whose every dκ/ds jump came under 1e-4 (relative to the
                        ///< larger side, or to κ over the chord where both are near 0)
  int runs_moved = 0;   ///< those changed at all (G3 or nearer it)
  int nodes_added = 0;  ///< cuts made

  G3CubicReport& operator+=(const G3CubicReport& o) {
    runs += o.runs, runs_g3 += o.runs_g3, runs_moved += o.runs_moved, nodes_added += o.nodes_added;
    return *this;
  }
};

/// How many nodes a contour of `cubics` cubics and `nodes` nodes may gain by cuts: `share` of its
/// cubics, rounded to the nearest, but never past `most_share` times its source's
/// `source_nodes` (the fairing issue's bar, which the G3 output keeps too); none where the
/// contour is there already.
int g3_node_budget(std::size_t cubics, std::size_t nodes, std::size_t source_nodes, double share, double most_share);

/// Makes the smooth runs of `nodes` as G3 as each allows. `allowance_by_cubic[i]`: how far
/// (units) the cubic from node i may move; missing entries allow nothing.
G3CubicReport make_cubics_g3(std::vector<OutlineNode>& nodes, bool closed, std::span<const double> allowance_by_cubic,
                             const G3CubicSettings& settings);

}  // namespace gf
