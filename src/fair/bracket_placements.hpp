// A curve between two lines drawn as two cubics (a serif's bracket: line, join, cubic, node,
// cubic, join, line), placed on the grid as one piece. Its three joins are G2 on the grid only
// together: κ = 0 where it leaves a line needs its far handle exactly on that line, a whole
// step of the node's direction that a line of long step (Pagella's serif tops: (16, 1)) seldom
// offers; the node's curvature must then match across it, set by whole steps of both handles.
// The passes choosing steps move one node at a time against lines placed before them, and
// left TeX Gyre Pagella's H serifs with κ·UPM 0.13 at the join although placements exist that
// meet all three within the tolerance: the line turned a quarter of a degree about its far
// corner onto a step of (15, 1), its join on a grid point of that line, the node two units off.
// This lists such placements, nearest the unrounded bracket first; the caller judges them
// (fair/bracket_choice: within the allowance, no inflection or extremum gained).
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <variant>
#include <vector>

#include "fair/outline_nodes.hpp"

namespace gf {

/// A line the bracket meets tangentially, along the contour's direction.
struct BracketLine {
  Vec2 far;                    ///< its other end, as rounded
  /// Another place of its other end: where rounding moved that corner off its nearest grid
  /// point along the line beyond it (Pagella's i: a serif's top corner a unit up its side).
  std::optional<Vec2> far_alternative;
  Vec2 join, step;             ///< the join and the line's primitive step, as rounded
  Vec2 exact_far, exact_join;  ///< the unrounded line
  /// Whether the line may turn about `far` (a corner there, the line off the axes): its join
  /// then goes to grid points near the unrounded line, else only slides along the line.
  bool may_turn = false;
};

/// The line from node `join` (smooth, meeting a cubic) to node `far` as the passes left it
/// (`step` its primitive step along the contour), with its unrounded self: it may turn where
/// `far` is a corner and the unrounded line is off the axes, and `far` may go back to its nearest
/// grid point where the line beyond it (`beyond_is_line`, ending at `beyond`) is horizontal or
/// vertical and stays so.
BracketLine bracket_line(const std::vector<OutlineNode>& nodes, const std::vector<OutlineNode>& ideal, Vec2 step,
                         std::size_t join, std::size_t far, bool beyond_is_line, Vec2 beyond);

/// A join's place on its line and the line's step there, along the contour's direction; or, at
/// an end that is a node, that node, its direction and the curvature to meet there.
struct JoinPlace {
  Vec2 far, join, step;
  bool at_node = false;
  std::optional<double> kappa;  ///< at a node: the curvature to meet there, if any
};

/// Where a join may go: along its line within 16 units of the unrounded join and of its rounded
/// place and between them (four of its steps at most), or, where the line may turn about its far
/// end, at grid points within 0.75 units of the unrounded line (the step then from the far end
/// to the join), turning the line by at most `most_turn`. `arrives`: the line arrives at the
/// join (a bracket's first line), else it leaves it. The line keeps half its unrounded length.
std::vector<JoinPlace> join_places(const BracketLine& line, bool arrives, double most_turn);

/// A node a bracket ends at instead of a line: the third node of a longer run from a line,
/// whose κ must match `kappa`, the curvature of the cubic beyond it, or a corner (no `kappa`:
/// its curvature binds nothing). It stays where it is, its handle on the bracket's side taking
/// whole steps of its direction `step` (along the contour's direction).
struct BracketNode {
  Vec2 point, step;
  std::optional<double> kappa;
};

/// The bracket as the passes left it and its unrounded self: `first` arrives at the bracket's
/// start, `last` leaves its end; `exact` is the unrounded J1, P1, P2, N, Q1, Q2, J2.
struct Bracket {
  std::variant<BracketLine, BracketNode> first, last;
  std::array<Vec2, 7> exact;
};

/// A placement: joins, handles and node on the grid, G1 exact at all three joins (at an end
/// that is a node, its join is that node and its far end too).
struct BracketPlacement {
  Vec2 far1, join1, step1, handle1, handle2, node, node_step, handle3, handle4, join2, step2, far2;
  double spread = 0.0;  ///< the farthest of its cubics' quarter points from the unrounded bracket
};

/// Placements whose curvature is within `target` (relative_jump, flat under `flat`) of 0 at both
/// joins (of an end node's `kappa` there, if any) and of itself across the node, the node at one
/// of `node_points` in one of `node_steps` (along the contour's direction), each join within 16
/// units along its line of the unrounded one and of its rounded place, or between them (0.75
/// across it where the line turns; four of its steps where it only slides), turning its line by
/// at most `most_turn` radians, each end's handle within four times its unrounded length either
/// way; at most `most`, least spread first.
std::vector<BracketPlacement> bracket_placements(const Bracket& bracket, std::span<const Vec2> node_points,
                                                 std::span<const Vec2> node_steps, double flat, double target,
                                                 double most_turn, std::size_t most);

}  // namespace gf
