// The faired nodes of a contour settled on the integer grid: rounded (fair/grid_rounding) where
// the float outline lies within the tolerance, on what it leaves of the tolerance cubic by
// cubic, and rounded again where that strays; and, on text under G2, the float cubics beside a
// curvature jump rounding left split in two and rounded again (fair/jump_splits).
#pragma once

#include <optional>
#include <vector>

#include "fair/fair_options.hpp"
#include "fair/outline_nodes.hpp"
#include "fair/sampled_contour.hpp"

namespace gf {

/// A faired outline as a contour, and its two-sided distance from the source (font units).
struct OutlineOnGrid {
  Contour contour;
  double deviation = 0.0;
};

/// `nodes` as a contour; on the grid (Rounding::integers) and within the tolerance of the
/// source, rounded. Where rounding strays past the tolerance it rounds again, with the lines'
/// ends within their allowance, then (`halving_allowances`) on halved allowances.
OutlineOnGrid settle_on_grid(const std::vector<OutlineNode>& nodes, bool closed, const SampledContour& sampled_source,
                             const FairSettings& settings, bool halving_allowances);

/// Where `rounded`, settle_on_grid's outline of `nodes` within the tolerance of `source`, keeps
/// a curvature jump, on text under G2 on the grid (FairSettings::split_beside_jumps): `nodes`
/// with the cubics beside each jump split, settled again; none where nothing was split, or that
/// strays or has no fewer faults than `rounded` (counted against `source` only then: most
/// splits stray or mend nothing, and counting for every contour cost whole DejaVu Sans 5 %).
std::optional<OutlineOnGrid> rounded_with_splits(const Contour& source, const std::vector<OutlineNode>& nodes,
                                                 const Contour& rounded, const SampledContour& sampled_source,
                                                 const FairSettings& settings, bool halving_allowances);

/// An outline's nodes with lines split, and their outline settled on the grid.
struct SplitOnGrid {
  std::vector<OutlineNode> nodes;
  OutlineOnGrid outline;
};

/// Where `rounded`, settle_on_grid's outline of `nodes`, keeps a kink at a curve's join to a
/// line within the tolerance of `source` (on text, where the kinks' splits give nothing, also
/// where it has faults and slid such a join along its line, no rounded node within 3 units of
/// it), or strays past it (at each join of a curve to a line where it stretched the curve's
/// handle then): `nodes` with each such line split where both its parts step short
/// (fair/line_splits.hpp; where it strayed or slid the join and the line has no such split,
/// its curve split beside it instead), each split kept where the float outline stays within
/// `available` of the source, settled again. None where nothing was split, or that strays, or
/// (where `rounded` did not) has no fewer faults than `rounded`, both counted as the last
/// passes leave them (fair/line_kinks.hpp, then fair/join_mending.hpp), or (at slid joins) has
/// more inflections.
std::optional<SplitOnGrid> rounded_with_line_splits(const Contour& source, const std::vector<OutlineNode>& nodes,
                                                    const OutlineOnGrid& rounded, const SampledContour& sampled_source,
                                                    const FairSettings& settings, double available,
                                                    bool halving_allowances);

}  // namespace gf
