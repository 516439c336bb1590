#include "fair/plan_fairing.hpp"

#include <sstream>

#include "fair/cubic_writeback.hpp"
#include "geom/arc_length.hpp"
#include "geom/curvature.hpp"

namespace gf {

namespace {

// Of the writeback's budget, what making a run kept as drawn G1 at its kinks may move it
// (drawn_nodes): the run is the source itself, and the rounding keeps its own reserve.
constexpr double drawn_move_share = 0.5;

// Of the writeback's budget, what a G3 chain's span with its end curvatures freed may use
// (SpanCutting::freed_span_budget_share): the G3 cubics need the rest. Off the grid only: on it
// the G3 cubics need every node they have, and with the extrema's curvatures freed DejaVu
// Sans's median dκ/ds jump (a–z A–Z, rounded) went 0.033 → 0.077, over the G3 bar of 0.05.
constexpr double g3_freed_span_share = 0.5;

// Assembles the faired pieces in order; nodes where two pieces meet are merged.
class NodeAssembler {
 public:
  void append(std::vector<OutlineNode> piece, bool smooth_join) {
    if (piece.empty()) return;
    if (!nodes_.empty() && distance(nodes_.back().point, piece.front().point) < 1e-9) {
      OutlineNode& joint = nodes_.back();
      joint.out_handle = piece.front().out_handle;
      joint.smooth = smooth_join;
      if (piece.front().grid_step) joint.grid_step = piece.front().grid_step;
      piece.erase(piece.begin());
    } else {
      piece.front().smooth = false;  // after a gap (or first): a corner until a join says otherwise
    }
    for (OutlineNode& n : piece) nodes_.push_back(std::move(n));
  }
  /// A closed contour: the last node is the first one again.
  void close(bool smooth_join) {
    if (nodes_.size() > 1 && distance(nodes_.back().point, nodes_.front().point) < 1e-9) {
      nodes_.front().in_handle = nodes_.back().in_handle;
      nodes_.front().smooth = smooth_join;
      nodes_.pop_back();
    }
  }
  std::vector<OutlineNode>& nodes() { return nodes_; }

