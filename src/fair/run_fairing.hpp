// One smooth run rebuilt as log-aesthetic segments (seed 001 §3; lac-math.md §4.1, §6.1):
// cut at the selected junctions, α per piece from its LCG (the nearest drawable α when that
// one has no solution), G2 by rotating the junction tangents, and pieces that stray farther
// than the budget from the source cut again and refitted.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "aesthetic/log_aesthetic_segment.hpp"
#include "aesthetic/polynomial_spiral.hpp"
#include "fair/contour_plan.hpp"
#include "fair/fair_options.hpp"
#include "fair/run_reference.hpp"

namespace gf {

/// A stretch of a run's smoothing guide between two frames: what a span of a handwriting run
/// becomes when no G2 chain of log-aesthetic segments within the budget exists for it. The guide
/// is C2, so the stretch is G2 throughout; its end frames are the ones its neighbouring chains
/// have, so the joins are G2 too.
struct GuideStretch {
  std::shared_ptr<const RunReference> guide;  ///< the whole run's guide, shared by its stretches
  double s0 = 0.0, s1 = 0.0;  ///< arc lengths along it (s1 may pass the seam of a closed guide)
  LacPoint start, end;   ///< the frames at its ends (ignored when the stretch is the whole closed guide)
};

/// Consecutive segments with G2 junctions (when solved). Open chains end at the run's ends or
/// at inflections; a closed chain is the whole closed run.
struct FairedChain {
  std::vector<LogAestheticSegment> segments;
  std::vector<PolynomialSpiral> spirals;  ///< G3 (fair/g3_run.hpp): instead of segments, with the same ends
  std::optional<GuideStretch> guide;  ///< instead of segments, where no chain was found
  bool closed = false;
  bool zero_curvature_start = false, zero_curvature_end = false;
  double max_mismatch_relative = 0.0;  ///< max |Δκ| / max |κ| over its junctions
  bool slid_line_ends = false;  ///< a κ = 0 end left where the run met its line, along the line (which follows)

  /// Where it starts and ends, whichever curves carry it (spirals, segments or the guide).
  LacPoint start_frame() const;
  LacPoint end_frame() const;
};

struct FairedRun {
  std::vector<FairedChain> chains;  ///< in order along the run
  double deviation = 0.0;           ///< two-sided Hausdorff bound against the source run, font units
  int guide_stretches = 0;           ///< spans written from the guide (no chain within the budget)
  int g2_line_joins = 0;  ///< of a G3 run, line joins held to G2 (no room on the line for G3)
  std::string g3_shortfall;  ///< --continuity g3: why the run stayed G2
  bool ok = false;
  std::string reason;  ///< why not, when not

  /// Its chains are G3 spirals (--continuity g3): the G3 solve hands spirals to every chain or none.
  bool g3() const { return !chains.empty() && !chains.front().spirals.empty(); }
  /// Its ends may lie elsewhere along the lines it meets than the source's: G3 slid them, or a
  /// chain did.
  bool ends_moved() const {
    return g3() || (!chains.empty() && (chains.front().slid_line_ends || chains.back().slid_line_ends));
  }
};

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
