// G3 for a whole smooth run (issue 6; docs/g3.md): after the G2 solve, every segment is
// re-expressed as a polynomial spiral whose κ(s) is the cubic Hermite of its end curvatures
// and curvature slopes (aesthetic/polynomial_spiral.hpp without bumps), and the junction
// frames are solved again so that each spiral meets the next junction.
//
// κ′ at a junction is not an unknown: it is a mean of the two neighbouring secant slopes
// (κ_{j+1} − κ_j) / L_j, 0 where they differ in sign (a curvature extremum): the
// Fritsch–Butland harmonic mean, or a smooth variant of it (SlopeRule). Both neighbours share
// it, so dκ/ds is continuous by construction, and every piece's κ(s) stays monotone (either
// mean is at most twice the smaller secant, inside the cubic Hermite's monotone region). Then
// the unknowns balance the end conditions, three per segment (the far end's point and tangent):
//
//   junction         unknowns                      held
//   smooth           tangent angle, κ              point
//   inflection       tangent angle, slide along    κ = 0
//                    its normal
//   held             tangent angle, slide along    κ, the G2 solve's (a smooth node the
//                    its normal                    solve would carry across 0, g3_reexpression)
//   corner (end)     κ                             point, tangent; κ′ the end secant
//   corner, held     tangent angle                 point, κ (the G2 solve's); κ′ the end secant
//   line (end)       slide along the line          tangent, κ = κ′ = 0 (G3 with the line)
//   line, G2 only    slide along the line          tangent, κ = 0; κ′ the end secant
//   every segment    its length L
//
// A G3 line join needs κ to rise from 0 with zero slope, which a curve leaving a short line (a
// straight stretch in the spine of an 's') may only do by sliding off more line than there is:
// such a run is solved again with its line joins held to G2, and then (fair/g3_reexpression)
// once more at G3 with the segments at those joins cut in two, a shorter first spiral leaving
// its line with the room the whole one lacked.
//
// Why the junctions move rather than only κ′ being forced on G2 frames: with point, tangent and
// κ held, a forced κ′ leaves each segment three unknowns for three end conditions, and on
// DejaVu Sans only 21 of 577 junctions came out (the spiral overshot or strayed); the patent
// moves junctions for the same reason.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "aesthetic/polynomial_spiral.hpp"
#include "fair/contour_plan.hpp"
#include "fair/faired_run.hpp"
#include "fair/path_piece.hpp"

namespace gf {

enum class G3NodeKind { smooth, inflection, held, corner, corner_held, line, line_g2 };

struct G3Node {
  Vec2 point;
  double tangent_angle;  ///< radians, unwrapped along the run
  double curvature;      ///< the G2 solve's (κ = 0 at inflections and line ends is imposed)
  G3NodeKind kind;
  double slide_room = 0.0;  ///< line ends: how far the node may slide into its line (the rest is the line's)
};

struct G3Result {
  std::vector<PolynomialSpiral> spirals;  ///< segment i from node i to i + 1 (wrapping on a closed run); empty on failure
  std::vector<CurvatureEnd> ends;         ///< every node as solved, κ′ included
  int iterations = 0;
  double residual = 0.0;  ///< max miss of a segment's far end: position over its chord, angle in radians
  std::string reason;     ///< why not, in one line
  bool ok() const { return !spirals.empty(); }
};

/// How κ′ at an inner junction follows from the secants a and b either side (0 where they differ
/// in sign, a curvature extremum). Both stay within the cubic Hermite's monotone region.
enum class SlopeRule {
  /// Fritsch–Butland: 2ab / (a + b), at most twice the smaller secant. Its derivative jumps
  /// where a secant crosses zero, and Newton may stall on a run whose secants do.
  harmonic_mean,
  /// 4a²b² / ((a + b)(a² + b²)): the same where a = b, at most 1.11 times the smaller secant,
  /// and rising from zero as a secant squared, so smooth where one crosses it.
  smooth_mean,
};

/// `nodes` and the starting `lengths` come from the G2 chain. Open runs: nodes.size() ==
/// lengths.size() + 1, the ends corner or line, the inner nodes smooth or inflection. Closed:
/// one node per segment, none of them an end. Newton on all unknowns at once with a sparse
/// finite-difference Jacobian and a backtracking line search.
G3Result make_g3(std::span<const G3Node> nodes, std::span<const double> lengths, bool closed,
                 SlopeRule rule = SlopeRule::harmonic_mean);

/// A run's G2 chains as one G3 problem: a node at every segment end (a guide stretch's pieces
/// counted as segments, fair/path_piece.hpp), an inflection where two chains meet, the run's
/// own ends corners or lines.
struct G3Problem {
  std::vector<G3Node> nodes;
  std::vector<double> lengths;
  std::vector<std::size_t> run_piece;         ///< per G3 segment, the run's segment or guide piece it came from
  std::vector<std::size_t> pieces_per_chain;  ///< the run's segments or guide pieces in each chain
  bool closed = false;
  SlopeRule slope_rule = SlopeRule::harmonic_mean;
};

/// make_g3 on the problem's nodes, lengths and slope rule.
G3Result make_g3(const G3Problem& problem);

/// Where a piece cut into n is cut: at equal arc lengths, or at equal steps of arc length and of
/// curvature walked together (so the cuts crowd where κ changes fast).
enum class CutPlacement { by_length, by_length_and_curvature };

/// Where `piece` is cut into n: n + 1 arc lengths from its start, 0 and its length included. By
/// length and curvature, at equal steps of (s / L + w(s) / w(L)) / 2, w(s) the curvature walked
/// up to s, Σ|Δκ| (64 samples, linear between them); where κ is constant, at equal lengths.
std::vector<double> cut_places(const PathPiece& piece, int n, CutPlacement placement);

/// A run's chains read as pieces: a log-aesthetic segment, or a guide stretch's piece (cut where
/// its curvature changes sign, every quarter turn and at its curvature extrema). They hold
/// references into the chains, which must outlive them.
struct RunPieces {
  std::vector<PathPiece> pieces;
  std::vector<bool> at_inflection;  ///< the piece starts at κ = 0: where its chain meets the one before, or a guide's κ changes sign
  std::vector<std::size_t> per_chain;
};

/// Nullopt when a chain has neither segments nor a guide, or there is no chain at all.
std::optional<RunPieces> run_pieces(const std::vector<FairedChain>& chains);

/// The G3 problem with piece i cut at `cuts[i]` (arc lengths from its start, 0 and its length
/// included), each node with the curve's own point, tangent and κ there; `equal_lengths`: the
/// lengths as the piece's length over the cuts (cut_places by length), else their differences.
G3Problem g3_problem(const RunPieces& pieces, const SmoothRun& run, std::span<const std::vector<double>> cuts,
                     bool equal_lengths);

/// `pieces[i]`: how many G3 segments the run's segment (or guide piece) i becomes (1 when not
/// given), cut where `placement` says with its own point, tangent and κ there: more freedom
/// where κ′ = 0 at an extremum would otherwise round the curvature's peak too wide, or where κ
/// rises steeply. Nullopt when there is no chain at all.
std::optional<G3Problem> g3_problem(const std::vector<FairedChain>& chains, const SmoothRun& run,
                                    std::span<const int> pieces = {},
                                    CutPlacement placement = CutPlacement::by_length);

/// The solved spirals handed back to the chains they came from, in place of their
/// log-aesthetic segments.
void adopt_spirals(std::vector<FairedChain>& chains, const G3Problem& problem, std::vector<PolynomialSpiral> spirals);

}  // namespace gf
