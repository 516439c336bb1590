// A serif's bracket, or the two cubics of a run next to a line, placed on the grid as one
// piece (fair/bracket_placements) where the passes of fair/handle_steps leave it jumping: the
// placements judged by NodeChange at the bracket's node, the cheapest allowed one standing.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "fair/cubic_judge.hpp"
#include "fair/outline_joins.hpp"

namespace gf {

/// Two cubics of a run, from node h through node i to node j, of which h or j is a line join,
/// that still jump once the passes end (a serif's bracket; in a longer run, the two next to its
/// line; a curve from a line to a corner), placed as one piece (fair/bracket_placements.hpp):
/// each line turned about its far corner or slid, an end inside the run kept with κ there to
/// match the cubic beyond, a corner kept with its handle's direction, the node moved and turned,
/// all handles set together; the cheapest allowed placement stands, where it costs less than the
/// run as it is. Returns whether it moved.
bool place_bracket(std::vector<OutlineNode>& nodes, const std::vector<OutlineNode>& ideal,
                   std::vector<std::optional<Vec2>>& steps, const OutlineJoins& joins, std::size_t h, CubicJudge& judge,
                   double flat);

}  // namespace gf
