// The passes that move a node of a rounded outline where whole-step handles alone leave a
// curvature jump (fair/handle_steps): a nudge of a node joining two cubics, a flat node or a
// line join's far node seated where its far handles land on a tangent line, a line join slid
// along its line, a corner's handle seated on the line its cubic meets. Each returns the nodes
// it moved; a change stands only where NodeChange allows it and it costs less.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "fair/cubic_judge.hpp"
#include "fair/outline_joins.hpp"

namespace gf {

/// Where whole steps alone leave a jump, the node itself may move a unit (its handles with it,
/// G1 stays exact) and its two handles a step or three: the curvatures of both its cubics
/// change at both their ends, so the jumps at the two neighbours count too. A node whose
/// direction is not horizontal or vertical (an extremum's must stay so) may also turn to a
/// primitive direction within `grid_turn` of its unrounded tangent, its handles as long as there.
/// Only the nodes `candidates` lists are tried; returns those it moved (a turn in `steps`).
std::vector<std::size_t> nudge_jumping_nodes(std::vector<OutlineNode>& nodes, const std::vector<OutlineNode>& ideal,
                                             std::vector<std::optional<Vec2>>& steps, const OutlineJoins& joins,
                                             std::span<const std::size_t> candidates, CubicJudge& judge, double flat);

/// A flat node (flat_node: an inflection, or a node rounding left flat on one side) keeps κ = 0
/// on the grid only where both far handles lie exactly on its tangent line, and each is a
/// whole number of its own node's steps from that node: the tangent line must cross both their
/// handle lines at whole steps. Where the node still jumps, the grid points next to it and the
/// primitive directions within `grid_turn` of its tangent (sides up to 32) are tried for one
/// whose line does; the far handles go there and the node's own handles, whose lengths set its
/// neighbours' curvature, a step or three either way; not where a kept corner beside it would
/// turn under the kink limit. Returns the nodes it moved (its direction changed in `steps`).
std::vector<std::size_t> seat_flat_nodes(std::vector<OutlineNode>& nodes, const std::vector<OutlineNode>& ideal,
                                         std::vector<std::optional<Vec2>>& steps, const OutlineJoins& joins,
                                         std::span<const std::size_t> candidates, CubicJudge& judge, double flat);

/// A curve leaving a line keeps κ = 0 at the join on the grid only where its far handle lies
/// exactly on the line, a whole number of the far node's steps from that node; along a diagonal
/// line the far node's own direction seldom crosses it at one (Comic Neue's K: a 22-unit cap
/// left its line with κ·UPM 18). Where such a join still jumps, its far node, one joining two
/// cubics, is tried at the grid points up to two units from its own (a line of step (3, −4)
/// passes a whole step of a horizontal handle every four units of height: Lato's c, whose cap
/// seats two units down) and, unless it is an extremum, in the primitive
/// directions within `grid_turn` of its tangent, for one whose handle line crosses the line at a whole
/// step on its side of the join (with `beside_lines`, HandleStepLimits::seats_beside_lines, also
/// at the whole steps either side of the line); that handle goes there, the node's other handle
/// a step or three either way. Returns the nodes it moved (their directions changed in `steps`).
std::vector<std::size_t> seat_line_joins(std::vector<OutlineNode>& nodes, const std::vector<OutlineNode>& ideal,
                                         std::vector<std::optional<Vec2>>& steps, const OutlineJoins& joins,
                                         std::span<const std::size_t> candidates, CubicJudge& judge, double flat,
                                         bool beside_lines);

/// A curve whose far handle misses its line leaves the line with κ = (2/3)·d/h² (d the far
/// handle's offset from the line, h the near handle's length), and on a slanted line the grid
/// sets d in multiples of 1/|step|: Lato's A, whose feet leave the legs' lines of step (−9, 23)
/// with κ·UPM 0.066 on two-step handles; Pagella's serifs, stepping (16, 1), with 0.16 on one.
/// Where such a join still jumps, its node slides back along the line by one to three of the
/// line's steps, the near handle's tip kept: the curve leaves the line where it did, straight,
/// only sooner, and its handle grows by as many steps. Pass after pass, a join stays within
/// twice its cubic's chord of where the passes found it (`entry`): unbounded, Comic Neue's u had
/// a step of (1, 56) slide a short cap 56 units down its stem, which strayed and cost the
/// contour eight roundings more, and Gentium's M a bracket of 89 units crawl 600 units up its
/// stem; within one chord, Lato's M stopped a step short of where its cap's curve leaves the leg
/// flat enough (slide_reach). The line keeps half its length at least. Since stop 85 the near
/// handle may also slide along with the join, as long as it was, and a join slides too where
/// not it but its cubic's far node jumps with κ = 0 on the cubic's side, the near handle's tip
/// on that node's tangent, which no length of that node's handle changes (Gentium Plus's w: a
/// 17-unit curve from a (3, 11) line to an x-extremum, κ·UPM 0 against 78). Returns the first
/// node of each cubic it changed.
std::vector<std::size_t> slide_line_joins(std::vector<OutlineNode>& nodes, std::span<const OutlineNode> entry,
                                          std::span<const std::optional<Vec2>> steps, const OutlineJoins& joins,
                                          CubicJudge& judge, double flat);

/// A corner whose cubic meets a line at the far end keeps no grid direction: its handle may go
/// to any grid point, and cubic_choices offers the line's whole step nearest it, where κ = 0 at
/// the join. Where that moves the cubic too far (DejaVu Serif's R: the leg's corner 1.81 units
/// against an allowance of 1.71), the corner is tried at the grid points up to two units from
/// its own, its handle at the line's whole steps up to two either side, its other handle where
/// it is; it must still turn by the kink limit (or as little as it did). `corners`: interior
/// corners at a cubic (choose_handle_steps lists them); since stop 65 also those with a line on
/// the other side (Caladea's v, x and y: a serif's curve from its stroke's line to the serif's
/// end kept κ·UPM 0.5–0.9 at the join), such a corner moving only where that line's other end
/// is a corner too. Each corner is tried
/// once: a tried one leaves `corners` (again every pass, it cost Because We Learn's a–z A–Z 3 %
/// more time for nothing). Returns the corners moved.
std::vector<std::size_t> seat_line_joins_at_corners(std::vector<OutlineNode>& nodes, const std::vector<OutlineNode>& ideal,
                                                    std::span<const std::optional<Vec2>> steps, const OutlineJoins& joins,
                                                    std::vector<std::size_t>& corners, CubicJudge& judge, double flat);

}  // namespace gf
