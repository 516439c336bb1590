#include "fair/outline_on_grid.hpp"

#include <algorithm>
#include <functional>
#include <optional>

#include "fair/curve_line_joins.hpp"
#include "fair/grid_rounding.hpp"
#include "fair/join_mending.hpp"
#include "fair/jump_splits.hpp"
#include "fair/line_kinks.hpp"
#include "fair/line_splits.hpp"
#include "fair/outline_faults.hpp"
#include "fair/rounding_retry.hpp"
#include "geom/tolerance_band.hpp"

namespace gf {

namespace {

// Rounds of polishing the joins rounding leaves jumping (HandleStepLimits::polish_rounds): a
// handwriting font's a-z A-Z changed no further after three.
constexpr int handwriting_polish_rounds = 3;
// Under --continuity g3, where the polish also takes the nodes whose dκ/ds jumps: DejaVu Sans
// a–z A–Z, median jump 0.62 with none, 0.112 with one round, 0.076 with two or three.
constexpr int text_g3_polish_rounds = 2;
// Text under G2 (since stop 60, with the nodes beside the jumps): whole DejaVu Sans, g2-jumps
// 664, 612 and 605 with one, two and three rounds (24.7, 26.0 and 26.3 s); a–z A–Z, EB Garamond
// 194, 165 and 159, FreeSerif 14, 12 and 13, Lato 18, 17 and 17.
constexpr int text_polish_rounds = 2;
// Units: a flat node's far handle farther off its tangent line than the nudges reach (two
// units) and half a unit of rounding (HandleStepLimits::flat_node_reach).
constexpr double text_flat_node_reach = 2.5;
// Under --continuity g3, what a dκ/ds jump costs in rounding (HandleStepLimits::slope_jump_weight),
// and on text what a curvature jump the check counts costs on top (counted_jump_cost), ten
// times that. Text a–z A–Z with the band around the source (HandleStepLimits::band), the median
// dκ/ds jump at weights 3, 4, 5, 6, 8: DejaVu Sans Bold 0.058, 0.066, 0.062, 0.048, 0.040 (the
// bar 0.05); Lato 0.038, 0.037, 0.037, 0.035, 0.035; Cantarell 0.039, 0.038, 0.036, 0.034, 0.034,
// its curvature variation 0.922, 0.937, 0.952, 0.955, 0.935× of the source's (the bar 0.95×).
constexpr double text_slope_jump_weight = 8.0, handwriting_slope_jump_weight = 5.0;
constexpr double text_counted_jump_cost = 10.0 * text_slope_jump_weight;
constexpr int rounding_retries = 3;  // halvings where rounding strayed, then as many of every cubic's
// Units: how far rounding may have moved a node from its float place (fair/jump_splits.hpp).
constexpr double split_reach = 3.0;
// Of the tolerance, how far a line split for short steps may move the outline (fair/line_splits):
// at a quarter, FreeSerif Italic's V found no split of its 719-unit stroke, at half one with
// steps (2, 3) and (37, 61).
constexpr double line_split_move_share = 0.5;

// Where rounding strayed, a curve meeting a line whose handle it gave more than this many times
// its float length (and a unit) took whole steps of the line too long for it.
constexpr double stretched_handle = 2.0;

// The longest handle at the node of `c` nearest `p`, within `reach` of it; 0 where there is none.
double longest_handle_near(const Contour& c, Vec2 p, double reach) {
  const std::size_t n = c.segments.size();
  double longest = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 node = c.node_point(i);
    if (distance(node, p) > reach) continue;
    if (const Cubic* out = std::get_if<Cubic>(&c.segments[i])) longest = std::max(longest, distance(out->p[1], node));
    if (!c.closed && i == 0) continue;
    if (const Cubic* in = std::get_if<Cubic>(&c.segments[(i + n - 1) % n]))
      longest = std::max(longest, distance(in->p[2], node));
  }
  return longest;
}

// Whether `c` has a node within `reach` of `p`.
bool rounded_node_within(const Contour& c, Vec2 p, double reach) {
  for (std::size_t i = 0; i < c.segments.size(); ++i)
    if (distance(c.node_point(i), p) <= reach) return true;
  return false;
}

// What a line split is judged by: an outline's faults as the last passes leave it, the line
// kinks taken (fair/line_kinks) and the joins mended (fair/join_mending). The kinks at the
// splits are the fillets', and the kinks between lines rounding left may be too (Liberation
// Sans Narrow's A: a split kept for two kinks fewer than the rounded outline had, both of which
// the fillets took, left one); and a split that leaves more jumps may leave fewer once the
// joins are mended (URW P052's W: 5 against 3, then 1 against 2). The counter is built, and
// the rounded outline counted, once, where first needed.
class SplitJudge {
 public:
  SplitJudge(const Contour& source, const OutlineOnGrid& rounded, const SampledContour& sampled_source,
             const FairSettings& settings)
      : source_(source),
        rounded_(rounded),
        sampled_source_(sampled_source),
        tolerance_units_(settings.tolerance_units),
        units_per_em_(settings.units_per_em) {}

