// A faired run's G2 chains re-expressed as G3 spirals (issue 6; docs/g3.md): over the whole
// run first (fair/g3_run.hpp), in three attempts, then piece by piece (fair/g3_local.hpp).
#pragma once

#include "fair/contour_plan.hpp"
#include "fair/faired_run.hpp"
#include "fair/run_reference.hpp"

namespace gf {

/// The run made G3 in full by the first of three attempts that does it:
/// - Fritsch–Butland κ′ (g3_run.hpp's SlopeRule), cut at equal lengths;
/// - the same, but cut where κ changes fast too once a solve stalls (a stall is mostly a spiral
///   whose cubic κ cannot follow a steep rise);
/// - that with the smooth mean, whose Newton does not stall where a secant crosses zero (dkg's T).
/// A run the first meets is as it was (with the second first, many of Because We Learn's guided
/// runs, cut for their signs and then stalled, came out otherwise: 8 curvature extrema more in
/// all). The second and third are taken only where κ varies at most twice as much as along the
/// G2 curve (a run of Leckerli's F came out G3 varying 5.6 times as much, one of dkg's T 10.6
/// times; of the 521 runs of dkg the first attempt makes G3, 7 vary over 1.5 times as much, the
/// most 5.7). a–z A–Z, the smooth joins of the segments off G3: dkg Bold 193 → 23, dkg 18 → 10,
/// Ruf 57 → 9, Leckerli 17 → 0. None in full: the first attempt's partial G3, else G2 and why.
///
/// `zero_curvature`: |κ| under which κ counts no sign. `budget`: how far from `source` the G3
/// curve may lie.
void reexpress_as_g3(FairedRun& result, const RunReference& source, const SmoothRun& run, double budget,
                     double zero_curvature);

}  // namespace gf
