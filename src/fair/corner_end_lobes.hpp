// A stroke's edge that leaves a corner bending one way for a short stretch and then turns the
// other way: on a scan, the last of the corner's rounding, which the guide follows within its
// tolerance and the writeback cuts at the inflection. Where one cubic from the corner, bending
// one way, meets the node after the inflection with its tangent and curvature (G2 kept there)
// within what the outline leaves of the tolerance, the cubics become that one: an inflection
// and a node fewer, the corner still a corner. Where the lobe runs into a line, the line runs
// from the corner, moved onto it.
#pragma once

#include <vector>

#include "fair/outline_nodes.hpp"

namespace gf {

struct CornerLobeLimits {
  double least_corner_deg = 6.0;  ///< the corner still turns by this much, and by half what it did at least
  double most_turn_deg = 30.0;    ///< the corner's tangent turns by at most this much
};

/// For each corner of a closed outline whose first cubic (or, read backwards, its last) bends
/// against the way the outline goes on, the lobe ending inside that cubic, at its end or inside
/// the next: the cubics up to the lobe's end become one from the corner, G2 with what follows,
/// bending one way (cut at its H/V extrema, which keep nodes), that moves the outline least,
/// where that is within `allowance` (per segment, node i to node i + 1: what the outline leaves
/// of the tolerance there) of the cubics it replaces. Where the lobe runs into a line instead,
/// the corner moves onto the line's extension and the line runs from it, within the allowance
/// of the three segments it changes. `allowance` follows the nodes, which start again at the
/// node nearest where they did. How many lobes went.
int drop_corner_end_lobes(std::vector<OutlineNode>& nodes, bool closed, std::vector<double>& allowance,
                          const CornerLobeLimits& limits = {});

}  // namespace gf
