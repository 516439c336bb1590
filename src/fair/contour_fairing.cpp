#include "fair/contour_fairing.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <functional>
#include <limits>
#include <optional>
#include <span>
#include <sstream>
#include <utility>

#include "fair/contour_plan.hpp"
#include "fair/corner_end_lobes.hpp"
#include "fair/cubic_writeback.hpp"
#include "fair/g3_cubics.hpp"
#include "fair/join_mending.hpp"
#include "fair/kinked_corners.hpp"
#include "fair/leaning_line_ends.hpp"
#include "fair/line_kinks.hpp"
#include "fair/outline_faults.hpp"
#include "fair/outline_on_grid.hpp"
#include "fair/plan_fairing.hpp"
#include "fair/run_fairing.hpp"
#include "fair/spare_nodes.hpp"
#include "fair/spurs.hpp"
#include "fair/stem_jogs.hpp"
#include "fair/tight_turn.hpp"
#include "fair/upright_lines.hpp"
#include "geom/arc_length.hpp"
#include "geom/curvature.hpp"

namespace gf {

namespace {

// Of the tolerance, how far a fillet onto a leaning line's axis may move the outline.
constexpr double leaning_move_share = 0.25;

// Start where the source starts when that node survived, else at the nearest node.
void rotate_to_start(std::vector<OutlineNode>& nodes, Vec2 source_start) {
  if (nodes.empty()) return;
  const std::size_t first = nearest_node(nodes, source_start);
  std::rotate(nodes.begin(), nodes.begin() + static_cast<std::ptrdiff_t>(first), nodes.end());
}

// What the cubics may spend on G3: what the float outline leaves of the tolerance at each
// cubic, less g3_rounding_reserve when the outline is rounded after (rounding then has at least
// that, 5 % kept for sampling); more left rounding no fewer g2-jumps and fewer joins G3 (Lato,
// DejaVu Sans Bold and Serif, Inter, Liberation Serif at 1 and 1.25 units). At most
// g3_reserve_share of the tolerance: on a 1000-unit em (1.25 units) the float outline reaches
// past half of it, and 0.75 left the cubics nothing (TeX Gyre Heros a–z A–Z: 23 of 77 runs G3
// before rounding, κ′ jump median 0.100 after; at 0.3, 0.4, 0.5 of the tolerance 0.039, 0.040,
// 0.044 with g2-jumps 4, 3, 4; Cantarell's TV 0.956×, 0.931×, 0.935× of the source's, the bar
// 0.95×). And the nodes a contour may gain for it: the G3 issue allows 20 % over the G2 output,
// and the G3 curve itself takes up to 9 % (Inter).
constexpr double g3_rounding_reserve = 0.75, g3_reserve_share = 0.4;
constexpr double g3_node_share = 0.12;
constexpr double most_nodes_share = 1.3;  // of the source's nodes: the fairing issue's bar

// --continuity g3: the written cubics made as G3 as their allowances let them (fair/g3_cubics),
// the nodes they add held within g3_node_share of the cubics, and within the fairing issue's
// bar of 1.3 times the source's nodes (`source_nodes`), which the G3 output must keep too (TeX
// Gyre Heros a–z A–Z: 1.18× under G2, 1.31× with 17 nodes added for G3).
G3CubicReport carry_g3_into_cubics(std::vector<OutlineNode>& nodes, bool closed, const SampledContour& sampled_source,
                                   std::size_t source_nodes, const FairSettings& settings) {
  const double reserve = settings.rounding == Rounding::integers
                             ? std::min(g3_rounding_reserve, g3_reserve_share * settings.tolerance_units)
                             : 0.0;
  const std::vector<double> allowance =
      tolerance_left_at(nodes, closed, sampled_source, settings.tolerance_units, reserve);
  std::size_t cubics = 0;
  for (const OutlineNode& node : nodes) cubics += node.out_handle.has_value();
  const int budget = g3_node_budget(cubics, nodes.size(), source_nodes, g3_node_share, most_nodes_share);
  return make_cubics_g3(nodes, closed, allowance, {settings.flat_curvature(), budget});
}

// On the grid, curves meeting lines that lean a little off an axis join them through a fillet
// from the axis (fair/leaning_line_ends.hpp), each moving the outline by up to a quarter of the
// tolerance; kept where the outline stays within `available`, what the float outline may use.
// A fillet's end can land a unit short of the curve's next node (Comic Neue's d and g, Kristi's
// N, Gentium Plus's M: each rounded to a cubic folded on that unit), so short cubics are merged
// again where a fillet went in.
void fillet_leaning_lines(std::vector<OutlineNode>& nodes, bool closed, const SampledContour& sampled_source,
                          const FairSettings& settings, double available) {
  std::vector<OutlineNode> filleted = nodes;
  LeaningLineLimits limits;
  limits.max_move_units = leaning_move_share * settings.tolerance_units;
  if (fillet_leaning_line_ends(filleted, closed, limits) == 0) return;
  if (!within_distance(SampledContour(to_contour(filleted, closed)), sampled_source, available)) return;
  nodes = std::move(filleted);
  merge_tiny_cubics(nodes, closed, tiny_cubic_chord);
}

// Handwriting: a corner's short lobe bending against the stroke's edge beyond it becomes part of
// one cubic from the corner (fair/corner_end_lobes.hpp), each within what the outline leaves of
// `available` at the cubics it replaces; kept where the whole outline stays within `available`.
void drop_lobes_at_corners(std::vector<OutlineNode>& nodes, bool closed, const SampledContour& sampled_source,
                           const FairSettings& settings, double available) {
  if (std::all_of(nodes.begin(), nodes.end(), [](const OutlineNode& q) { return q.smooth; })) return;
  std::vector<double> allowance =
      tolerance_left_at(nodes, closed, sampled_source, settings.tolerance_units, settings.tolerance_units - available);
  std::vector<OutlineNode> dropped = nodes;
  if (drop_corner_end_lobes(dropped, closed, allowance) == 0) return;
  if (!within_distance(SampledContour(to_contour(dropped, closed)), sampled_source, available)) return;
  nodes = std::move(dropped);
}

// How many times a contour has been faired on one plan and basis (fair_within_budgets), and
// how many times it may be: a fairing again (fair_contour) stops where the first did, and
// gives a plan up where its rounding strays instead of rounding again on halved allowances
// (EB Garamond's K, at 0.9 of the tolerance: fourteen more roundings of half a second each).
struct Tries {
  int made = 0;
  int most = std::numeric_limits<int>::max();
  /// Whether a rounding that strays is rounded again on halved allowances (false: the plan is
  /// given up after the rounding with its lines' ends kept within their allowance).
  bool halving_allowances = true;
  /// Nodes whose curvature the tries' writebacks moved off the faired path's (ChainCubics::freed_nodes).
  int freed_nodes = 0;
  /// Spare nodes the tries' fairings removed (fair/spare_nodes).
  int spare_nodes_removed = 0;
  /// Of those, how many only with an inflection node's tangent turned (SpareNodeRemoval::turned).
  int spare_nodes_turned = 0;
  /// Of those, how many with their run fitted again whole (SpareNodeRemoval::in_runs).
  int spare_nodes_in_runs = 0;
};

// The contour faired on one plan: the budgets halved once when the first try strays, the
// outline rounded when asked; the runs that fail on their own outlines faired on `basis`.
// `kinked` gets the corners of the result that turn by less than the kink limit.
ContourFairing fair_within_budgets(const Contour& source, const ContourPlan& plan, const SampledContour& sampled_source,
                                   const FairSettings& settings, FairedRuns& cache, Tries& tries, RunBasis basis,
                                   std::vector<std::size_t>& kinked, bool as_drawn = false) {
  ContourFairing out;
  out.contour = source;
  if (tries.made >= tries.most) {
    out.reason = "no more tries than its first fairing took";
    return out;
  }
  ++tries.made;
  const bool round = settings.rounding == Rounding::integers;
  double available =
      std::max(settings.tolerance_units - (round ? settings.rounding_reserve_units : 0.0), 0.25 * settings.tolerance_units);
  bool run_failed = false;
  // On the guides, one try: a second, with half the budget, took whole DejaVu Sans 8 % more
  // time to fair 18 more contours.
  const int attempts = basis == RunBasis::guide ? 1 : 2;
  for (int attempt = 0; attempt < attempts; ++attempt, available *= 0.5) {
    FairedPlan a = fair_plan(plan, settings, {settings.chain_share * available, (1.0 - settings.chain_share) * available},
                                  cache, run_failed, basis, as_drawn);
    tries.freed_nodes += a.freed_nodes;
    run_failed = !a.failure.empty();
    if (run_failed) {
      out.reason = a.failure;
      continue;
    }
    drop_empty_cubics(a.nodes, source.closed);
    if (round) merge_tiny_cubics(a.nodes, source.closed, tiny_cubic_chord);
    rotate_to_start(a.nodes, source.node_point(0));
    if (settings.profile == FairProfile::handwriting)
      drop_lobes_at_corners(a.nodes, source.closed, sampled_source, settings, available);
    if (round) fillet_leaning_lines(a.nodes, source.closed, sampled_source, settings, available);
    std::vector<OutlineNode> with_spares;  // the outline before its spare nodes went, where some did
    SpareNodeRemoval spares;
    if (settings.remove_spare_nodes) {
      std::vector<OutlineNode> kept = a.nodes;
      spares = remove_spare_nodes(a.nodes, source.closed, sampled_source,
                                  {available, settings.units_per_em, settings.turn_inflection_nodes,
                                   settings.fit_spare_runs});
      if (spares.removed > 0) with_spares = std::move(kept);
    }
    // A fairing asked to turn inflection nodes that turns none would round what the fairing
    // without turning rounded: given up before its rounding, the costly part (DejaVu Sans's
    // U+2765: 0.9 s a try).
    if (settings.turn_inflection_nodes && spares.turned == 0) {
      tries.made = tries.most;
      out.reason = "no inflection node's tangent turned";
      return out;
    }
    if (settings.continuity == Continuity::g3)
      a.g3_cubics = carry_g3_into_cubics(a.nodes, source.closed, sampled_source, source.node_count(), settings);
    auto [faired, d] = settle_on_grid(a.nodes, source.closed, sampled_source, settings, tries.halving_allowances);
    // The merged cubics may spend the whole budget, and rounding then stray past its reserve
    // where the spare nodes' shorter cubics did not (EB Garamond's G, which then took another
    // basis and kept runs as drawn): rounded again with them.
    if (d > settings.tolerance_units && !with_spares.empty()) {
      a.nodes = std::move(with_spares);
      OutlineOnGrid again = settle_on_grid(a.nodes, source.closed, sampled_source, settings, tries.halving_allowances);
      faired = std::move(again.contour), d = again.deviation, spares = {};
    }
    tries.spare_nodes_removed += spares.removed;
    tries.spare_nodes_turned += spares.turned;
    tries.spare_nodes_in_runs += spares.in_runs;
    // Where rounding strayed, on the last budget only: a smaller budget that rounds within the
    // tolerance leaves the lines whole (Gentium Plus's V: split on the first, its curvature
    // variation 651 → 750).
    const bool last = attempt + 1 == attempts;
    if (std::optional<SplitOnGrid> lined =
            d <= settings.tolerance_units || last
                ? rounded_with_line_splits(source, a.nodes, {faired, d}, sampled_source, settings, available,
                                           tries.halving_allowances)
                : std::nullopt) {
      a.nodes = std::move(lined->nodes);
      faired = std::move(lined->outline.contour), d = lined->outline.deviation;
    }
    int split_nodes = 0;
    std::optional<OutlineOnGrid> split;
    if (d <= settings.tolerance_units)
      split = rounded_with_splits(source, a.nodes, faired, sampled_source, settings, tries.halving_allowances);
    if (split) {
      split_nodes = static_cast<int>(split->contour.segments.size()) - static_cast<int>(faired.segments.size());
      faired = std::move(split->contour), d = split->deviation;
    }
    if (d <= settings.tolerance_units) {
      out.contour = std::move(faired);
      out.faired = true;
      out.reason.clear();
      out.deviation = d;
      out.max_curvature_mismatch = a.mismatch;
      out.g1_nodes = a.g1_nodes;
      out.guide_stretches = a.guide_stretches;
      out.basis = basis;
      out.split_nodes = split_nodes;
      out.g3_runs = a.g3_runs;
      out.g2_line_joins = a.g2_line_joins;
      out.g3_shortfalls = std::move(a.g3_shortfalls);
      out.g3_cubics = a.g3_cubics;
      out.runs_as_drawn = std::move(a.runs_as_drawn);
      out.pieces = std::move(a.pieces);
      kinked = kinked_corners(out.contour, a.corners);
      return out;
    }
    out.reason = std::isfinite(d) ? "the faired contour came out " + std::to_string(d) + " units from the source"
                                  : std::string("the faired contour collapsed to nothing");
  }
  return out;
}

// A text contour that cannot be faired on its own outlines is faired again with the runs that
// failed there on their smoothing guides, and then on their own outlines with the jumps of
// stalled chains (RunBasis); why the first try failed is what is reported when none fairs.
// Where `opened` gives one (the plan with its kinks against lines opened,
// PlanOptions::open_against_lines: those kinks may be what left no G2 chain), on each basis on
// that plan first; it is asked only then.
ContourFairing fair_planned(const Contour& source, const ContourPlan& plan,
                            const std::function<std::optional<ContourPlan>()>& opened,
                            const SampledContour& sampled_source, const FairSettings& settings, FairedRuns& cache,
                            Tries& tries, std::vector<std::size_t>& kinked) {
  const auto on = [&](const ContourPlan& p, RunBasis basis, bool as_drawn = false) {
    return fair_within_budgets(source, p, sampled_source, settings, cache, tries, basis, kinked, as_drawn);
  };
  ContourFairing own = on(plan, RunBasis::own);
  if (own.faired) return own;
  const bool text = settings.profile == FairProfile::text;
  if (const std::optional<ContourPlan> other = opened())
    for (const RunBasis basis : {RunBasis::own, RunBasis::guide, RunBasis::own_with_jumps})
      if (ContourFairing again = on(*other, basis); again.faired) return again;
  if (text)
    for (const RunBasis next : {RunBasis::guide, RunBasis::own_with_jumps})
      if (ContourFairing again = on(plan, next); again.faired) return again;
  // Last, the runs that fail on the last basis kept as drawn, the rest faired (EB Garamond's t
  // and K: one cap's or serif's run of a dozen kept the whole contour unfaired).
  ContourFairing partly = on(plan, text ? RunBasis::own_with_jumps : RunBasis::own, true);
  return partly.faired ? partly : own;
}

// How many times corners that came out as kinks are made smooth and the contour faired again.
// Lines a pass merges meet their neighbour at a new angle: Breip's F (a curve tangent to a
// 15-unit vertical line, then three lines 3° apart) takes three passes, the third making the
// curve's join smooth, which two left a kink of 0.9°.
constexpr int kink_passes = 8;

// The kinks left between two lines (no run passes through them, and merging the lines strays:
// Inter's Q tail, Cantarell's y) taken away within the tolerance (fair/line_kinks.hpp).
void fillet_kinks(ContourFairing& out, const Contour& source, const FairSettings& settings) {
  LineKinksTaken taken = without_line_kinks(out.contour, out.deviation, source, settings.tolerance_units,
                                            settings.rounding == Rounding::integers);
  if (taken.changed) out.contour = std::move(taken.contour), out.deviation = taken.deviation;
}

// The contour faired on `curve` (the source, or the same curve split at its tight `turns`, its
// stem jogs perhaps straightened and nearly upright lines stood up): planned, its runs faired,
// and corners that came out as kinks made smooth. Its distances are measured from
// `reference`: `curve` itself, or the source where anything was straightened.
ContourFairing fair_curve(const Contour& source, const Contour& curve, const Contour& reference,
                          std::span<const TightTurn> turns, const FairSettings& settings, Tries& tries,
                          RunFairings& memo) {
  ContourFairing out;
  out.contour = source;
  PlanOptions options{settings.corner_angle_deg, settings.profile == FairProfile::text};
  if (settings.stub_line_units) options.stub_line_units = *settings.stub_line_units;
  options.stub_turn_deg = settings.stub_turn_deg;
  // `open`: with PlanOptions::open_against_lines.
  const auto plan_with = [&](std::span<const std::size_t> smooth_nodes, bool open = false) {
    PlanOptions o = options;
    o.open_against_lines = open;
    ContourPlan p = plan_contour(curve, smooth_nodes, o);
    aim_runs_at_tight_turns(p, turns);
    return p;
  };
  const ContourPlan plan = plan_with({});
  if (plan.pieces.empty()) {
    out.reason = "nothing to fair (every segment degenerate)";
    return out;
  }
  const bool has_curve = std::any_of(plan.pieces.begin(), plan.pieces.end(),
                                     [](const auto& p) { return std::holds_alternative<SmoothRun>(p); });
  if (!has_curve) {
    out.faired = true;  // lines only: as fair as it gets, but for its kinks
    for (const auto& piece : plan.pieces)
      out.pieces.push_back(line_piece(std::get<Line>(piece).start(), std::get<Line>(piece).end(), false));
    return out;
  }
  const SampledContour sampled_source(reference);
  std::vector<std::size_t> kinked, smooth_nodes;
  FairedRuns cache(memo);
  // The contour faired on `p`, planned with `smooth` made smooth, and, where it has kinks
  // against lines to open (text), on the same plan with those opened after its own outlines fail.
  const auto fair_plans = [&](const ContourPlan& p, std::span<const std::size_t> smooth,
                              std::vector<std::size_t>& kinks) {
    const auto opened = [&]() -> std::optional<ContourPlan> {
      if (!options.corners_stay) return std::nullopt;
      ContourPlan o = plan_with(smooth, true);
      if (opened_corners(o) == 0) return std::nullopt;
      return o;
    };
    return fair_planned(curve, p, opened, sampled_source, settings, cache, tries, kinks);
  };
  // The contour faired with the kinks where curves meet lines corners, as drawn, and no kink
  // pass making them smooth again; none where it has no such kink.
  const auto fair_cornered = [&]() -> std::optional<ContourFairing> {
    const double tangential_line_deg = std::exchange(options.tangential_line_deg, JoinThresholds{}.smooth_max_deg);
    const ContourPlan cornered_plan = plan_with({});
    options.tangential_line_deg = tangential_line_deg;
    if (cornered_plan.pieces == plan.pieces) return std::nullopt;
    std::vector<std::size_t> as_drawn;
    return fair_plans(cornered_plan, {}, as_drawn);
  };
  if (settings.line_kinks_as_drawn) {
    std::optional<ContourFairing> cornered = fair_cornered();
    if (!cornered) {
      out.reason = "no kink where a curve meets a line";
      return out;
    }
    if (!cornered->faired) cornered->contour = source;  // as it was, not split at its turns
    return std::move(*cornered);
  }
  out = fair_plans(plan, {}, kinked);
  // A contour that does not fair with its curves made tangential to the lines they meet at a
  // kink is faired with those kinks corners (Comic Neue's u and i: stems' lines 0.8° off the
  // vertical, kinked so at both ends against their curves' vertical tangents; the i's foot had
  // no drawable G2 chain, and the u's line has grid steps of 60 units or more, so no handle on
  // it seats a curve within the tolerance: each contour had been kept unfaired).
  if (!out.faired) {
    if (std::optional<ContourFairing> cornered = fair_cornered(); cornered && cornered->faired) out = std::move(*cornered);
    kinked.clear();
  }
  // A corner whose faired pieces meet by less than the kink limit was noise the fairing
  // straightened (or a scan's few degrees at a line): made smooth, it becomes G2 instead of
  // a kink. Kept only when the contour still fairs; once every corner still kinked was made
  // smooth before, the next pass would plan the same.
  const auto made_smooth = [&](std::size_t node) {
    return std::find(smooth_nodes.begin(), smooth_nodes.end(), node) != smooth_nodes.end();
  };
  for (int pass = 0; pass < kink_passes && out.faired && !kinked.empty(); ++pass) {
    smooth_nodes.insert(smooth_nodes.end(), kinked.begin(), kinked.end());
    std::vector<std::size_t> still;
    ContourFairing again = fair_plans(plan_with(smooth_nodes), smooth_nodes, still);
    if (!again.faired || again.runs_as_drawn.size() > out.runs_as_drawn.size()) break;
    out = std::move(again);
    kinked = std::move(still);
    if (std::all_of(kinked.begin(), kinked.end(), made_smooth)) break;
  }
  if (!out.faired) out.contour = source;  // as it was, not split at its turns
  return out;
}

// An upright line's ends, and a straightened jog's, move by at most half the tolerance (a jog
// is noise, and its stem straight within it; a line's end a unit off the axis on a 2,048-unit
// em, Open Sans's Q foot, needs 0.39 of it) and 3 units: the rest is the fairing's.
constexpr double upright_move_share = 0.5, jog_move_share = 0.5, most_jog_move = 3.0;

}  // namespace

// The nodes a split adds where rounding left a jump (fair/jump_splits.hpp) are what it costs:
// Accanthis's c, a fairing leaving rounding 0.75 units drew it with 28 nodes and a jump a split
// mended, against 23 nodes and a jump before it, and 21 and none at 0.9 of the tolerance after.
bool replaces_kept_fairing(const ContourFairing& again, const OutlineFaults& again_faults, const ContourFairing& kept,
                           const OutlineFaults& kept_faults, std::size_t source_nodes) {
  const auto nodes = [](const ContourFairing& f) { return static_cast<int>(f.contour.segments.size()); };
  if (again.split_nodes > 0 && nodes(again) - again.split_nodes > nodes(kept)) return false;
  if (again.mended_joins > 0 && nodes(again) > most_nodes_share * static_cast<double>(source_nodes) &&
      nodes(again) - nodes(kept) > kept_faults.at_smooth_joins() - again_faults.at_smooth_joins())
    return false;
  return fewer_faults(again_faults, kept_faults);
}

double contour_distance(const Contour& a, const Contour& b) {
  return distance_between(SampledContour(a), SampledContour(b));
}

namespace {

// Each side of a contour may move by the tolerance; past half its thickness the two sides
// could cross and turn it inside out (a brush font's 5-unit speck, faired at 10, came out
// reversed). So a thin contour is faired, and its joins mended, to half its thickness; a
// closed one that encloses no area, not at all (none).
std::optional<double> contour_tolerance(const Contour& source, const FairSettings& settings) {
  if (!source.closed) return settings.tolerance_units;
  const double thick = thickness(source);
  if (thick == 0.0) return std::nullopt;
  return std::min(settings.tolerance_units, 0.5 * thick);
}

// `settings.rounding` resolved on the contour.
ContourFairing fair_contour_once(const Contour& source, const FairSettings& requested, Tries& tries, RunFairings& memo) {
  FairSettings settings = requested;
  ContourFairing out;
  out.contour = source;
  const std::optional<double> tolerance = contour_tolerance(source, settings);
  if (!tolerance) {
    out.reason = "it encloses no area";
    return out;
  }
  settings.tolerance_units = *tolerance;
  // Handwriting's spurs are cut first (fair/spurs.hpp: a scan's overshoot doubled back on
  // itself). On the grid, stem jogs are straightened (fair/stem_jogs.hpp: moves up to half the
  // tolerance) and then nearly upright lines a curve meets stand up (fair/upright_lines.hpp:
  // up to a quarter), before the fairing; its distances are still measured from the source.
  // (Taking the move off the tolerance instead changed the fairing of whole contours: Breip's
  // I came out with a spike by its notch.)
  MovedContour spurless{source};
  if (settings.profile == FairProfile::handwriting) spurless = cut_spurs(source, SpurLimits{});
  MovedContour straightened = spurless, upright = spurless;
  if (settings.rounding == Rounding::integers) {
    JogLimits jogs;
    jogs.max_move_units = std::min(most_jog_move, jog_move_share * settings.tolerance_units);
    straightened = straighten_stem_jogs(spurless.contour, jogs);
    UprightLimits limits;
    limits.max_move_units = std::min(limits.max_move_units, upright_move_share * settings.tolerance_units);
    upright = stand_lines_upright(straightened.contour, limits);
  }
  const Contour& stood = upright.contour;
  const bool any_stood = spurless.changes + straightened.changes + upright.changes > 0;
  // Handwriting's tight turns are corners (fair/tight_turn.hpp), unless the contour then fails.
  std::optional<TightTurns> turned;
  if (settings.profile == FairProfile::handwriting) {
    TightTurnLimits limits;
    limits.min_turn_deg = settings.corner_angle_deg, limits.deviation_units = settings.tolerance_units;
    if (TightTurns t = find_tight_turns(stood, limits); !t.turns.empty()) turned = std::move(t);
  }
  // What the fairing of `curve` measures its distances from.
  const auto reference_for = [&](const Contour& curve) -> const Contour& { return any_stood ? source : curve; };
  if (turned) out = fair_curve(source, turned->contour, reference_for(turned->contour), turned->turns, settings, tries, memo);
  if (!turned || !out.faired || !out.runs_as_drawn.empty()) {
    ContourFairing plain = fair_curve(source, stood, reference_for(stood), {}, settings, tries, memo);
    if (!out.faired || (plain.faired && plain.runs_as_drawn.size() < out.runs_as_drawn.size())) out = std::move(plain);
  }
  if (out.faired) fillet_kinks(out, source, settings);
  // The last word on direction: a faired contour that winds the other way would fill (or
  // cut) the opposite of what the source does.
  if (out.faired && source.closed && (signed_area(out.contour) > 0.0) != (signed_area(source) > 0.0)) {
    out = ContourFairing{};
    out.contour = source;
    out.reason = "the faired contour would wind the other way";
  }
  return out;
}

// On text, the rounded outline of a contour that keeps a curvature jump or a kink the check
// counts, or (since stop 86) more inflections than its source, is faired again, and the
// version with the fewest faults (fewer_faults) kept: which joins the grid can make G2 depends
// on where the fairing puts the nodes and how much of the tolerance it leaves rounding. Again
// leaving rounding a quarter unit more (0.75 units instead of half a unit), then half a unit
// more, then at 0.9 of the tolerance leaving it half a unit, then a whole unit, each only while
// faults are left. a–z A–Z, the ten text fonts still jumping: g2-jumps 161 with the first
// alone, 137 with the first again, 115 with the second, 111 with the third (Carlito 1 → 0),
// 102 with the fourth; 0.8 of the tolerance after the third, 109 for a third more time on EB
// Garamond (docs/fairing.md, stops 76 and 77). Last, with the writeback halving its spans
// down to twice its rounded shortest (16 units): a stroke's edge bending back and forth by a
// unit or two, written as cubics of 5 to 7 units, leaves whole steps no curvature to match
// (a–z A–Z of 27 fonts: EB Garamond's g2-jumps 57 → 53, its W; Caladea's 3 → 1, its y; no
// other font changed; at 24 units 54 and 1; halving so in every first fairing, EB Garamond 85;
// stop 80). Only a contour its first fairing took at most two tries (fair_within_budgets) to
// fair, and each fairing again stops there: of whole DejaVu Sans's contours that took more
// (another basis, a kink pass), none came out better, and they took most of the time. Not on
// handwriting, whose bar is a share of its joins, which it meets.
struct Refairing {
  double more_reserve_units = 0.0;  ///< added to FairSettings::rounding_reserve_units
  double tolerance_scale = 1.0;     ///< of FairSettings::tolerance_units
  double span_scale = 1.0;          ///< of FairSettings::shortest_rounded_span_units
};
constexpr std::array<Refairing, 5> refairings{{{0.25, 1.0}, {0.5, 1.0}, {0.0, 0.9}, {0.5, 0.9}, {0.0, 1.0, 2.0}}};
constexpr int most_tries_faired_again = 2;
// Then, while jumps or kinks are left, with other splits of the budget between the chain and
// its cubics (FairSettings::chain_share, text 0.4), the nodes' curvatures the path's, each kept
// only where it has fewer of those: the split sets where the writeback cuts its spans and how
// long their handles are, so which joins whole grid steps can match (a–z A–Z rounded, 44 text
// fonts: g2-jumps 89 → 69, Nimbus Sans 1 → 0, Linux Libertine's g; whole DejaVu Sans 35 → 22).
// Kept for fewer inflections alone, EB Garamond's W traded two beyond its source for a jump at
// a cap serif's flat top moved there from its leg. Ten splits (also 0.1, 0.2, 0.33, 0.5, 0.67
// and 0.85) took a–z A–Z to about 50, but whole DejaVu Sans past the 60 s bar on two cores
// (53 → 67 s); with the curvatures free too, no fewer jumps, and 9 s more.
constexpr std::array<double, 4> other_chain_shares{0.25, 0.6, 0.15, 0.75};

// A fairing's faults as the check counts them (fair/outline_faults), the jumps and kinks it
// leaves first mended on the grid (fair/join_mending) where that leaves fewer: whichever
// fairing is kept has had its joins searched, and a fairing again whose joins mend can replace
// one whose joins do not (TeX Gyre Schola's X). The source is sampled at the first mend.
class MendedFaults {
 public:
  MendedFaults(const Contour& source, const FairSettings& settings)
      : source_(source),
        counter_(source, settings.units_per_em),
        limits_{.tolerance_units = contour_tolerance(source, settings).value_or(0.0),  // none: never faired
                .units_per_em = settings.units_per_em} {}

