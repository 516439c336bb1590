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

}  // namespace gf