  /// The faults of the rounded outline as rounding left it.
  OutlineFaults rounded_as_left() { return counter().count(rounded_.contour); }

  /// The faults of `o` as the last passes leave it.
  OutlineFaults finished(const OutlineOnGrid& o) {
    Contour c = without_line_kinks(o.contour, o.deviation, source_, tolerance_units_, true).contour;
    // Not with a curve between lines redrawn (`curves_between_lines`): judged so, TeX Gyre
    // Pagella's x kept a line split it does without otherwise, its curvature variation 422 →
    // 668 (the source's 817); the contour kept is mended so anyway (fair_contour).
    const JoinMendingLimits mending{
        .tolerance_units = tolerance_units_, .units_per_em = units_per_em_, .curves_between_lines = false};
    return mend_where_fewer_faults(c, counter().count(c), counter(), sampled_source_, mending).faults;
  }

  /// The same of the rounded outline.
  const OutlineFaults& rounded_finished() {
    if (!rounded_finished_) rounded_finished_ = finished(rounded_);
    return *rounded_finished_;
  }

 private:
  const FaultCounter& counter() {
    if (!counter_) counter_.emplace(source_, units_per_em_);
    return *counter_;
  }

  const Contour& source_;
  const OutlineOnGrid& rounded_;
  const SampledContour& sampled_source_;
  double tolerance_units_, units_per_em_;
  std::optional<FaultCounter> counter_;
  std::optional<OutlineFaults> rounded_finished_;
};

// How a split at the joins `at` must leave the rounded outline to be kept.
enum class SplitKept { within_tolerance, with_fewer_faults, with_fewer_faults_and_inflections };

// `nodes` with the lines at the curve joins `at` split (split_line_at), each split kept where
// the float outline stays within `available`, and settled again: kept as `kept` says, its
// faults and the rounded outline's as `judge` counts them. Where rounding strayed, or slid the
// join, a join whose line has no such split has its curve split beside the line instead
// (split_curve_beside_line: Gentium Plus's M; slid, Pagella's G and Quicksand's W lost their
// jumps, Gentium Plus Italic's H and I their kinks, and Caladea Bold's Y gained a jump). Not
// at kinks: there the curve splits changed no glyph of 44 text fonts' a–z A–Z.
std::optional<SplitOnGrid> split_and_settle(std::vector<std::size_t> at, bool closed,
                                            const std::vector<OutlineNode>& nodes, SplitJudge& judge,
                                            const SampledContour& sampled_source, const FairSettings& settings,
                                            double available, bool halving_allowances, SplitKept kept) {
  if (at.empty()) return std::nullopt;
  // Last first: a split puts its vertex in beside its node (or at the end), and the nodes
  // before stay where they are.
  std::sort(at.begin(), at.end(), std::greater<>());
  at.erase(std::unique(at.begin(), at.end()), at.end());
  LineSplitLimits limits;
  limits.max_move_units = line_split_move_share * settings.tolerance_units;
  SplitOnGrid out{nodes, {}};
  bool split = false;
  for (const std::size_t k : at) {
    std::vector<OutlineNode> trial = out.nodes;
    if (split_line_at(trial, closed, k, limits)) {
      if (!within_distance(SampledContour(to_contour(trial, closed)), sampled_source, available)) continue;
    } else if (kept == SplitKept::with_fewer_faults || !split_curve_beside_line(trial, closed, k)) {
      continue;
    }  // else the curve split, exactly: the float outline is where it was
    out.nodes = std::move(trial);
    split = true;
  }
  if (!split) return std::nullopt;
  out.outline = settle_on_grid(out.nodes, closed, sampled_source, settings, halving_allowances);
  if (out.outline.deviation > settings.tolerance_units) return std::nullopt;
  if (kept == SplitKept::within_tolerance) return out;
  const OutlineFaults now = judge.finished(out.outline), was = judge.rounded_finished();
  if (!fewer_faults(now, was)) return std::nullopt;
  if (kept == SplitKept::with_fewer_faults_and_inflections && now.inflections > was.inflections) return std::nullopt;
  return out;
}

}  // namespace