  OutlineFaults operator()(ContourFairing& fairing) {
    const OutlineFaults faults = counter_.count(fairing.contour);
    if (faults.at_smooth_joins() == 0) return faults;
    if (!sampled_source_) sampled_source_.emplace(source_);
    Contour mended = fairing.contour;
    const MendedJoins m = mend_where_fewer_faults(mended, faults, counter_, *sampled_source_, limits_);
    if (m.mended == 0) return faults;
    fairing.deviation = std::max(fairing.deviation, distance_between(SampledContour(mended), *sampled_source_));
    fairing.contour = std::move(mended);
    fairing.mended_joins = m.mended;
    return m.faults;
  }

 private:
  const Contour& source_;
  FaultCounter counter_;
  JoinMendingLimits limits_;
  std::optional<SampledContour> sampled_source_;
};

// The fairings again of a contour `out` whose first fairing (`first` its tries, `memo` its
// runs) left `faults`, each kept where it has fewer (replaces_kept_fairing).
void refair_while_faulty(ContourFairing& out, OutlineFaults& faults, const Contour& source, FairSettings settings,
                         Tries first, RunFairings& memo, MendedFaults& count) {
  // With the nodes' curvatures free the writeback's cubics are fewer and differently long, and
  // the grid matches a join's curvature at some that it missed before and misses others (Comic
  // Neue's V: two kinks where its arms' lines meet the serifs; Accanthis's M, a jump where a
  // refairing had found none). So the refairings fair as before, with the nodes as the path
  // has them, and where the first fairing freed a node's curvature and fails, takes more tries
  // than the refairings allow or leaves faults, so does a fairing at the first settings: the
  // one with fewer faults kept (that one where the first did not come within those tries).
  // There each refairing is also tried with the curvatures free: a–z A–Z, g2-jumps EB
  // Garamond 31 → 26, Junicode 32 → 26, Quicksand 13 → 12 (and a lost corner fewer); no other
  // text font changed; whole DejaVu Sans 33.5 → 36.8 s.
  bool refair = out.faired && first.made <= most_tries_faired_again;
  const bool freed = settings.free_node_curvatures && (!out.faired || first.freed_nodes > 0);
  settings.free_node_curvatures = false;
  const auto better = [&](const ContourFairing& again, const OutlineFaults& again_faults) {
    return replaces_kept_fairing(again, again_faults, out, faults, source.segments.size());
  };
  if (freed && (!refair || faults.mendable())) {
    Tries fixed_tries;
    ContourFairing again = fair_contour_once(source, settings, fixed_tries, memo);
    const bool again_within = again.faired && fixed_tries.made <= most_tries_faired_again;
    if (again.faired) {
      const OutlineFaults again_faults = count(again);
      if (!out.faired || (!refair && again_within) || better(again, again_faults))
        out = std::move(again), faults = again_faults;
    }
    refair = again_within;
    first = fixed_tries;
  }
  if (!refair) return;
  // Each fairing again stops at as many tries as the first took, and is kept where it leaves
  // fewer faults (`mending_joins`: and fewer jumps and kinks).
  const auto fair_again = [&](const FairSettings& again_settings, bool mending_joins) {
    Tries again_tries{0, first.made, false};
    ContourFairing again = fair_contour_once(source, again_settings, again_tries, memo);
    if (!again.faired) return;
    const OutlineFaults again_faults = count(again);
    if (mending_joins && again_faults.at_smooth_joins() >= faults.at_smooth_joins()) return;
    if (better(again, again_faults)) out = std::move(again), faults = again_faults;
  };
  for (const Refairing& r : refairings) {
    for (const bool free : {false, true}) {
      if (!faults.mendable()) break;
      if (free && !freed) continue;
      FairSettings again_settings = settings;
      again_settings.free_node_curvatures = free;
      again_settings.rounding_reserve_units += r.more_reserve_units;
      again_settings.tolerance_units *= r.tolerance_scale;
      again_settings.shortest_rounded_span_units *= r.span_scale;
      fair_again(again_settings, false);
    }
  }
  for (const double share : other_chain_shares) {
    if (faults.at_smooth_joins() == 0) break;
    FairSettings again_settings = settings;  // its nodes' curvatures the path's
    again_settings.chain_share = share;
    fair_again(again_settings, true);
  }
}

// The fairings again of a contour `out` whose first fairing (`first` its tries, `memo` its
// runs) left `faults`, with its spare nodes (fair/spare_nodes) kept and removed.
//
// The spare nodes removed, a cubic rounds longer, and fewer nodes sit where the writeback put
// them for the grid: a first fairing that removed some and leaves jumps or kinks is faired
// again with them kept, kept where that leaves no more faults, and the refairings after it
// keep them too; so those start where stop 94's did (a mended fairing of more nodes replaces
// none of fewer: against a pruned first, Junicode's e and z kept a jump). a–z A–Z of 44 text
// fonts: g2-jumps 29, as at stop 94; with the spare nodes removed in every fairing 35 (Noto
// Serif's Y 0 → 1), and with the fairing again kept only where it has fewer faults 34.
//
// Since stop 107, where jumps or kinks are left so, the refairings run again from the first
// fairing with the spare nodes removed, and that is kept where it has fewer faults, or the
// same and fewer nodes; the first fairing itself is kept so too. The grid matches some joins
// of the longer cubics that it missed with the shorter (EB Garamond's G: a jump, 57 nodes,
// against none and 45). Not for every contour left with faults: where only inflections are
// left over the source's, the refairings again cost 5 s of whole DejaVu Sans's 52 and changed
// no figure; nor with the spare nodes removed throughout, which mends most but loses jumps the
// kept nodes mend (Accanthis, Linux Biolinum, URW P052).
void fair_again_while_faulty(ContourFairing& out, OutlineFaults& faults, const Contour& source, FairSettings settings,
                             Tries first, RunFairings& memo, MendedFaults& count) {
  // Where the first fairing's spare nodes went with their runs fitted again whole and it fails
  // or leaves faults, it is faired again with each spare node tried only in its window, and
  // that kept, and the fairings again below made so too, where it leaves fewer faults. The
  // runs' nodes slide, and rounding then meets some joins worse: Accanthis's O kept a jump,
  // and the fairing again with every spare node kept drew its counter in 16 cubics, not 6.
  if (settings.remove_spare_nodes && settings.fit_spare_runs && first.spare_nodes_in_runs > 0 &&
      (!out.faired || faults.mendable())) {
    FairSettings windows = settings;
    windows.fit_spare_runs = false;
    Tries window_tries;
    if (ContourFairing again = fair_contour_once(source, windows, window_tries, memo); again.faired)
      if (const OutlineFaults again_faults = count(again); !out.faired || fewer_faults(again_faults, faults))
        out = std::move(again), faults = again_faults, first = window_tries, settings = windows;
  }
  if (!settings.remove_spare_nodes || (out.faired && !faults.mendable())) {
    refair_while_faulty(out, faults, source, settings, first, memo, count);
    return;
  }
  ContourFairing pruned = out;
  OutlineFaults pruned_faults = faults;
  const Tries pruned_tries = first;
  settings.remove_spare_nodes = false;
  Tries kept_tries;
  ContourFairing again =
      first.spare_nodes_removed > 0 ? fair_contour_once(source, settings, kept_tries, memo) : ContourFairing{};
  if (again.faired) {
    const OutlineFaults again_faults = count(again);
    if (!out.faired || !fewer_faults(faults, again_faults)) out = std::move(again), faults = again_faults, first = kept_tries;
  }
  refair_while_faulty(out, faults, source, settings, first, memo, count);
  if (!pruned.faired) return;
  if (faults.at_smooth_joins() > 0) {
    settings.remove_spare_nodes = true;
    refair_while_faulty(pruned, pruned_faults, source, settings, pruned_tries, memo, count);
  }
  if (fewer_faults(pruned_faults, faults) ||
      (pruned_faults == faults && pruned.contour.segments.size() < out.contour.segments.size()))
    out = std::move(pruned), faults = pruned_faults;
}

// A contour whose first fairing leaves jumps or kinks, faired again with its spare nodes beside
// inflection nodes removed also where the inflection's tangent turns a little
// (SpareNodeLimits::turn_inflection_nodes), on as many tries as the first took; none where no
// tangent turns. The curves then meet the grid otherwise: EB Garamond's K kept a κ·UPM −2,000
// spike at its crotch's extremum (295, 364), none now, its curvature variation 1.84× → 0.96×
// its source's. Turning in every first fairing removed more nodes (a–z A–Z: EB Garamond
// 1.398× → 1.377×, Junicode 1.536× → 1.519×) but left jumps on the grid in DejaVu Sans's ✽,
// ❃, ≋ and others, whose mending took the whole font from 52 s to 60 s.
std::optional<ContourFairing> fair_turning_inflections(const OutlineFaults& faults, const Contour& source,
                                                       FairSettings settings, const Tries& first, RunFairings& memo) {
  if (faults.at_smooth_joins() == 0 || !settings.remove_spare_nodes) return std::nullopt;
  settings.turn_inflection_nodes = true;
  Tries tries{0, first.made, false};
  ContourFairing turned = fair_contour_once(source, settings, tries, memo);
  if (!turned.faired || tries.spare_nodes_turned == 0) return std::nullopt;
  return turned;
}

}  // namespace

ContourFairing fair_contour(const Contour& source, const FairSettings& requested) {
  FairSettings settings = requested;
  settings.rounding = resolve_rounding(requested.rounding, {&source, 1});
  Tries first;
  RunFairings memo;  // the runs every fairing below asks for, faired once
  ContourFairing out = fair_contour_once(source, settings, first, memo);
  if (settings.profile != FairProfile::text || settings.rounding != Rounding::integers) return out;
  MendedFaults count(source, settings);
  OutlineFaults faults = out.faired ? count(out) : OutlineFaults{};
  // The fairing with inflections turned first: where it leaves no fault once its joins are
  // mended, the fairings again have nothing to mend (EB Garamond's K: 31 fairings again, 57 s,
  // before the turned one that mended it); elsewhere it is kept last, where it has fewer faults
  // than they leave. Its mending is what it costs where it stays faulty (DejaVu Sans's ❃ and ✾,
  // 0.8 s each), but K has two jumps before it and none after.
  std::optional<ContourFairing> turned =
      out.faired ? fair_turning_inflections(faults, source, settings, first, memo) : std::nullopt;
  const OutlineFaults turned_faults = turned ? count(*turned) : OutlineFaults{};
  if (turned && !turned_faults.mendable() && turned_faults.corners_lost <= faults.corners_lost) {
    out = std::move(*turned), faults = turned_faults;
  } else {
    fair_again_while_faulty(out, faults, source, settings, first, memo, count);
    if (turned && fewer_faults(turned_faults, faults)) out = std::move(*turned), faults = turned_faults;
  }
  // Last, a contour whose runs faired only on another basis than their own outlines, faults
  // left, is faired with the kinks where its curves meet lines corners as drawn, and that kept
  // where the other has no fewer faults: the source's own kink is truer to the design than a
  // smoothing guide's curve (Comic Neue's u, its foot's curve cut beside the stem where
  // rounding strayed: on the guide, a jump for the kink and 1.8 times the source's curvature
  // variation).
  if (out.faired && out.basis != RunBasis::own && faults.mendable()) {
    settings.line_kinks_as_drawn = true;
    Tries cornered_tries;
    if (ContourFairing cornered = fair_contour_once(source, settings, cornered_tries, memo); cornered.faired)
      if (const OutlineFaults cornered_faults = count(cornered); !fewer_faults(faults, cornered_faults))
        out = std::move(cornered);
  }
  return out;
}

}  // namespace gf
