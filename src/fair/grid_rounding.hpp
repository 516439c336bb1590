// Faired nodes rounded to integer coordinates so that G1 stays exact: a smooth node and its
// two handles end up exactly collinear on the grid (both handle vectors integer multiples of
// one primitive direction), a node at a horizontal or vertical extremum keeps axis-parallel
// handles, and a curve meeting a line keeps its handle on the line. Among the exact choices
// the one that moves the points least is taken; then the handle lengths are chosen in whole
// steps so that G2 survives as well as the grid allows (fair/handle_steps.hpp). Two nodes that
// land on one grid point with next to nothing between them become one, so the result may have
// fewer nodes than the input.
#pragma once

#include <vector>

#include "fair/handle_steps.hpp"
#include "fair/outline_nodes.hpp"

namespace gf {

std::vector<OutlineNode> round_to_grid(const std::vector<OutlineNode>& nodes, bool closed,
                                       const HandleStepLimits& limits = {});

}  // namespace gf
