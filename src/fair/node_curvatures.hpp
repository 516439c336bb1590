// The curvature the cubic writeback gives each of a chain's nodes. A span between two nodes is
// written as its G2 Hermite cubic: end points, tangents and both end curvatures fixed, no freedom
// left, so where the path's curvatures at the nodes give no cubic within the budget the span is
// cut into more. Yet most such spans have a cubic with those tangents within the budget (EB
// Garamond a–z A–Z: 472 of the 573 spans one G2 cubic missed), only with other curvatures at
// its ends. An extremum's curvature binds nothing but G2 itself, so it may move off the path's,
// as far as both spans it joins then fit whole: curvature stays continuous at the node, the
// cubics stay within the budget of the path, and the span needs one cubic instead of two.
#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <vector>

namespace gf {

/// What the choice knows of one node of a chain.
struct NodeCurvature {
  double path = 0.0;   ///< the faired path's κ there
  bool free = false;   ///< its κ may move: an extremum inside the chain that is not flat
};

/// Whether the span from node i to the next fits within the writeback's budget as one cubic
/// with those curvatures at its ends.
using SpanFits = std::function<bool(std::size_t i, double k_start, double k_end)>;

/// The end curvatures of the cubic nearest the span from node i with its end tangents (any
/// curvatures), where there is one: where a span needs other end curvatures to fit, they lie
/// near these. Asked only of spans that do not fit as the path has them.
using SpanSeeds = std::function<std::optional<std::array<double, 2>>(std::size_t i)>;

/// The curvature at each node (a closed chain's last span returns to its first node): the
/// path's, except at free nodes where another lets more spans fit whole. A node moves only
/// where every span it ends then fits (a span still cut keeps the path's curvature at both
/// ends, so it takes no more cubics than before), keeps its sign, and stays within a factor of
/// two of the path's unless a seed lies farther; among choices fitting as many spans, the
/// nearest the path's in log κ.
std::vector<double> choose_node_curvatures(std::span<const NodeCurvature> nodes, bool closed, const SpanFits& fits,
                                           const SpanSeeds& seeds);

}  // namespace gf