OutlineOnGrid settle_on_grid(const std::vector<OutlineNode>& nodes, bool closed, const SampledContour& sampled_source,
                             const FairSettings& settings, bool halving_allowances) {
  Contour faired = to_contour(nodes, closed);
  const SampledContour sampled(faired);
  // Each segment's own share: what rounding may still spend there (geom/polyline_distance.hpp).
  const std::vector<NearestPiece> answers =
      nearest_pieces(sampled.grid, sampled.samples.segment_of, sampled_source.points());
  const std::vector<double> by_segment =
      distance_by_piece(sampled.grid, sampled.samples.segment_of, sampled_source.grid, answers);
  double d = by_segment.empty() ? distance_between(sampled, sampled_source)
                                : *std::max_element(by_segment.begin(), by_segment.end());
  if (settings.rounding == Rounding::integers && d <= settings.tolerance_units) {
    // What the float outline leaves of the tolerance, segment by segment, is what rounding
    // may spend on G2 there (5 % kept for sampling).
    const bool hand = settings.profile == FairProfile::handwriting;
    const bool g3 = settings.continuity == Continuity::g3;
    HandleStepLimits limits;
    limits.flat_curvature = settings.flat_curvature();
    limits.allowance = 0.95 * (settings.tolerance_units - d);
    limits.polish_rounds = hand ? handwriting_polish_rounds : g3 ? text_g3_polish_rounds : text_polish_rounds;
    limits.polish_only_at_jumps = g3 && !hand;
    limits.inflection_handles = limits.node_turns = hand;
    limits.flat_node_reach = hand ? 0.0 : text_flat_node_reach;
    limits.slope_jump_weight = !g3 ? 0.0 : hand ? handwriting_slope_jump_weight : text_slope_jump_weight;
    limits.counted_jump_cost = g3 && !hand ? text_counted_jump_cost : 0.0;
    limits.seats_beside_lines = g3;
    limits.allowance_by_cubic = tolerance_left(by_segment, settings.tolerance_units, 0.0);
    // Rounding can stray past its allowance where it slides a line's end (line_rounding) and
    // the handles after it take other whole steps (DejaVu Sans's chi: 4.4 units from the
    // source at a tolerance of 2.56, and the contour was kept unfaired), or moves a corner
    // to a grid neighbour past the tolerance (FreeSerif's V, at 1.25): rounded again with
    // the lines' ends kept within their allowance, then both ways on half the allowance of
    // the cubics about where it strayed (halve_allowances), up to three times, then of every
    // cubic, up to three times more. First, cubics may move past their allowance where they
    // stay within the band around the source (measured exactly: what the sampling leaves is
    // the 5 % kept), twice (the lines' ends free, then kept within their allowance); where
    // that strays, as without the band (retried with the band as often, EB Garamond a–z A–Z
    // had g2-jumps 220 → 204, but its $ a 4-unit cubic folded into a zigzag). Not on
    // handwriting under G3: there the band let rounding trade curvature extrema inside
    // cubics for dκ/ds matched at nodes (Because We Learn a–z A–Z, extrema 0.4985× of the
    // source's without it, 0.5025× with it, over the fairing bar of 0.5×; dkg's g2-jumps
    // 0.76 % of the joins without it, 0.61 % with it, within 2 %).
    std::optional<ToleranceBand> band;
    if (!(hand && g3)) band.emplace(sampled_source.points(), answers, 0.95 * settings.tolerance_units);
    std::vector<const ToleranceBand*> bands{nullptr};
    if (band) bands.insert(bands.begin(), &*band);
    const HandleStepLimits first = limits;
    for (const ToleranceBand* within : bands) {
      limits = first;
      limits.band = within;
      const int last_retry = within || !halving_allowances ? 1 : 4 * rounding_retries + 1;
      std::vector<std::size_t> strayed;  // the cubics about where the last rounding strayed
      for (int retry = 0;; ++retry) {
        limits.any_grid_neighbour = retry % 2 == 0;
        if (retry > 0 && limits.any_grid_neighbour)
          halve_allowances(limits, retry > 2 * rounding_retries ? std::vector<std::size_t>{} : strayed);
        faired = to_contour(round_to_grid(nodes, closed, limits), closed);
        const SampledContour sampled_faired(faired);
        d = distance_between(sampled_faired, sampled_source);
        if (d <= settings.tolerance_units || retry == last_retry) break;
        const std::vector<double> by_segment =
            distance_by_piece(sampled_faired.grid, sampled_faired.samples.segment_of, sampled_source.grid);
        strayed = cubics_about_strays(by_segment, settings.tolerance_units, limits.allowance_by_cubic.size());
      }
      if (d <= settings.tolerance_units) break;
    }
  }
  return {std::move(faired), d};
}