 private:
  std::vector<OutlineNode> nodes_;
};

// The chain's pieces for export, the first one's join as `smooth_start` says.
void record_chain(const FairedChain& chain, bool smooth_start, FairedPieces& out) {
  const std::size_t first = out.size();
  for (const LogAestheticSegment& s : chain.segments)
    out.push_back({.kind = FairedPieceKind::log_aesthetic, .length = s.length(), .start = s.start(), .end = s.end(),
                   .alpha = s.alpha(), .smooth_start = true});
  for (const PolynomialSpiral& s : chain.spirals)
    out.push_back({.kind = FairedPieceKind::polynomial_spiral, .length = s.length(), .start = s.start(), .end = s.end(),
                   .smooth_start = true, .bumps = std::pair{s.symmetric_bump(), s.odd_bump()}});
  if (chain.guide) {
    LacPoint a = chain.start_frame(), b = chain.end_frame();
    a.curvature_derivative = b.curvature_derivative = std::nullopt;
    out.push_back({.kind = FairedPieceKind::guide, .length = chain.guide->s1 - chain.guide->s0, .start = a, .end = b,
                   .smooth_start = true});
  }
  if (out.size() > first) out[first].smooth_start = smooth_start;
}

// Where a piece starts and ends once faired: a run may have slid its ends along the lines it
// meets (fair/g3_run.hpp; leave_line_earlier in fair/chain_fairing.cpp), and the lines follow.
LacPoint faired_start(const FairedRun& run) { return run.chains.front().start_frame(); }
LacPoint faired_end(const FairedRun& run) { return run.chains.back().end_frame(); }

// A run no basis fairs, as the source draws it: its nodes, smooth where the source is G1 or
// breaks G1 by less than the kink limit (made G1 there, each handle moving its cubic by at most
// `most_move`: join_nearly_smooth_node), and its cubics recorded as pieces. The run keeps its
// curves, not the source's kinks (EB Garamond's N: ten of them, 0.3° to 2.3°).
std::vector<OutlineNode> drawn_nodes(const SmoothRun& run, double most_move, FairedPieces& pieces) {
  std::vector<OutlineNode> drawn(run.cubics.size() + 1);
  for (std::size_t k = 0; k < run.cubics.size(); ++k) {
    const Cubic& c = run.cubics[k];
    drawn[k].point = c.p[0], drawn[k].out_handle = c.p[1], drawn[k + 1].in_handle = c.p[2];
    drawn[k].smooth = false;
    const Segment s = c;
    const auto frame = [&](SegmentEnd end, Vec2 at) {
      return LacPoint{at, end_tangent(s, end).value_or(Vec2{}), end_curvature(s, end).curvature.value_or(0.0),
                      std::nullopt};
    };
    pieces.push_back({.kind = FairedPieceKind::as_drawn, .length = arc_length_estimate(s),
                      .start = frame(SegmentEnd::start, c.p[0]), .end = frame(SegmentEnd::end, c.p[3])});
  }
  drawn.back().point = run.cubics.back().p[3];
  drawn.back().smooth = false;
  for (std::size_t k = 1; k + 1 < drawn.size(); ++k) join_nearly_smooth_node(drawn[k], radians(kink_limit_deg), most_move);
  return drawn;
}

}  // namespace

const FairedRun& FairedRuns::get(const SmoothRun& run, const FairSettings& settings, double budget, bool larger_stands,
                                 RunBasis basis) {
  // A contour's first run to fail on its own outline ends that attempt, so on the guides the
  // runs after it come untried on their own. Where a guide fails, the run's own outline serves
  // rather than the contour falling to the last basis and its stalled chains (Lato's W: one
  // cap's guide failed, and a flank kept a chain with κ·UPM −34 and 19 across a junction).
  // Their own outline first for all of them moved more rounded joins than it mended (Lato's
  // a–z A–Z g2-jumps 17 → 23, FreeSerif's 12 → 15).
  if (basis == RunBasis::guide) {
    const FairedRun& guided = find_or_fair(run, settings, budget, larger_stands, basis);
    if (guided.ok) return guided;
    const FairedRun& own = find_or_fair(run, settings, budget, larger_stands, RunBasis::own);
    return own.ok ? own : guided;
  }
  return find_or_fair(run, settings, budget, larger_stands, basis);
}

const FairedRun& FairedRuns::find_or_fair(const SmoothRun& run, const FairSettings& settings, double budget,
                                          bool larger_stands, RunBasis basis) {
  for (const RunFairings::Entry* e : entries_)
    if (e->run == run && (e->budget == budget || (larger_stands && e->faired.ok && e->budget > budget)) &&
        (e->basis == basis || (e->basis == RunBasis::own && e->faired.ok)))
      return e->faired;
  entries_.push_back(&memo_.fair(run, settings, budget, basis));
  return entries_.back()->faired;
}

namespace {

// The settings as fair_run reads them: what only the writeback and rounding read set aside
// (FairSettings says which).
FairSettings runs_settings(FairSettings s) {
  s.free_node_curvatures = false;
  s.split_beside_jumps = false;
  s.remove_spare_nodes = false;
  s.turn_inflection_nodes = false;
  s.fit_spare_runs = false;
  s.rounding_reserve_units = 0.0;
  s.shortest_rounded_span_units = 0.0;
  return s;
}

}  // namespace

const RunFairings::Entry& RunFairings::fair(const SmoothRun& run, const FairSettings& settings, double budget,
                                            RunBasis basis) {
  const FairSettings read = runs_settings(settings);
  for (const Entry& e : entries_)
    if (e.budget == budget && e.basis == basis && e.settings == read && e.run == run) return e;
  entries_.push_back({run, read, budget, basis, fair_run(run, settings, budget, basis)});
  return entries_.back();
}

FairedPiece line_piece(Vec2 a, Vec2 b, bool smooth_start) {
  const Vec2 t = (b - a) / distance(a, b);
  return {.kind = FairedPieceKind::line, .length = distance(a, b), .start = {a, t, 0.0, 0.0}, .end = {b, t, 0.0, 0.0},
          .smooth_start = smooth_start};
}

FairedPlan fair_plan(const ContourPlan& plan, const FairSettings& settings, Budgets budgets, FairedRuns& cache,
                     bool after_run_failure, RunBasis basis, bool as_drawn) {
  FairedPlan a;
  const bool hand = settings.profile == FairProfile::handwriting;
  const SpanCutting cutting{
      .shortest_span = settings.rounding == Rounding::integers ? settings.shortest_rounded_span_units : shortest_span_units,
      .evenly = hand,
      .no_inner_extrema = hand,
      .free_node_curvatures = settings.free_node_curvatures};
  const std::size_t count = plan.pieces.size();
  std::vector<std::optional<FairedRun>> runs(count);
  for (std::size_t i = 0; i < count; ++i) {
    const SmoothRun* run = std::get_if<SmoothRun>(&plan.pieces[i]);
    if (!run) continue;
    runs[i] = cache.get(*run, settings, budgets.chain, after_run_failure, basis);
    if (runs[i]->ok) continue;
    if (!as_drawn || run->closed) {
      a.failure = runs[i]->reason;
      return a;
    }
    const Vec2 p = run->cubics.front().p[0];
    std::ostringstream where;
    where << "the run from (" << p.x << ", " << p.y << ") kept as drawn: " << runs[i]->reason;
    a.runs_as_drawn.push_back(where.str());
  }
  const auto moved_run_at = [&](std::size_t i) { return runs[i] && runs[i]->ends_moved() ? &*runs[i] : nullptr; };
  NodeAssembler assembler;
  bool previous_ends_smooth = false;  // how the last piece ended: the join to the next piece
  std::vector<bool> smooth_before(count, false);  // the join in front of each piece
  std::vector<Vec2> starts(count);                // where each piece starts once faired
  const auto append_line = [&](std::size_t i, Vec2 from, Vec2 to, bool smooth_start) {
    OutlineNode start, end;
    start.point = from, end.point = to;
    start.smooth = smooth_before[i] = smooth_start;
    starts[i] = from;
    a.pieces.push_back(line_piece(from, to, smooth_start));
    assembler.append({start, end}, smooth_start);
    previous_ends_smooth = false;
  };
  for (std::size_t i = 0; i < count; ++i) {
    if (const Line* line = std::get_if<Line>(&plan.pieces[i])) {
      Vec2 start = line->start(), end = line->end();
      const bool wraps = plan.closed && count > 1;
      if (i > 0 || wraps)
        if (const FairedRun* before = moved_run_at((i + count - 1) % count)) start = faired_end(*before).point;
      if (i + 1 < count || wraps)
        if (const FairedRun* after = moved_run_at((i + 1) % count)) end = faired_start(*after).point;
      append_line(i, start, end, previous_ends_smooth);
      continue;
    }
    const SmoothRun& run = std::get<SmoothRun>(plan.pieces[i]);
    const FairedRun& faired = *runs[i];
    if (!faired.ok) {
      // As drawn, joined to what comes before smooth only where the source is exactly G1; no
      // corner of the plan here to be made smooth and faired again.
      std::vector<OutlineNode> drawn = drawn_nodes(run, drawn_move_share * budgets.cubic, a.pieces);
      const std::vector<OutlineNode>& before = assembler.nodes();
      const bool joined = !before.empty() && distance(before.back().point, drawn.front().point) < 1e-9 &&
                          exactly_collinear(arriving_direction(before, before.size() - 1), leaving_direction(drawn, 0));
      smooth_before[i] = true;
      starts[i] = drawn.front().point;
      assembler.append(std::move(drawn), joined);
      previous_ends_smooth = false;
      continue;
    }
    if (faired.chains.empty()) {
      // Too short for a chain (a few units between two turns): its chord, a corner at each end.
      append_line(i, run.cubics.front().p[0], run.cubics.back().p[3], false);
      continue;
    }
    a.guide_stretches += faired.guide_stretches;
    if (faired.g3()) ++a.g3_runs, a.g2_line_joins += faired.g2_line_joins;
    else if (!faired.g3_shortfall.empty()) a.g3_shortfalls.push_back(faired.g3_shortfall);
    // A closed run's chains meet at inflections, G1 there like every join inside a run.
    const bool start_smooth = run.closed || run.start.kind == RunEndKind::line;
    smooth_before[i] = start_smooth || previous_ends_smooth;
    starts[i] = faired_start(faired).point;
    // The inflections between chains that the writeback turns onto an axis (flat_inflection_axis).
    const std::size_t chains = faired.chains.size();
    std::vector<std::optional<Vec2>> flat_axis(chains);  // at the end of chain k
    for (std::size_t k = 0; k + 1 < chains || (run.closed && chains > 1 && k < chains); ++k)
      flat_axis[k] = flat_inflection_axis(faired.chains[k], faired.chains[(k + 1) % chains], budgets.cubic);
    for (std::size_t k = 0; k < chains; ++k) {
      const FairedChain& chain = faired.chains[k];
      a.mismatch = std::max(a.mismatch, chain.max_mismatch_relative);
      ChainEnds ends;
      ends.start_corner = k == 0 && !run.closed && run.start.kind == RunEndKind::corner;
      ends.end_corner = k + 1 == chains && !run.closed && run.end.kind == RunEndKind::corner;
      if (ends.start_corner) ends.start_run_end = run.start;
      if (ends.end_corner) ends.end_run_end = run.end;
      ends.end_axis = flat_axis[k];
      if (k > 0 || (run.closed && chains > 1)) ends.start_axis = flat_axis[(k + chains - 1) % chains];
      SpanCutting chain_cutting = cutting;
      if (!chain.spirals.empty()) {
        chain_cutting.free_node_curvatures = cutting.free_node_curvatures && settings.rounding != Rounding::integers;
        chain_cutting.freed_span_budget_share = g3_freed_span_share;
      }
      ChainCubics cubics = write_chain_as_cubics(chain, budgets.cubic, settings.flat_curvature(), ends, chain_cutting);
      a.g1_nodes += cubics.g1_fallbacks;
      a.freed_nodes += cubics.freed_nodes;
      const bool join_smooth = k > 0 || start_smooth || previous_ends_smooth;
      record_chain(chain, chain.closed || join_smooth, a.pieces);
      if (chain.closed) {
        a.nodes = std::move(cubics.nodes);
        return a;
      }
      assembler.append(std::move(cubics.nodes), join_smooth);
    }
    previous_ends_smooth = run.ends_at_line();
    if (!assembler.nodes().empty()) assembler.nodes().back().smooth = previous_ends_smooth;
  }
  if (plan.closed) {
    // The first node's join: the last piece's end kind, or, for a run first, the run's start
    // (smooth where it meets a line or closes on itself).
    bool smooth = previous_ends_smooth;
    if (const SmoothRun* first = std::get_if<SmoothRun>(&plan.pieces.front()))
      smooth = first->closed || first->start.kind == RunEndKind::line;
    assembler.close(smooth);
    if (!a.pieces.empty()) a.pieces.front().smooth_start = smooth;
    smooth_before[0] = smooth;
  }
  for (std::size_t i = plan.closed ? 0 : 1; i < count; ++i)
    if (!smooth_before[i]) a.corners.push_back({plan.start_nodes[i], starts[i]});
  a.nodes = std::move(assembler.nodes());
  return a;
}

}  // namespace gf
