// G3 piece by piece (issue 6), for a run the whole-run solve (fair/g3_run.hpp) leaves G2: every
// node keeps the G2 curve's point, tangent and κ and takes one κ′ for both its sides; each piece
// between two nodes becomes the polynomial spiral, bumps included (aesthetic/polynomial_spiral.hpp),
// that meets both its ends' frames. No node moves, so no junction that cannot be met holds the
// others back; the bumps pay for the κ′ changed at the nodes. Where a spiral's κ turns back
// farther or changes sign more often than the G2 curve's between the same nodes, the caller cuts
// the piece in two: a shorter piece is nearer its own cubic κ(s).
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "aesthetic/polynomial_spiral.hpp"
#include "fair/g3_run.hpp"

namespace gf {

/// The G2 curve's κ′ on either side of a node (nullopt: no piece on that side).
struct NodeSlopes {
  std::optional<double> before, after;
};

/// How κ runs along a segment, from 33 samples: how far it turns back (Σ|Δκ| − |κ(end) −
/// κ(start)|, 0 where monotone) and how often it changes sign (|κ| under the zero given, or a
/// thousandth of the run's largest |κ| at its nodes, having no sign: less is noise).
struct SegmentShape {
  double turn_back = 0.0;
  int sign_changes = 0;
};

/// What the G2 curve gives the segments of g3_problem(pieces, run, cuts, …): every node's slopes
/// (a piece's own κ′ where it reports one, else, a guide's or a log-aesthetic inflection end's,
/// the difference of κ over a 64th of the piece on that side) and every segment's κ at 33
/// samples.
struct LocalTargets {
  std::vector<NodeSlopes> slopes;
  std::vector<std::vector<double>> curvatures;
};
LocalTargets local_targets(const RunPieces& pieces, std::span<const std::vector<double>> cuts, bool closed);

/// The κ′ a node's two sides share: 0 at a line end (G3 with the line); a corner end's own; inside,
/// the harmonic mean of the two sides (at most twice the smaller, as the whole-run solve's rule),
/// 0 where they differ in sign (an extremum of κ at the node).
double shared_slope(G3NodeKind kind, NodeSlopes slopes);

struct LocalG3 {
  std::vector<std::optional<PolynomialSpiral>> spirals;  ///< per segment; nullopt where none keeps the piece's shape
  std::vector<CurvatureEnd> ends;                        ///< every node, κ′ the shared one
  bool ok() const;
  /// The spirals, all of them found (ok()).
  std::vector<PolynomialSpiral> found() const;
};

/// Each segment of `problem` fitted on its own between its nodes' frames: kept where the fit
/// converges and its κ turns back no farther, plus a thousandth of the run's largest |κ| at its
/// nodes, and changes sign no more often (SegmentShape) than the G2 curve's there. A line end
/// that gives no such spiral slides along its line.
LocalG3 fit_g3_locally(const G3Problem& problem, const LocalTargets& targets, double zero);

}  // namespace gf
