// The whole-step handles of a run of cubics joined at smooth nodes, chosen together (Viterbi
// over the cubics, each cubic's states every pair of its two handles' choices; a run that
// closes on itself with each state of its first cubic in turn), so that curvature matches
// across its nodes and is zero where it meets a line.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "fair/cubic_judge.hpp"
#include "fair/outline_joins.hpp"
#include "fair/step_costs.hpp"

namespace gf {

/// Where one handle of a node may go: whole steps along the node's grid direction, up to
/// `corner_reach` units either way for a corner's handle (none on the node itself, where the
/// cubic has no direction), else where it is. The rounded position comes first.
std::vector<Vec2> handle_candidates(const OutlineNode& node, std::optional<Vec2> step, bool out, int corner_reach = 1);

/// One cubic of the outline and every choice of its two handles (state = out·ins + in).
struct CubicChoices {
  std::size_t start = 0, end = 0;  ///< node indices
  std::vector<Vec2> outs, ins;
  std::vector<double> k_start, k_end, cost;
  std::vector<const CubicTraits*> traits;  ///< each state's, for the turns at its nodes

  std::size_t states() const { return outs.size() * ins.size(); }
};

/// The cheapest states of a run of cubics, one per cubic, and what they cost.
struct RunChoice {
  std::vector<std::size_t> states;
  double cost = infeasible;
};

/// The whole steps of one run of cubics joined at smooth nodes (the nodes starting them, in
/// order), chosen together: the choices and the cheapest states.
struct RunSteps {
  std::vector<CubicChoices> run;
  RunChoice best;
};

/// The handles set to the cheapest states (none where every state is infeasible). Returns
/// whether any handle moved.
bool apply_steps(std::vector<OutlineNode>& nodes, const RunSteps& chosen);

/// The run's handles (`cubics`: the nodes starting its cubics; `cycle`: it closes on itself)
/// set to the cheapest states. Returns whether any handle moved.
bool choose_run_steps(std::vector<OutlineNode>& nodes, std::span<const std::optional<Vec2>> steps,
                      const OutlineJoins& joins, std::span<const std::size_t> cubics, bool cycle, CubicJudge& judge,
                      double flat);

/// The cubics of a run around one node, re-chosen while that node is tried in other places:
/// three cubics either side of it, between the fixed cubics next to them (whose curvature at the
/// window's ends still counts); the whole run where it is that short. Three against two: dkg's
/// a–z A–Z g2-jumps 1.97 → 1.62 % for 0.6 % more instructions; one: 2.44 %.
struct RunWindow {
  std::vector<std::size_t> cubics;  ///< node indices starting the cubics re-chosen
  std::optional<std::size_t> before, after;  ///< the fixed cubics at its ends
  bool whole_cycle = false;                  ///< the whole of a run that closes on itself
};

/// The window of `run` around its cubic at `position`.
RunWindow window_around(std::span<const std::size_t> run, bool cycle, std::size_t position);

/// The cheapest handles of the window's cubics with its nodes where they are now (the fixed end
/// cubics first and last in `run`, one state each); the choices of cubics not touching node
/// `moving` reused from `known` (the same window with that node elsewhere) when given.
RunSteps choose_window(const std::vector<OutlineNode>& nodes, std::span<const std::optional<Vec2>> steps,
                       const OutlineJoins& joins, const RunWindow& w, CubicJudge& judge, double flat,
                       std::size_t moving, const RunSteps* known = nullptr);

}  // namespace gf
