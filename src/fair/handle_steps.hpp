// Whole-step handle lengths for a rounded outline, chosen so that curvature stays continuous
// across its smooth nodes (G2) and zero where a curve meets a line, while G1 stays exact.
//
// Every handle of a smooth node lies a whole number of steps of the node's primitive grid
// direction away from it, so the curvature at a cubic's end, κ = (2/3)·h/|P1 − P0|² with h
// the far handle's offset from the tangent line, takes only discrete values: a handle one
// step longer or shorter at either end of the cubic changes it. The lengths along each run
// of cubics joined at smooth nodes are chosen together (Viterbi over the cubics, the run's
// first cubic enumerated when the run closes on itself).
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>
#include <span>
#include <vector>

#include "fair/outline_nodes.hpp"
#include "geom/tolerance_band.hpp"

namespace gf {

struct HandleStepLimits {
  /// |κ| (1/unit) below which two curvatures are compared by their difference, not their
  /// ratio: a curve this flat has no visible curvature to match.
  double flat_curvature = 5e-4;
  /// How far (units) a cubic may move from its unrounded self to gain G2.
  double allowance = 0.5;
  /// The same for the cubic from each node, where given (what the unrounded outline leaves of
  /// the tolerance there); else `allowance` for every cubic.
  std::vector<double> allowance_by_cubic;
  /// Where given (not owned; it outlives the rounding), a cubic that moves farther than its
  /// allowance is still allowed where it stays within this band around the source, measured
  /// exactly rather than bounded by the triangle inequality (the unrounded cubic's own distance
  /// from the source plus the move): a far handle seated on its line moves a cubic most where
  /// the unrounded one lies nearest the source. DejaVu Serif's R: the seat moved its leg's
  /// curve 2.311 units against an allowance of 2.297. The source a shortened cubic leaves at a
  /// slid node may be covered by the unrounded cubic beside it (ToleranceBand::holds_along:
  /// Noto Sans's h, a slide the shoulder's G2 needs).
  const ToleranceBand* band = nullptr;
  /// Rounds of moving each node at or beside a jump that the passes leave, with the handles of
  /// the cubics around it chosen again for every place tried: the joins a move of one node
  /// alone cannot mend. A round can cost more than the passes (dkg's a–z A–Z took half as many
  /// instructions again for three; whole DejaVu Sans 78 s instead of 53 for one).
  int polish_rounds = 0;
  /// Polish only the nodes at jumps (not those beside them, but for a line join's far node,
  /// at the places where its handle lands exactly on the line). Whole DejaVu Sans, one round,
  /// with the runs left with one jump polished: g2-jumps 1,357 → 1,315 for 4–5 % more time
  /// (stop 40); every jumping run, 939 → 883 for 7 % more (stop 46); every jumping run with
  /// the nodes beside its jumps, 826 for 40 % more. Since stop 60 (closed runs solved faster)
  /// text under G2 polishes beside its jumps too: whole DejaVu Sans 768 → 664 for 14 % more
  /// time (21.6 → 24.6 s; 612 with two rounds, 26.0 s). Text under G3 polishes at its jumps only: beside them, Cantarell's
  /// curvature variation came to 0.953× of the source's, over the bar.
  bool polish_only_at_jumps = false;
  /// At a smooth node flat on both sides before rounding (an inflection), the far handles'
  /// whole steps nearest its tangent line are choices too, as where a curve meets a line:
  /// dkg's g2-jumps with the polish 2.09 → 1.63 %, but whole DejaVu Sans 2,825 → 2,850 (of
  /// 71,768 smooth joins) without it. Handwriting only.
  bool inflection_handles = false;
  /// Where the runs are chosen, a turn of κ at a node the unrounded outline has not there (the
  /// end of one cubic and the start of the next bending towards the node's curvature, which
  /// whole steps set a few per cent off: a tooth of the comb) costs as a jump of 8 % does,
  /// and the polish also takes the runs where a node or cubic turns so. Handwriting
  /// only, where the check's hysteresis, 1 % of the outline's largest |κ|, is finer than the
  /// grid sets curvature at a short cubic's end. dkg a–z A–Z extrema: the cost 0.605× →
  /// 0.578× (at 1.2 % of the em); with the guide's lobes merged as well, the polish 0.533× →
  /// 0.478×, for half as much time again (one thread, 9.3 → 14.1 s).
  bool node_turns = false;
  /// Whether a line's end (fair/line_rounding) may go to any of its grid neighbours, however
  /// far that moves it, or only to those within its allowance (and its nearest grid point): a
  /// neighbour may give a line the short grid step a curve's handle on it needs, but a corner
  /// on the grid moved to a diagonal neighbour strays by 1.4 units.
  bool any_grid_neighbour = true;
  /// --continuity g3 where positive: a jump j of dκ/ds at a smooth node over 4 % costs this
  /// times 1 + j/2, and the polish takes the nodes where it jumps, trying places up to two
  /// units off. 8 on text, where a curvature jump the check counts costs more still
  /// (counted_jump_cost), so G2 comes first. 5 on handwriting, whose G2 bar is a share of the
  /// joins and whose short cubics leave whole steps few ways to match dκ/ds: dkg a–z A–Z,
  /// median dκ/ds jump 0.19 → 0.040 (1, 2, 4, 6, 8: 0.19, 0.12, 0.056, 0.039, 0.036), g2-jumps
  /// 0.75 → 0.97 % of the joins (6: 1.8 %, 8: 2.5 %; the bar 2 %), curvature extrema 0.480 →
  /// 0.494× (6: 0.503×; the bar 0.5×).
  double slope_jump_weight = 0.0;
  /// What a curvature jump the check counts (over 5 %) costs on top of what any jump over the
  /// target does, where choices are weighed: under --continuity g3 on text, whose bar allows
  /// none, more than the dκ/ds jumps it could mend save, so that the weight of dκ/ds may rise
  /// without breaking G2 (DejaVu Sans a–z A–Z at slope_jump_weight 3: g2-jumps 0 → 1 without
  /// it, 0 with it).
  double counted_jump_cost = 0.0;
  /// A line join's far node (fair/node_seats, seat_line_joins) may also seat its handle at the
  /// whole steps either side of the line, not only exactly on it. --continuity g3 only: Lato's M
  /// and W, where no node of the curves from the apex lines seats its handle on the line, keep
  /// κ·UPM 0.34 and 0.08 at the join without; under G2 Lato a–z A–Z gained a jump with it and
  /// Comic Neue took twice the time.
  bool seats_beside_lines = false;

