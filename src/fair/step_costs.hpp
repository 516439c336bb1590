// What choosing whole-step handles weighs (fair/handle_steps): the targets a curvature jump is
// measured against, and the costs of what a rounded cubic gains over its unrounded self. The
// choice of handles, a node's nudge and a bracket's placement weigh alike by these.
#pragma once

#include <algorithm>
#include <limits>
#include <numbers>

#include "fair/contour_plan.hpp"
#include "fair/cubic_change.hpp"
#include "fair/handle_steps.hpp"

namespace gf {

constexpr int handle_reach = 3;      // whole steps either way from the rounded length
constexpr double grid_turn = 0.1;    // radians a node may turn on the grid (the allowance bounds what that moves)
constexpr double target_jump = 0.03;  // below the check's 5 %, with room for its sampling
constexpr double checked_jump = 0.05;  // the check's g2-jump (HandleStepLimits::counted_jump_cost)
constexpr double wrong_way = 1e4;     // an inflection or extremum the unrounded cubic lacks
constexpr double infeasible = std::numeric_limits<double>::infinity();
constexpr double kink_limit = radians(kink_limit_deg);  // fair/contour_plan.hpp's
// Curvature variation a rounded cubic adds inside, relative to its unrounded largest |κ|: free
// up to 5 %, then weighed a third of a matching curvature jump (whose cost rises 100 per unit),
// so G2 stays first. Measured: Because We Learn TV 0.59 → 0.55× with g2-jumps 11.0 → 10.7 %.
constexpr double free_variation = 0.05;
constexpr double variation_weight = 3.0;
// A curvature extremum a rounded cubic adds inside (a wobble of the comb, an extremum the check
// counts): 3 each, at most 1.9 a cubic, so that even both cubics at a node cost less than one
// jump over the target (at least 4) and G2 stays first. Measured, a-z A-Z: dkg extrema 0.77 ->
// 0.70x, Because We Learn 0.79 -> 0.72x; uncapped, Inter's g kept a jump.
constexpr double turn_weight = 3.0, most_turn_cost = 1.9;
// A turn of κ at a node the unrounded outline lacks there (a tooth of the comb where whole
// steps set the node's two ends a few per cent apart; handwriting only): weighed as a jump of
// 8 % (1 + 100·0.08), so the grid would rather leave a small jump the check barely counts than
// a tooth it counts as two extrema. Measured, a–z A–Z rounded, 3 → 9: Because We Learn extrema
// 0.506× → 0.483× (the bar 0.5×; 6 to 20 all come under it), dkg g2-jumps 0.95 → 1.25 % (the
// bar 2 %).
constexpr double node_turn_weight = 9.0;
// A cubic shorter than this (units) is checked for folding into a loop or cusp within its chord
// (cubic_turning); a longer one that folds reaches past its chord (overreach_length). Because
// We Create's brush ends: 3-unit cubics rounded into loops, 14 of its 54 missing extrema.
constexpr double fold_chord = 16.0;
constexpr double fold_turn = 0.5 * std::numbers::pi;  // turning beyond the unrounded cubic's
// A cubic bending wholly the other way from its unrounded self (a nearly straight cubic whose
// rounded ends tilt it across its chord) puts an inflection at a node between it and its
// neighbours: weighed under any jump over the target, over every one within it.
constexpr double flip_weight = 2.0;
inline double flip_cost(const CurvatureShape& rounded, const CurvatureShape& unrounded) {
  return rounded.bend * unrounded.bend < 0 ? flip_weight : 0.0;
}

inline double turn_cost(int added) { return std::min(most_turn_cost, turn_weight * std::max(0, added)); }

// The curvature variation a rounded cubic adds inside beyond free_variation of its unrounded
// largest |κ|: a spike a comb would show (a one-step handle with its far handle a unit off the
// tangent gives κ = 2/3 a unit, a hundred times what the cubic had).
inline double variation_cost(const CurvatureShape& rounded, const CurvatureShape& unrounded, double flat) {
  const double excess = (rounded.variation - unrounded.variation) / std::max(unrounded.largest, flat);
  return excess > free_variation ? variation_weight * (excess - free_variation) : 0.0;
}

// What a rounded cubic's curvature costs beyond its unrounded self's, short of an inflection
// inside it: bending wholly the other way, curvature extrema it gains (a wobble of the comb),
// and curvature variation it gains beyond a little (a spike a comb would show). The choice of
// handles and a node's nudge weigh it alike.
inline double shape_cost(const CurvatureShape& rounded, const CurvatureShape& unrounded, double flat) {
  return flip_cost(rounded, unrounded) + turn_cost(rounded.turns - unrounded.turns) +
         variation_cost(rounded, unrounded, flat);
}

// G2 first: any jump over the target costs more than every choice that meets it.
inline double jump_cost(double j) { return j <= target_jump ? j * j : 1.0 + 100.0 * j; }

// A jump of dκ/ds (relative to the larger side, as the G3 check measures it) over 4 % costs
// `weight` times 1 to 2 (HandleStepLimits::slope_jump_weight).
constexpr double target_slope_jump = 0.04;
inline double slope_jump_cost(double d1, double d2, double weight) {
  const double j = relative_jump(d1, d2, 0.0);
  return j <= target_slope_jump ? 0.0 : weight * (1.0 + 0.5 * j);
}

}  // namespace gf
