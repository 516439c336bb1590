// Smooth nodes where a cubic meets a line, as the passes before rounding that rework such joins
// for the grid see them (fair/leaning_line_ends, fair/line_splits): the cubic, the line's far
// end, the shortest grid step the line can take and the way the cubic bends into the join.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "fair/outline_nodes.hpp"

namespace gf {

/// A smooth node joining a whole cubic to a line whose far node has no handle on it either.
struct CurveLineJoin {
  bool arrives;      ///< the cubic arrives at the node and the line leaves it (else the reverse)
  Cubic curve;       ///< the cubic, turned where needed so that it ends at the node
  std::size_t far;   ///< the line's other node
};

/// Node k as such a join; none where it is not one (an open outline's ends are not).
std::optional<CurveLineJoin> curve_line_join(const std::vector<OutlineNode>& nodes, bool closed, std::size_t k);

/// The shortest primitive grid step of the line from a to b with each end moved by a unit or
/// less: the step rounding can give it at best.
double shortest_line_step(Vec2 a, Vec2 b);

/// The sign of the curvature a cubic ends with just before its end (a cubic meeting a line G2
/// is flat at the end itself); 0 where it is straight there.
double end_bend(const Cubic& c);

}  // namespace gf
