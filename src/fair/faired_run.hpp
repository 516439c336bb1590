// What fairing a smooth run gives: chains of log-aesthetic segments (or G3 spirals, or
// stretches of the run's smoothing guide) in order along the run, and how far it came from the
// source (fair/run_fairing.hpp makes them; fair/path_piece.hpp reads them as one curve).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "aesthetic/log_aesthetic_segment.hpp"
#include "aesthetic/polynomial_spiral.hpp"
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

}  // namespace gf
