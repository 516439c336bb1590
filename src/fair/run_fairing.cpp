#include "fair/run_fairing.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include "fair/chain_fairing.hpp"
#include "fair/g3_reexpression.hpp"
#include "fair/junctions.hpp"
#include "fair/run_reference.hpp"
#include "geom/curvature.hpp"
#include "geom/smoothing_spline.hpp"

namespace gf {

namespace {

constexpr int max_rounds = 10;
constexpr int fallback_rounds = 4;  // a text run on its guide, after its own outline failed
constexpr int max_guide_refinements = 3;  // doublings of a smoothing guide's spans

// Handwriting traced from scans wobbles at every scale below the tolerance: the junctions and
// the chain are built on a guide, the smoothest cubic spline of the run within `tolerance` of
// it (geom/smoothing_spline; one span per half feature window, up to eight where that cannot
// come within it), while fidelity is measured against the source itself. A line's tangent is
// held at its end (and κ = 0 there, given `straight_line_ends`); a corner's is the guide's.
// The spline aims at `tolerance` (its share of the budget: the smoothing's bound), and serves
// once within `budget`, the chains' own: the chains on it are measured against the source, and
// a span with no chain is the guide itself. None when no spline comes within that. A
// professional outline is its own guide until no chain on it comes within the budget
// (fair_run).
std::optional<SmoothRun> guide_for(const SmoothRun& run, const RunReference& source, double tolerance, double budget,
                                   double window, SmoothingPenalty penalty, const LobeMerging& merging,
                                   bool straight_line_ends) {
  const double L = source.length();
  const auto samples = [&](int count) {
    std::vector<Vec2> points;
    for (int i = 0; i <= count; ++i) {
      if (run.closed && i == count) break;
      points.push_back(source.point_at(L * i / count));
    }
    return points;
  };
  std::vector<Vec2> points = samples(std::clamp(static_cast<int>(L / 1.5), 40, 1200));
  SmoothingEnds ends;
  if (run.starts_at_line()) ends.start_tangent = run.start.tangent;
  if (run.ends_at_line()) ends.end_tangent = run.end.tangent;
  ends.straight_ends = straight_line_ends;
  int spans = std::clamp(static_cast<int>(std::ceil(L / (0.5 * window))), run.closed ? 4 : 1, 80);
  const auto within = [&](const BSplineFit& f) { return !f.spans.empty() && f.max_residual <= budget; };
  BSplineFit fit = fit_smoothing_spline(points, tolerance, spans, run.closed, ends, penalty, merging);
  // A thin contour's tolerance is half its thickness, a tenth of a unit on a brush font's
  // hairline (Because We Create's t): finer spans there, at least two points each, the run
  // sampled again at four a span where it has fewer (EB Garamond's d, G and N, a bowl or a
  // whole outline of sharp serifs of 829 to 4,343 units: at a point every 1.5 or 3 units, the
  // spans stopped doubling while the spline was still farther than its budget).
  for (int k = 0; k < max_guide_refinements && !within(fit); ++k) {
    spans *= 2;
    if (2 * spans > static_cast<int>(points.size())) points = samples(4 * spans);
    fit = fit_smoothing_spline(points, tolerance, spans, run.closed, ends, penalty, merging);
  }
  if (!within(fit)) return std::nullopt;
  SmoothRun guide = run;
  guide.cubics = fit.spans;
  // A corner's tangent is the guide's, as far as the corner stays one (kept_corner_angle).
  const auto corner_tangent = [](const RunEnd& end, const Cubic& span, SegmentEnd at) {
    const double drawn = angle_of(end.tangent), guided = angle_of(*end_tangent(span, at));
    return direction_of(kept_corner_angle(end, at == SegmentEnd::start, drawn, guided).value_or(drawn));
  };
  if (!run.closed) {
    if (run.start.kind == RunEndKind::corner)
      guide.start.tangent = corner_tangent(run.start, fit.spans.front(), SegmentEnd::start);
    if (run.end.kind == RunEndKind::corner) guide.end.tangent = corner_tangent(run.end, fit.spans.back(), SegmentEnd::end);
  }
  return guide;
}

// Where no chain within the budget exists for a span of a guided run: the guide itself over
// the span, between the frames a chain would have had there (so its neighbours join it G2).
FairedChain guide_stretch(const ChainSpan& span, const std::shared_ptr<const RunReference>& guide,
                          const SmoothRun& guide_run, double w) {
  const RunReference& ref = *guide;
  FairedChain chain;
  chain.closed = span.closed;
  GuideStretch g;
  g.guide = guide;
  if (span.closed) {
    g.s0 = 0.0, g.s1 = ref.length();
  } else {
    g.s0 = span.s.front(), g.s1 = span.s.back();
    const auto frame = [&](double s, bool zero) {
      return LacPoint{ref.mean_point(s, w), end_tangent_of(s, ref, guide_run, w), zero ? 0.0 : ref.curvature_at(s), 0.0};
    };
    g.start = frame(g.s0, span.zero_start);
    g.end = frame(g.s1, span.zero_end);
    chain.zero_curvature_start = span.zero_start;
    chain.zero_curvature_end = span.zero_end;
  }
  chain.guide = std::move(g);
  return chain;
}

// |κ| under which G3 counts no sign: the check's |κ|·UPM of 1e-6.
double unsigned_curvature(const FairSettings& settings) { return 2e-6 * settings.flat_curvature(); }

// The run faired on `guide` (its smoothing guide) or, without one, on its source itself, in at
// most `rounds` rounds from `junctions` (on the guide's arc length where there is one);
// `keep_stalled` and `leave_lines` as fair_chain takes them.
FairedRun fair_run_from(const SmoothRun& run, const RunReference& source, const std::optional<SmoothRun>& guide,
                        const std::shared_ptr<const RunReference>& guide_ref, std::vector<Junction> junctions,
                        const FairSettings& settings, double budget, int rounds, bool keep_stalled, bool leave_lines) {
  FairedRun result;
  const SmoothRun& guide_run = guide ? *guide : run;
  const RunReference& ref = guide_ref ? *guide_ref : source;
  const double L = ref.length();
  bool too_far = false;
  // A span that asked for no change is the same span in every later round (the rounds only
  // cut and drop junctions of the spans that did): its outcome, a chain or none to be had, is
  // kept, not solved again.
  std::vector<std::pair<ChainSpan, ChainOutcome>> settled;
  PieceAlphas alphas(ref);
  for (int round = 0; round < rounds; ++round) {
    std::vector<double> cuts, drops;
    too_far = false;
    result.chains.clear();
    result.guide_stretches = 0;
    result.deviation = 0.0;
    for (const ChainSpan& span : chain_spans(junctions, ref, run)) {
      // After half the rounds, a chain whose solve stalls gives way, or is kept with its best
      // angles where `keep_stalled` (the cubic writeback then meets the mean curvature at its
      // junctions).
      const auto known = std::find_if(settled.begin(), settled.end(), [&](const auto& e) { return e.first == span; });
      ChainOutcome o = known != settled.end()
                           ? known->second
                           : fair_chain(span, ref, alphas, source, guide.has_value(), guide_run, settings, budget,
                                        round >= rounds / 2, keep_stalled, leave_lines);
      if (known == settled.end() && !o.adjusts()) settled.emplace_back(span, o);
      result.deviation = std::max(result.deviation, o.deviation);
      too_far = too_far || o.too_far;
      // A guided span with no chain when the rounds run out (or none to be had) is the guide.
      const bool last_round = round + 1 == rounds || !o.adjusts();
      if (!o.chain && guide && last_round) {
        o = ChainOutcome{};
        o.chain = guide_stretch(span, guide_ref, guide_run, settings.feature_window_units);
        ++result.guide_stretches;
      }
      if (o.chain) result.chains.push_back(std::move(*o.chain));
      else if (!o.adjusts()) {
        result.reason = "no feasible G2 chain";
        return result;
      }
      for (const double c : o.cuts) cuts.push_back(ref.closed() ? std::fmod(c, L) : c);
      for (const double d : o.drops) drops.push_back(ref.closed() ? std::fmod(d, L) : d);
    }
    for (const double d : drops)
      std::erase_if(junctions, [&](const Junction& j) { return std::abs(j.s - d) < 1e-9; });
    if (cuts.empty() && drops.empty()) {
      result.ok = true;
      if (settings.continuity == Continuity::g3)
        reexpress_as_g3(result, source, run, budget, unsigned_curvature(settings));
      return result;
    }
    for (const double c : cuts) junctions.push_back({c, JunctionKind::split});
    std::sort(junctions.begin(), junctions.end(), earlier);
  }
  result.reason = (too_far ? "still " + std::to_string(result.deviation) + " units from the source"
                           : std::string("no drawable G2 chain on the junctions")) +
                  " after " + std::to_string(rounds) + " rounds of refinement";
  return result;
}

// fair_run_from on the run's junctions. On the run's last try (`last_try`), where no chain
// comes of them and the run has an arc between κ = 0 ends cut at its curvature peak, again with
// that arc cut at quarters of its turning (junctions.hpp `arcs_by_turning`: Comic Neue's K,
// whose foot's curvature peaks 11 units from its line, left the transition there no room).
// Not before: where a guide takes over, it draws a designed arch better (TeX Gyre Pagella's
// n and h came out with two g2-jumps more each, their TV 5 % and 7 % higher).
FairedRun fair_run_on(const SmoothRun& run, const RunReference& source, const std::optional<SmoothRun>& guide,
                      const FairSettings& settings, double budget, int rounds, bool keep_stalled, bool leave_lines,
                      bool last_try) {
  const auto guide_ref = guide ? std::make_shared<const RunReference>(*guide) : nullptr;
  const RunReference& ref = guide_ref ? *guide_ref : source;
  JunctionOptions options = junction_options(settings);
  const auto junctions = [&] { return select_junctions(ref, run.starts_at_line(), run.ends_at_line(), options); };
  const std::vector<Junction> at_peaks = junctions();
  FairedRun r = fair_run_from(run, source, guide, guide_ref, at_peaks, settings, budget, rounds, keep_stalled, leave_lines);
  if (r.ok || !last_try) return r;
  options.arcs_by_turning = true;
  const std::vector<Junction> at_quarters = junctions();
  if (at_quarters == at_peaks) return r;
  FairedRun again = fair_run_from(run, source, guide, guide_ref, at_quarters, settings, budget, rounds, keep_stalled,
                                  leave_lines);
  return again.ok ? again : r;
}

// G3 at every smooth join: spirals throughout, no line join held to G2.
bool fully_g3(const FairedRun& r) { return r.g3() && r.g2_line_joins == 0; }

// The whole run as one stretch of its guide (no chain), re-expressed as G3 (fair_run).
FairedRun g3_on_guide(const SmoothRun& run, const RunReference& source, const SmoothRun& guide,
                      const FairSettings& settings, double budget) {
  const auto ref = std::make_shared<const RunReference>(guide);
  ChainSpan span;
  span.s = {0.0, ref->length()};
  span.closed = run.closed;
  span.zero_start = run.starts_at_line();
  span.zero_end = run.ends_at_line();
  FairedRun result;
  result.chains.push_back(guide_stretch(span, ref, guide, settings.feature_window_units));
  result.guide_stretches = 1;
  result.ok = true;
  reexpress_as_g3(result, source, run, budget, unsigned_curvature(settings));
  return result;
}

}  // namespace

FairedRun fair_run(const SmoothRun& run, const FairSettings& settings, double budget, RunBasis basis) {
  const RunReference source(run);
  // Leaving the lines earlier can keep a run from any chain that holding them found (DejaVu
  // Sans's ☚ was kept unfaired): on the last try a run gets (a text run's own outline with its
  // jumps, or handwriting's guide), such a run is faired again with its ends held. Earlier
  // tries give way to the next as they did.
  const bool last_try = settings.profile == FairProfile::handwriting || basis == RunBasis::own_with_jumps;
  const auto fair_on = [&](const std::optional<SmoothRun>& guide, int rounds, bool keep_stalled) {
    FairedRun r = fair_run_on(run, source, guide, settings, budget, rounds, keep_stalled, true, last_try);
    return r.ok || !last_try ? r : fair_run_on(run, source, guide, settings, budget, rounds, keep_stalled, false, true);
  };
  const auto guide = [&](SmoothingPenalty penalty, bool straight_line_ends) {
    return guide_for(run, source, budget * settings.guide_share, budget, settings.feature_window_units, penalty,
                     settings.guide_lobes, straight_line_ends);
  };
  // A guided run has a C2 guide to give way to, smoother than a chain left with its curvature
  // jumps; handwriting without one (none within the budget) keeps its stalled chains.
  if (settings.profile == FairProfile::handwriting) {
    const std::optional<SmoothRun> smoothed = guide(SmoothingPenalty::sparse, false);
    FairedRun faired = fair_on(smoothed, max_rounds, !smoothed);
    // Where G3 falls short of a guided run with chains, two more tries, each kept only where it
    // comes G3 in full:
    // - A run that meets a line is faired again on a guide held straight at its lines. A guide
    //   that still bends where it meets a line (κ·UPM 22 at dkg Bold's Q tail) leaves the G2
    //   curve a jump of κ there, which no spiral leaving the line with κ = κ′ = 0 follows
    //   without turning back. Only here: on every run, the handwriting fonts' G2 bars came out
    //   worse (Breip's g2-jumps 0.98 → 2.09 %, Comic Neue's TV 0.705× → 0.819×).
    // - Then the run is re-expressed from its guide alone (held straight where it meets a
    //   line). A guide stretch between chains takes their frames at its ends, the guide's mean
    //   point and tangent over the feature window, off its own (dkg's T: 0.0055 rad, with the
    //   guide's κ changing sign a unit before the join); one stretch has its own throughout.
    if (settings.continuity != Continuity::g3 || !smoothed || !faired.ok || faired.chains.empty() || fully_g3(faired))
      return faired;
    const bool meets_line = run.starts_at_line() || run.ends_at_line();
    const std::optional<SmoothRun> retry_guide = meets_line ? guide(SmoothingPenalty::sparse, true) : smoothed;
    if (!retry_guide) return faired;
    if (meets_line) {
      FairedRun again = fair_on(retry_guide, max_rounds, false);
      if (again.ok && fully_g3(again)) return again;
    }
    FairedRun on_guide = g3_on_guide(run, source, *retry_guide, settings, budget);
    return fully_g3(on_guide) ? on_guide : faired;
  }
  if (basis != RunBasis::guide)
    return fair_on(std::nullopt, max_rounds, basis == RunBasis::own_with_jumps);
  // A professional outline is its own guide, until no chain on it comes G2 within the budget
  // (Inter's U: κ falls from its shoulders to a flat bottom and rises again, and the solve
  // stalls): then the run is faired on its smoothing guide, as handwriting is, with the squared
  // penalty (a designed outline has no scan noise for the sparse one to gather, and it costs
  // three times the solves) and fewer rounds before a span is the guide itself (ten rounds
  // took a tenth more of whole DejaVu Sans's time).
  const std::optional<SmoothRun> smoothed = guide(SmoothingPenalty::squared, false);
  if (!smoothed) {
    FairedRun none;
    none.reason = "no smoothing guide within the budget";
    return none;
  }
  return fair_on(smoothed, fallback_rounds, false);
}

}  // namespace gf
