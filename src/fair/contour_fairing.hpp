// One contour faired end to end: planned into lines and smooth runs, every run rebuilt as G2
// log-aesthetic chains, written back as cubics, rounded to the grid, and measured against the
// source. A contour that cannot be faired within the tolerance is returned unchanged, with
// the reason: the fairing never loses the source's shape.
#pragma once

#include <string>
#include <vector>

#include "fair/fair_options.hpp"
#include "fair/faired_piece.hpp"
#include "fair/g3_cubics.hpp"
#include "fair/outline_faults.hpp"
#include "fair/run_fairing.hpp"
#include "geom/contour.hpp"

namespace gf {

struct ContourFairing {
  Contour contour;         ///< faired, or the source unchanged when `faired` is false
  bool faired = false;
  std::string reason;      ///< why the source was kept
  double deviation = 0.0;  ///< two-sided Hausdorff distance to the source, font units (measured)
  double max_curvature_mismatch = 0.0;  ///< of the log-aesthetic chains, relative
  int g1_nodes = 0;        ///< smooth nodes with G1 only: no G2 Hermite cubic was found for a span
  int guide_stretches = 0; ///< spans written from the smoothing guide: no G2 log-aesthetic chain within the budget
  /// What the runs that failed on their own outlines were faired on (text; own where none failed).
  RunBasis basis = RunBasis::own;
  int split_nodes = 0;     ///< nodes added where cubics beside a jump rounding left were split (fair/jump_splits.hpp)
  int mended_joins = 0;    ///< jumps and kinks rounding left, mended on the grid (fair/join_mending.hpp)
  int g3_runs = 0;         ///< --continuity g3: smooth runs that came out G3
  int g2_line_joins = 0;   ///< and their line joins held to G2 (no room on the line for G3)
  std::vector<std::string> g3_shortfalls;  ///< and why each other run stayed G2
  G3CubicReport g3_cubics;  ///< --continuity g3: how far the written cubics carry it (before rounding)
  /// Runs no chain fairs on any basis, kept as the source draws them while the rest of the
  /// contour is faired: where each starts, and why.
  std::vector<std::string> runs_as_drawn;
  FairedPieces pieces;     ///< the faired curve before the writeback (empty when kept)
};

/// `settings.rounding` as_source resolved on this contour alone (fair_glyph resolves it on
/// the whole glyph first, so that its contours agree).
ContourFairing fair_contour(const Contour& source, const FairSettings& settings);

/// Whether a fairing again of a contour, `again` with faults `again_faults`, replaces `kept`
/// with `kept_faults`: where it has fewer faults (fewer_faults), and, where splits beside the
/// jumps rounding left mended it (ContourFairing::split_nodes), only where its nodes without
/// those splits are no more than `kept`'s: the nodes a split adds are what the mend costs. And
/// where joins of it were mended on the grid (ContourFairing::mended_joins), only where it has
/// at most a node more than `kept` for each jump or kink fewer, or at most the fairing issue's
/// 1.3 times the `source_nodes` of the contour: a mend on a fairing of many more nodes (its spans
/// halved, the chain's share of the budget another) otherwise replaced one whose joins no mend
/// reached (Accanthis's c: 30 nodes against 21, of 10 in the source).
bool replaces_kept_fairing(const ContourFairing& again, const OutlineFaults& again_faults, const ContourFairing& kept,
                           const OutlineFaults& kept_faults, std::size_t source_nodes);

/// Two-sided Hausdorff distance between two contours, from dense samples of both.
double contour_distance(const Contour& a, const Contour& b);

}  // namespace gf