  /// Where positive, a smooth node flat on both sides before rounding (κ = 0 there: an
  /// inflection, or a nearly straight stretch) whose nearest grid direction turns its tangent
  /// by half a degree or more and leaves a far handle of its cubics farther than this (units)
  /// off its tangent line takes the direction whose tangent line passes nearest both far
  /// handles instead: no node move the nudges try (two units at most) seats such a node, and
  /// each cubic keeps a curvature the other lacks. Liberation Serif's D: a flat S along the
  /// bottom, its middle node 0.95° off level, took (1, 0) and left the far handles 3 and 2
  /// units off it, κ·UPM 1.7 against 0.1; (55, 1) seats it. Text a–z A–Z at 2.5: Liberation
  /// Serif g2-jumps 2 → 0, Open Sans 1 → 0, Lato 8 → 7, Carlito 16 → 14, FreeSerif 10 → 9 (its
  /// inflections 1.022× → 0.978× of the source's), Comic Neue 64 → 62, EB Garamond 164 → 160; at 1 or 2, or
  /// without the half degree, Roboto, Liberation Sans or Lato's S gained a jump. Not on
  /// handwriting (dkg a–z A–Z gained an extremum without a node), whose flat nodes take the
  /// far handles' whole steps nearest the tangent line as choices instead (`inflection_handles`).
  double flat_node_reach = 0.0;

  /// The band's piece for the cubic from each node, where rounding removed nodes before
  /// choosing the steps (fair/grid_rounding: flat cubics merged into lines); else the node's
  /// own index, the band's pieces being the unrounded outline's segments.
  std::vector<std::size_t> band_piece_by_cubic{};

