// A lone cubic between two lines, each meeting it tangentially, where the passes of
// fair/handle_steps leave a jump: κ = 0 at both ends needs both handles on both lines, so at
// their crossing X (the cubic a, X, X, b); on the grid X must be a grid point of both lines. The
// passes choose each line apart and seat one handle at a time, and where the crossing falls
// off the grid no handle seats both (Noto Sans's W, Carlito's w: a curve of a few degrees
// between a stroke and the line from an apex).
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "fair/cubic_judge.hpp"
#include "fair/outline_joins.hpp"

namespace gf {

/// The cubic from node a to node a + 1, both smooth joins with lines, with both handles at a
/// grid point X within three units of the unrounded lines' crossing: each line's join where a
/// bracket's may go (bracket_placements' join_places: slid along the line, or the line turned
/// about its far corner), X at whole steps of the line beyond it. The cheapest allowed by the
/// judge (within the allowance, no inflection, extremum, overreach or fold its unrounded self
/// and its present self both lack; the far corners turning no less than the kink limit or than
/// they did) stands where it costs less than the cubic as it is. Returns whether it moved.
bool seat_lone_cubic(std::vector<OutlineNode>& nodes, const std::vector<OutlineNode>& ideal,
                     std::vector<std::optional<Vec2>>& steps, const OutlineJoins& joins, std::size_t a,
                     CubicJudge& judge, double flat);

}  // namespace gf
