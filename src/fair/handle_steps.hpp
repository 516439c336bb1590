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

#include <optional>
#include <span>
#include <vector>

#include "fair/outline_nodes.hpp"

namespace gf {

struct HandleStepLimits {
  /// |κ| (1/unit) below which two curvatures are compared by their difference, not their
  /// ratio: a curve this flat has no visible curvature to match.
  double flat_curvature = 5e-4;
  /// How far (units) a cubic may move from its unrounded self to gain G2.
  double allowance = 0.5;
};

/// Moves the handles of `nodes` (rounded, G1 exact along `steps`) by whole steps along their
/// grid directions, and a corner's handle by a unit, to minimise the curvature jumps at
/// smooth nodes; `ideal` is the outline before rounding.
void choose_handle_steps(std::vector<OutlineNode>& nodes, const std::vector<OutlineNode>& ideal,
                         std::span<const std::optional<Vec2>> steps, bool closed, const HandleStepLimits& limits);

}  // namespace gf
