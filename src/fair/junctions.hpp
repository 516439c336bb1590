// Where a smooth run is cut into log-aesthetic segments (seed 001 §3, lac-math.md §4.1): at
// its inflections and curvature extrema, simplified as the seeds do. Curvature is read as
// the mean over a window (wobbles shorter than the window are not features); a lobe between
// two inflections that stays within half the tolerance of its chord is a wobble and merges
// with its neighbours; each lobe keeps one curvature extremum between zero-curvature ends
// and, towards a corner, only the extrema that stand out; no piece turns by more than 90°.
#pragma once

#include <vector>

#include "fair/fair_options.hpp"
#include "fair/run_reference.hpp"

namespace gf {

enum class JunctionKind { run_end, inflection, extremum, split };

struct Junction {
  double s;
  JunctionKind kind;
  bool operator==(const Junction&) const = default;
};

/// Orders junctions along the run.
inline bool earlier(const Junction& a, const Junction& b) { return a.s < b.s; }

struct JunctionOptions {
  double window_units;
  double tolerance_units;
  double extremum_prominence;  ///< a curvature extremum is kept when it stands out by this fraction of its lobe's peak
  double max_turning_rad;
  /// Every lobe between two κ = 0 ends that turns through most of a half turn is cut as an
  /// arc (at quarters of its turning), not at its curvature peak: a retry for runs whose
  /// peak lies too near a line for a transition to reach it.
  bool arcs_by_turning = false;
};

JunctionOptions junction_options(const FairSettings& settings);

/// Ascending in s; an open run's ends are run_end junctions at 0 and length(); a closed run
/// has no ends. `zero_curvature_start/end`: the run meets a line there (κ = 0 at the end).
std::vector<Junction> select_junctions(const RunReference& run, bool zero_curvature_start, bool zero_curvature_end,
                                       const JunctionOptions& options);

}  // namespace gf
