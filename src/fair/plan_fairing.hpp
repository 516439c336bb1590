// A contour's plan (fair/contour_plan) faired run by run and written back as one outline of
// nodes, not yet rounded: each smooth run faired on its basis (fair/run_fairing) within the
// chain's budget, its chains written as cubics (fair/cubic_writeback) within the cubics' budget,
// lines kept between them, and the pieces recorded for the segments' export.
#pragma once

#include <deque>
#include <optional>
#include <string>
#include <vector>

#include "fair/contour_plan.hpp"
#include "fair/fair_options.hpp"
#include "fair/faired_piece.hpp"
#include "fair/g3_cubics.hpp"
#include "fair/kinked_corners.hpp"
#include "fair/outline_nodes.hpp"
#include "fair/run_fairing.hpp"

namespace gf {

/// How the tolerance is shared: the chains' budget against the source, the cubics' against the
/// chains.
struct Budgets {
  double chain, cubic;
};

/// What fair_run gives, each run faired once for all of a contour's fairings: those differ in
/// what only the writeback and rounding read (FairSettings::free_node_curvatures,
/// rounding_reserve_units, shortest_rounded_span_units), and ask for the same runs on the same
/// budgets again. A memo of fair_run itself, so a fairing that finds a run here gets what it
/// would have faired.
class RunFairings {
 public:
  struct Entry {
    SmoothRun run;
    FairSettings settings;  ///< as the run fairing reads them (runs_settings)
    double budget;
    RunBasis basis;
    FairedRun faired;
  };
  const Entry& fair(const SmoothRun& run, const FairSettings& settings, double budget, RunBasis basis);

 private:
  std::deque<Entry> entries_;  // stable references
};

/// Runs already faired by one fairing of a contour: a plan made again with a corner smoothed
/// keeps every run away from that corner as it was, and those need not be faired twice. Where
/// the budgets were halved because a run failed (not because the outline strayed), a run
/// faired within a larger budget stands too. Those it found are its own, not another
/// fairing's (RunFairings serves those only as asked).
class FairedRuns {
 public:
  explicit FairedRuns(RunFairings& memo) : memo_(memo) {}

  /// `basis`: what a run that failed on its own outline is faired on next (text); one faired
  /// on its own outline stands.
  const FairedRun& get(const SmoothRun& run, const FairSettings& settings, double budget, bool larger_stands,
                       RunBasis basis);

 private:
  const FairedRun& find_or_fair(const SmoothRun& run, const FairSettings& settings, double budget, bool larger_stands,
                                RunBasis basis);

  RunFairings& memo_;
  std::vector<const RunFairings::Entry*> entries_;  // in the order this fairing asked for them
};

/// A plan faired: its nodes, or why not, with what the fairing counted on the way.
struct FairedPlan {
  std::vector<OutlineNode> nodes;
  std::string failure;
  double mismatch = 0.0;
  int g1_nodes = 0;
  int freed_nodes = 0;  ///< ChainCubics::freed_nodes, over the plan
  int guide_stretches = 0;
  int g3_runs = 0, g2_line_joins = 0;
  std::vector<std::string> g3_shortfalls;
  G3CubicReport g3_cubics;
  std::vector<std::string> runs_as_drawn;
  FairedPieces pieces;
  std::vector<CornerJoin> corners;
};

/// A line from a to b as an exported piece.
FairedPiece line_piece(Vec2 a, Vec2 b, bool smooth_start);

/// The plan's runs faired (through `cache`) on `basis` within `budgets.chain`, their chains
/// written as cubics within `budgets.cubic`, and the lines between them; the first run that
/// fails ends it with its reason, unless `as_drawn`, where an open run that fails is kept as the
/// source draws it instead of failing the contour. `after_run_failure`: the budgets were halved
/// because a run failed, so a run faired within a larger budget stands (FairedRuns::get).
FairedPlan fair_plan(const ContourPlan& plan, const FairSettings& settings, Budgets budgets, FairedRuns& cache,
                     bool after_run_failure, RunBasis basis, bool as_drawn = false);

}  // namespace gf
