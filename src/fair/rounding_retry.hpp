// Rounding again after the rounded contour strayed past the tolerance: where it strayed, the
// cubics there get half their allowance; the rest keep theirs. Halving every cubic's had
// FreeSerif's and EB Garamond's contours rounded on half their allowance for one serif's stray,
// and their G2 went with it (docs/fairing.md, stop 56).
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "fair/handle_steps.hpp"

namespace gf {

/// The cubics at and beside each segment whose distance from the source (`by_segment`, the
/// rounded contour's segments in order, a closed contour's wrapping) exceeds `tolerance_units`,
/// ascending, each once. None where the segments are not the `cubics` the allowances follow
/// (rounding merged nodes), nor where none strays.
std::vector<std::size_t> cubics_about_strays(std::span<const double> by_segment, double tolerance_units,
                                             std::size_t cubics);

/// Halves the allowance of the cubics `strayed` names; of every cubic (and the default) where it
/// names none.
void halve_allowances(HandleStepLimits& limits, std::span<const std::size_t> strayed);

}  // namespace gf
