// One chain of log-aesthetic segments on a span of a run's junctions (seed 001 §3; lac-math.md
// §4.1, §6.1): built on the span's points and tangents, made drawable, G2 by rotating its
// junction tangents, and measured against the source piece by piece. What it lacks (junctions
// to add or drop) it says, for the run's next round of refinement (fair/run_fairing).
#pragma once

#include <map>
#include <optional>
#include <utility>
#include <vector>

#include "fair/contour_plan.hpp"
#include "fair/fair_options.hpp"
#include "fair/faired_run.hpp"
#include "fair/junctions.hpp"
#include "fair/run_reference.hpp"

namespace gf {

/// α of each piece of a run's reference from its LCG, estimated once: a round of refinement
/// solves again only the spans whose junctions changed, and most of their pieces are pieces of
/// the round before (DejaVu Sans: one estimate in two was a repeat).
class PieceAlphas {
 public:
  explicit PieceAlphas(const RunReference& ref) : ref_(ref) {}
  double operator()(double s0, double s1);

 private:
  const RunReference& ref_;
  std::map<std::pair<double, double>, double> known_;
};

/// The junctions one chain runs over, by arc length along the run's reference, and whether it
/// ends with κ = 0 (at an inflection or a line).
struct ChainSpan {
  std::vector<double> s;  ///< arc lengths of its points (increasing; may pass L on a closed run)
  bool closed = false;
  bool zero_start = false, zero_end = false;
  bool operator==(const ChainSpan&) const = default;
};

/// The spans of `junctions` along the run: one closed span for a closed run without
/// inflections, else one open span between consecutive inflections (and the run's ends), each
/// κ = 0 where it meets an inflection or a line.
std::vector<ChainSpan> chain_spans(const std::vector<Junction>& junctions, const RunReference& ref, const SmoothRun& run);

/// A chain faired on a span, or what the span needs first.
struct ChainOutcome {
  std::optional<FairedChain> chain;
  std::vector<double> cuts;   ///< arc lengths where the chain needs another junction
  std::vector<double> drops;  ///< junctions (by arc length) the chain cannot use
  double deviation = 0.0;
  bool too_far = false;  ///< some piece strayed farther than the budget (else the cuts are for G2 or drawability)
  bool adjusts() const { return !cuts.empty() || !drops.empty(); }
};

/// The tangent an open span holds at its end s: the run's own at the run's ends (a line's, or
/// the guide's at a corner), else an inflection's, averaged over the window.
Vec2 end_tangent_of(double s, const RunReference& ref, const SmoothRun& run, double w);

/// The chain on `span` of `ref` within `budget` of `source`: `guided` where ref is the run's
/// smoothing guide, source the run itself (else both are the source). Once `accept_mismatch`, a
/// chain whose G2 solve stalls is kept with its best angles where `keep_stalled`, else gives
/// way (to the guide on a guided run, else to the next RunBasis). κ = 0 ends may leave their
/// lines earlier where `leave_lines`.
ChainOutcome fair_chain(const ChainSpan& span, const RunReference& ref, PieceAlphas& alphas, const RunReference& source,
                        bool guided, const SmoothRun& run, const FairSettings& settings, double budget,
                        bool accept_mismatch, bool keep_stalled, bool leave_lines);

}  // namespace gf