  double allowance_at(std::size_t node) const {
    return node < allowance_by_cubic.size() ? allowance_by_cubic[node] : allowance;
  }
  std::size_t band_piece(std::size_t node) const {
    return node < band_piece_by_cubic.size() ? band_piece_by_cubic[node] : node;
  }
};

/// The jump between two curvatures (or two dκ/ds), relative to the larger unless both are under
/// `flat`; 0 where both are 0 and nothing is flat. What every choice of steps weighs, and what
/// bracket placements (fair/bracket_placements.hpp) must meet.
inline double relative_jump(double k1, double k2, double flat) {
  const double big = std::max({std::abs(k1), std::abs(k2), flat});
  return big > 0.0 ? std::abs(k1 - k2) / big : 0.0;
}

/// How many steps (not necessarily whole) of `step` from `node`, on the side `sign` gives, reach
/// the line through `line_point` along `line_dir`; none where they run parallel (as far from the
/// line at every step).
std::optional<double> steps_to_line(Vec2 node, Vec2 step, double sign, Vec2 line_point, Vec2 line_dir);

/// steps_to_line where that is a whole number m ≥ 1: the handle node + sign·m·step lies exactly
/// on the line (κ = 0 where a curve meets it); none elsewhere.
std::optional<double> whole_steps_to_line(Vec2 node, Vec2 step, double sign, Vec2 line_point, Vec2 line_dir);

/// The handles node + sign·m·step (m ≥ 1 whole steps; sign −1 for an in-handle) nearest the
/// line through `line_point` along `line_dir` on either side of it (one when a whole step lies
/// on it): where a curve meets a line, its far handle there gives it the least curvature at
/// the join the grid allows, κ = 0 when on the line.
std::vector<Vec2> handles_near_line(Vec2 node, Vec2 step, double sign, Vec2 line_point, Vec2 line_dir);

/// The handles node + sign·m·step (m ≥ 1 whole steps; `out` false for an in-handle) on either
/// side of the length that gives the node's end of its cubic the curvature `target`, the
/// cubic's far handle at `far`: κ = 2d / (3h²) at a cubic's end (d how far the far handle lies
/// across the node's tangent, signed as κ; h the handle's length), so h = √(2d / 3κ). Where the
/// node runs along an axis the grid sets d in whole units, and a short handle gives only κ = 0
/// or far too much: the lengths that match can lie well beyond the rounded one. None where d
/// has the other sign, or longer than twice the chord to the cubic's `other_end`.
std::vector<Vec2> handles_for_curvature(Vec2 node, Vec2 step, bool out, Vec2 far, Vec2 other_end, double target);

/// The far handles far_node + sign·m·far_step (m ≥ 1 whole steps; far_node's in-handle where
/// `node` starts the cubic, `out`, else its out-handle) on either side of the place that gives
/// `node`'s end the curvature `target`, its own handle at `near`: κ = 2d / (3h²) with h fixed
/// and d, the far handle's offset across the node's tangent, linear in m. None where the far
/// handle runs along that tangent, or reaches past twice the chord.
std::vector<Vec2> far_handles_for_curvature(Vec2 node, Vec2 step, bool out, Vec2 near, Vec2 far_node, Vec2 far_step,
                                            double target);

/// Moves the handles of `nodes` (rounded, G1 exact along `grid_steps`) by whole steps along
/// their grid directions, and a corner's handle by a unit, to minimise the curvature jumps at
/// smooth nodes; then moves a node still jumping (or next to one), or one whose cubic bends
/// more ways than before rounding (an S no choice of whole steps undoes), by a unit with its
/// handles, or turns it to a nearby primitive direction, where that helps; seats an inflection
/// node still jumping where κ = 0 holds exactly on both sides, and the far node of a curve
/// whose line join still jumps where its handle lands on the line, or else slides that join
/// back along its line by whole steps, the handle's tip kept, so that the handle grows and the
/// curvature its far handle's offset gives shrinks; and chooses the steps again around
/// what moved, at most sixteen passes; then, `limits.polish_rounds` times over each run that
/// still jumps (or, with `limits.node_turns`, turns κ where the unrounded run does not), moves
/// each node at or beside a jump (or turning so), or a step along its own direction, with the
/// handles around it chosen again. `ideal` is the outline before rounding; no cubic moves
/// farther from it than the limits allow (as a curve: a handle slid along its tangent moves the
/// curve little; and along the outline: a node slid along its tangent moves its cubics little),
/// none gains an
/// inflection, an H/V extremum (or carries one from within half a unit of its node farther
/// off), a handle reaching far past its chord (overreach_length: of several, the least reach)
/// or, shorter than 16 units, a loop or cusp (cubic_turning), and curvature variation inside a
/// cubic beyond its unrounded self's costs (a third of the weight of a matching jump
/// at a node), as does a curvature extremum it adds (less than a jump over the target, so G2
/// comes first). Where no whole step near the rounded length gives an end at a smooth node its
/// unrounded curvature, the lengths aimed at it (handles_for_curvature) are tried too, and, where
/// the cubic's other end meets a line, that end's handle aimed likewise (far_handles_for_curvature).
void choose_handle_steps(std::vector<OutlineNode>& nodes, const std::vector<OutlineNode>& ideal,
                         std::span<const std::optional<Vec2>> grid_steps, bool closed, const HandleStepLimits& limits);

}  // namespace gf