// The splits, a–z A–Z rounded, 44 text fonts: g2-jumps 69 → 34, in 6 % less time (fewer
// contours left for the refairings). Once, both cubics: a second split where jumps were left,
// 32 for 12 % more time; then the cubic before and the one after alone where both did not
// mend it, 32 for 14 % more; each of the three kept where it has fewer faults or as many with
// fewer nodes, 32 for 45 % more.
std::optional<OutlineOnGrid> rounded_with_splits(const Contour& source, const std::vector<OutlineNode>& nodes,
                                                 const Contour& rounded, const SampledContour& sampled_source,
                                                 const FairSettings& settings, bool halving_allowances) {
  if (!settings.split_beside_jumps || settings.rounding != Rounding::integers ||
      settings.profile != FairProfile::text || settings.continuity != Continuity::g2)
    return std::nullopt;
  const std::vector<Vec2> jumps = joins_at_fault(rounded, JoinFault::jump, settings.units_per_em);
  if (jumps.empty()) return std::nullopt;
  const std::vector<OutlineNode> split =
      split_cubics_beside(nodes, source.closed, jumps, 2.0 * settings.shortest_rounded_span_units, split_reach);
  if (split.size() == nodes.size()) return std::nullopt;
  OutlineOnGrid again = settle_on_grid(split, source.closed, sampled_source, settings, halving_allowances);
  if (again.deviation > settings.tolerance_units) return std::nullopt;
  const FaultCounter faults(source, settings.units_per_em);
  if (!fewer_faults(faults.count(again.contour), faults.count(rounded))) return std::nullopt;
  return again;
}

std::optional<SplitOnGrid> rounded_with_line_splits(const Contour& source, const std::vector<OutlineNode>& nodes,
                                                    const OutlineOnGrid& rounded, const SampledContour& sampled_source,
                                                    const FairSettings& settings, double available,
                                                    bool halving_allowances) {
  if (settings.rounding != Rounding::integers) return std::nullopt;
  SplitJudge judge(source, rounded, sampled_source, settings);
  const auto split = [&](std::vector<std::size_t> at, SplitKept kept) {
    return split_and_settle(std::move(at), source.closed, nodes, judge, sampled_source, settings, available,
                            halving_allowances, kept);
  };
  // Where rounding strayed, the joins of a curve to a line where it stretched the curve's
  // handle (to whole steps of the line: FreeSerif Italic's V, 719 units against 9, and the
  // rounding came out 256 units off).
  if (rounded.deviation > settings.tolerance_units) {
    std::vector<std::size_t> at;
    for (std::size_t k = 0; k < nodes.size(); ++k)
      if (const std::optional<CurveLineJoin> join = curve_line_join(nodes, source.closed, k)) {
        const double handle = distance(join->curve.p[2], join->curve.p[3]);
        if (longest_handle_near(rounded.contour, nodes[k].point, split_reach) > stretched_handle * handle + 1.0)
          at.push_back(k);
      }
    return split(std::move(at), SplitKept::within_tolerance);
  }
  // Else those at kinks.
  std::vector<std::size_t> at;
  for (const Vec2 kink : joins_at_fault(rounded.contour, JoinFault::kink, settings.units_per_em))
    if (const std::optional<std::size_t> k = node_within(nodes, kink, split_reach)) at.push_back(*k);
  if (std::optional<SplitOnGrid> out = split(std::move(at), SplitKept::with_fewer_faults)) return out;
  // On text, where those gave nothing and the outline has faults, the joins rounding slid far
  // along their lines (no rounded node within split_reach), for a shorter step, stretching the
  // handle to it (Gentium Book's A: a 28-unit handle into its stroke's (182, 553), the join
  // moved 66 units up onto (19, 58) and the handle given two of those, 122 units; the serif's
  // curve folded into an inflection); kept only with no more inflections (Pagella's w: one
  // jump and one kink fewer for two inflections, and the kink came back once settled again).
  if (settings.profile != FairProfile::text) return std::nullopt;
  std::vector<std::size_t> slid;
  for (std::size_t k = 0; k < nodes.size(); ++k)
    if (curve_line_join(nodes, source.closed, k) && !rounded_node_within(rounded.contour, nodes[k].point, split_reach))
      slid.push_back(k);
  if (slid.empty() || !judge.rounded_as_left().mendable()) return std::nullopt;
  return split(std::move(slid), SplitKept::with_fewer_faults_and_inflections);
}

}  // namespace gf
