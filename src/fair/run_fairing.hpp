// One smooth run rebuilt as log-aesthetic segments (seed 001 §3; lac-math.md §4.1, §6.1):
// cut at the selected junctions, α per piece from its LCG (the nearest drawable α when that
// one has no solution), G2 by rotating the junction tangents, and pieces that stray farther
// than the budget from the source cut again and refitted.
#pragma once

#include "fair/contour_plan.hpp"
#include "fair/fair_options.hpp"
#include "fair/faired_run.hpp"

namespace gf {

/// What a text run is faired on. First its own outline, where a chain whose G2 solve stalls
/// fails the run; then, for a contour that could not be faired so, its smoothing guide (or, where
/// no guide comes within the budget, its own outline again where that comes G2); last,
/// for one that could not be faired on its guides either, its own outline again, a stalled
/// chain kept with the curvature jumps its junctions have left (the cubic writeback meets their
/// mean) while none exceeds the largest |κ| its segments' ends had before the solve. Kept with
/// its jumps at the first try, a stalled chain had left whole DejaVu Sans 2,253 g2-jumps and
/// 275 smooth nodes G1 only; Open Sans's k and v turned a 1.7° kink into ten segments of jumps.
/// Handwriting is always faired on its guide.
enum class RunBasis { own, guide, own_with_jumps };

/// The run faired within `budget_units` on `basis`.
FairedRun fair_run(const SmoothRun& run, const FairSettings& settings, double budget_units,
                   RunBasis basis = RunBasis::own);

}  // namespace gf
