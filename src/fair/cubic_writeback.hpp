// A faired chain of log-aesthetic segments written back as cubic Béziers: on-curve nodes at
// the chain's ends (corners, inflections, line joins) and at every horizontal and vertical
// extremum; between them as few cubics as the budget allows, each the G2 Hermite cubic of its
// ends (geom/g2_hermite.hpp), so curvature matches on both sides of every node (at a corner,
// whose curvature binds nothing, only the other end's is met). A span whose
// best cubic strays too far becomes the fewest cubics whose inner nodes sit where the tangent
// runs along a grid direction, the shortest first (a shortest path over those places), and
// among as few the ones whose coarsest node rounding can set finest, span ends included.
#pragma once

#include <optional>
#include <vector>

#include "fair/contour_plan.hpp"
#include "fair/faired_run.hpp"
#include "fair/outline_nodes.hpp"

namespace gf {

struct ChainCubics {
  std::vector<OutlineNode> nodes;  ///< an open chain's first and last nodes carry only their inner handle
  /// Spans where no G2 Hermite cubic existed within the depth limit: written meeting one end's
  /// curvature and nearest the other's where a cubic bending one way can, else with G1 handles.
  int g1_fallbacks = 0;
  /// Nodes whose curvature the writeback moved off the path's (SpanCutting::free_node_curvatures).
  int freed_nodes = 0;
};

/// Which ends of an open chain are corners. A corner's curvature binds nothing, so a span from
/// one need only meet the curvature at its other end (fewer cubics where the G2 Hermite cubic
/// strays). And its tangent the writeback may turn a little: an extremum a few units from a
/// corner (a stroke's end a degree off the vertical) would leave a cubic too short for the
/// grid to set its curvature, so the corner's tangent is turned onto the axis instead and the
/// extremum is the corner (where that takes no more cubics).
struct ChainEnds {
  bool start_corner = false, end_corner = false;
  /// At a corner end, the run's end as planned (its drawn tangent and the piece beyond): a
  /// corner drawn turning by snap_turn or more keeps the turn kept_corner_angle keeps.
  RunEnd start_run_end{}, end_run_end{};
  /// An end at an inflection turned onto this axis (flat_inflection_axis): its tangent along
  /// it, κ = 0, and the axis extremum next to it dropped.
  std::optional<Vec2> start_axis, end_axis;
};

/// Where chain `before` ends and chain `after` starts at an inflection, each turning onto the
/// same axis within snap_reach of it at points no farther apart across the axis than the
/// writeback's budget (a tip's turn overshooting the horizontal by a degree before the bowl:
/// Lato's and Carlito's j, 0.9 and 1.2 units): that axis, along `before`'s travel. Rounding
/// puts both extrema on one grid line or two and flattens the cubics between, against the
/// curvature of the turns beside them; turned onto the axis, the inflection is the one
/// extremum, flat.
std::optional<Vec2> flat_inflection_axis(const FairedChain& before, const FairedChain& after, double budget_units);

/// A span shorter than this (units) is one cubic, within the budget or not: halves of it would
/// round onto the same few grid points.
inline constexpr double shortest_span_units = 4.0;

/// How a span that no cubic fits within the budget, nor a chain of cubics through nodes where
/// the tangent runs along a grid direction up to (10, 0), is cut.
struct SpanCutting {
  /// A span shorter than this (units) is one cubic: as shortest_span_units, for this call.
  double shortest_span = shortest_span_units;
  /// Into the fewest cubics through those nodes and places evenly along it, their nodes'
  /// directions left to rounding; else halved, and each half fitted again. The places serve
  /// handwriting, whose long scanned strokes turn too little for any grid direction and were
  /// halved into cubics each bending its own way (a–z A–Z rounded: Breip's inflections 0.404×
  /// → 0.387× of the source's, dkg's 0.271× → 0.242×; nodes Breip 0.598× → 0.574×, Because We
  /// Learn 1.055× → 0.998×). Not on text, whose tolerance leaves rounding half a unit: such
  /// nodes, on no grid direction, round to one a few tenths of a degree off, and the longer
  /// cubics took more g2-jumps (EB Garamond a–z A–Z 100 → 117, Gentium Plus 9 → 12).
  bool evenly = false;
  /// No cubic that crosses an axis inside, off its nodes: the path's extrema are nodes, so such
  /// a cubic wobbles where the path does not. Handwriting, whose budget of ten units or more
  /// let a long, nearly level guide span of Femke Klaver's Z come out as one S-shaped cubic
  /// with two extrema inside (2 units deep over 765). Not on text, whose rounding moves such
  /// an extremum onto its node or off the cubic; turned away there, Gentium Plus's M took a
  /// node more and a g2-jump.
  bool no_inner_extrema = false;
  /// The curvature at an extremum inside the chain may move off the path's where the two spans
  /// beside it then fit whole, so a span whose G2 cubic strays is not cut at all
  /// (fair/node_curvatures).
  bool free_node_curvatures = false;
  /// Of the budget, what a span whose end curvatures were so moved may use. A G3 chain's
  /// cubics are solved again for G3 within what each leaves of the tolerance
  /// (fair/g3_cubics): fitted to the edge of the budget, Cantarell's S (1,000 units to the em,
  /// rounded) had none of its runs come out G3; at half, each did.
  double freed_span_budget_share = 1.0;
};

/// `flat_curvature`: below it a node's curvature counts as zero (a line join), not as a
/// curvature the grid must set finely.
ChainCubics write_chain_as_cubics(const FairedChain& chain, double budget_units, double flat_curvature,
                                  ChainEnds ends = {}, SpanCutting cutting = {});

}  // namespace gf
