// One smooth run rebuilt as log-aesthetic segments (seed 001 §3; lac-math.md §4.1, §6.1):
// cut at the selected junctions, α per piece from its LCG (the nearest drawable α when that
// one has no solution), G2 by rotating the junction tangents, and pieces that stray farther
// than the budget from the source cut again and refitted.
#pragma once

#include <string>
#include <vector>

#include "aesthetic/log_aesthetic_segment.hpp"
#include "fair/contour_plan.hpp"
#include "fair/fair_options.hpp"

namespace gf {

/// Consecutive segments with G2 junctions (when solved). Open chains end at the run's ends or
/// at inflections; a closed chain is the whole closed run.
struct FairedChain {
  std::vector<LogAestheticSegment> segments;
  bool closed = false;
  bool zero_curvature_start = false, zero_curvature_end = false;
  double max_mismatch_relative = 0.0;  ///< max |Δκ| / max |κ| over its junctions
};

struct FairedRun {
  std::vector<FairedChain> chains;  ///< in order along the run
  double deviation = 0.0;           ///< two-sided Hausdorff bound against the source run, font units
  bool ok = false;
  std::string reason;  ///< why not, when not
};

FairedRun fair_run(const SmoothRun& run, const FairSettings& settings, double budget_units);

}  // namespace gf
