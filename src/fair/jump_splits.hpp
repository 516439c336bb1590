// Cubics split in two beside the joins where rounding left curvature jumping. A node's handles
// lie whole steps of its grid direction from it, so the curvature a cubic's far handle gives
// at a join moves in steps the far node's direction sets: where that direction is long (C059's
// X: a (23, 33) step against a 7-unit handle offset), or a line's curve cannot seat its far
// handle on the line (Caladea's w), no choice of whole steps matches. A node in the middle of
// the cubic, where its tangent runs along a short grid direction, brings a far handle the grid
// can set finely, and the split itself leaves the float outline as it was (de Casteljau).
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "fair/outline_nodes.hpp"

namespace gf {

/// Where to split `c`: the parameter in [0.25, 0.75] nearest 0.5 where its tangent runs along a
/// primitive direction no longer than √5 ((1, 0), (1, 1), (2, 1) and mirrors), with that
/// direction along the curve; else 0.5 and no direction.
struct CubicSplit {
  double t = 0.5;
  std::optional<Vec2> grid_step;
};
CubicSplit split_place(const Cubic& c);

/// `nodes` with each cubic of chord at least `shortest_chord` that ends or starts at the node
/// nearest one of `joins` (within `reach` units; none where no node is) split at its
/// split_place, the new node smooth. The outline is the same curve.
std::vector<OutlineNode> split_cubics_beside(const std::vector<OutlineNode>& nodes, bool closed,
                                             std::span<const Vec2> joins, double shortest_chord, double reach);

}  // namespace gf
