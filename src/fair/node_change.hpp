// A change at one node of a rounded outline (a nudge, a seat, a bracket's placement), weighed
// by what it does to the curvature jumps at the node and its neighbours and allowed only where
// its cubics gain nothing their unrounded selves lack; and where such a change may put the node.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include "fair/cubic_judge.hpp"
#include "fair/outline_joins.hpp"
#include "fair/step_costs.hpp"

namespace gf {

/// Where rounding or a nudge may put a node: its grid point and those `reach` units from it that
/// are still within `reach` of the grid point nearest its unrounded place.
std::vector<Vec2> node_places(Vec2 at, Vec2 unrounded, int reach = 1);

/// The primitive grid directions within `most` radians of `tangent`, no component over `longest`.
std::vector<Vec2> directions_near(Vec2 tangent, double most, int longest);

/// The directions node i may take on the grid: its own step and, where that is not horizontal or
/// vertical (an extremum's must stay so), the primitive directions within `grid_turn` of its
/// unrounded tangent, only of at most `longest` units a side: whole steps of a longer one are too
/// coarse to set curvature by (and each direction costs a search). Of the horizontal and vertical
/// directions, only the unrounded tangent's own: the flat-node seat may turn an extremum off
/// its axis, and the node must be able to turn back where a cubic beside it then holds the
/// extremum inside (Breip's L under --continuity g3).
std::vector<Vec2> node_directions(Vec2 step, const OutlineNode& target, int longest = 10);

/// How many whole steps of d `from`'s out-handle (`out`) or in-handle is long, at least one: the
/// length a node turned or moved to d keeps.
inline double handle_steps_along(const OutlineNode& from, Vec2 d, bool out) {
  return std::max(1.0, whole_steps(from.point, out ? *from.out_handle : *from.in_handle, d, out ? 1.0 : -1.0));
}

/// Node `node` put at p along d with its handles m_in + a and m_out + b steps long (a and b
/// within handle_reach either way, each handle a step at least), `each` called at every pair.
template <class Each>
void for_each_handle_pair(OutlineNode& node, Vec2 p, Vec2 d, double m_in, double m_out, Each&& each) {
  node.point = p;
  for (int a = -handle_reach; a <= handle_reach; ++a)
    for (int b = -handle_reach; b <= handle_reach; ++b) {
      if (m_in + a < 1.0 || m_out + b < 1.0) continue;
      node.in_handle = p - d * (m_in + a);
      node.out_handle = p + d * (m_out + b);
      each();
    }
}

/// The most of each fault cubic k may have after a change: what its unrounded self or its state
/// before the change has, so that the change gains none that both lack.
struct FaultCeiling {
  int inflections, extrema;  ///< inflections: CubicJudge::inflections_added; extrema: H/V, all
  double overreach, turning;

  /// Cubic k's, `before` its traits before the change.
  static FaultCeiling of(CubicJudge& judge, std::size_t k, const CubicTraits& before);
  /// Whether `t`, in cubic k's place, is within its allowance and under the ceiling (its
  /// turning by fold_turn).
  bool admits(CubicJudge& judge, std::size_t k, const CubicTraits& t) const;
};

/// A change at node i of an outline: it changes both cubics at i (the one, where the other side
/// is a line: a corner's), so the curvature jumps at i and at its two neighbours. It is allowed
/// when no such cubic moves farther from its unrounded self than its allowance, nor gains an
/// inflection, an H/V extremum or a handle's reach past its chord that neither its unrounded
/// self nor the cubic before the change has.
class NodeChange {
 public:
  NodeChange(const std::vector<OutlineNode>& nodes, const OutlineJoins& joins, CubicJudge& judge, double flat,
             std::size_t i);

  /// The jump costs at node i and its neighbours, as the outline stands.
  double jump_costs() const;
  /// What either cubic at i costs for an inflection, a bend the other way, a curvature
  /// extremum or curvature variation its unrounded self lacks, as the cubic choice weighs them
  /// (a nearly straight cubic whose rounded ends leave its chord outside their tangents can
  /// only be an S).
  double bend_cost() const { return inflections_cost() + shapes_cost(); }
  /// Both.
  double cost() const { return jump_costs() + bend_cost(); }
  /// cost() where it is under `best` and the outline as it stands is an allowed change: the
  /// jumps first, the cubics' shapes only where the jumps leave room.
  std::optional<double> cost_under(double best) const;
  /// Whether either cubic bends the wrong way, or any of those jumps is over the target.
  bool needs_change() const;

 private:
  // Whether the outline as it stands is an allowed change.
  bool allowed() const;
  // What the inflections cost as the cubic choice weighs them: those either cubic at i adds
  // inside, and what happens at the inflection nodes among i and its neighbours.
  double inflections_cost() const;
  // shape_cost of both cubics at i, as the cubic choice weighs them: without the variation, a
  // nudge that left every jump as it was could trade a cubic's κ·UPM of 5 at the node for a
  // spike of 667 (EB Garamond's P, where its bowl meets the stem).
  double shapes_cost() const;
  // The jumps at the neighbour before, at node i (none at a corner) and at the neighbour after (join_jump, with
  // only the two cubics at i evaluated where the contour has room).
  std::array<double, 3> jumps_now() const;

  const std::vector<OutlineNode>& nodes_;
  const OutlineJoins& joins_;
  CubicJudge& judge_;
  double flat_;
  std::size_t i_, h_, j_;
  std::optional<double> beyond_h_, beyond_j_;
  std::vector<std::size_t> inflection_nodes_;  ///< of h, i and j, those CubicJudge::inflects_at
  std::vector<std::size_t> cubics_;  ///< the cubics at i: before it (h) and after it, where they are cubics
  std::vector<FaultCeiling> ceilings_;  ///< per cubic at i
};

}  // namespace gf
