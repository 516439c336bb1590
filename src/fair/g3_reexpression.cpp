#include "fair/g3_reexpression.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "fair/curve_samples.hpp"
#include "fair/g3_local.hpp"
#include "fair/g3_run.hpp"
#include "fair/path_piece.hpp"
#include "geom/polyline_distance.hpp"

namespace gf {

namespace {

constexpr int max_g3_rounds = 6;  // of cutting the segments whose G3 spirals stray or stall
// Of those rounds, how many cut every piece of a guided run whose spirals change κ's sign more
// often than its G2 curve before the rounds after also hold the nodes the solve carried across
// zero (a–z A–Z under G3: EB Garamond's segments off G3 529 → 102, its cubics' TV 0.958× →
// 0.886× of the source's; cutting alone through all six rounds took dkg from 11 s to 275 s).
constexpr int sign_cuts_before_holding = 2;
// Rounds such a run is given in all: every round doubles its pieces, and holding and cutting
// on through all six took Ruf from 170 s to 684 s, Leckerli from 84 s to 499 s.
constexpr int max_sign_rounds = 4;
// Solves again with the nodes G3 carried across κ = 0 held, at most (the nearly flat nodes of
// dkg's I walked across one after another for three; its f, refused at eight, came out G3 at
// 24). The solves are sparse (geom/damped_newton.hpp), so more holds cost little.
constexpr int max_zero_holds = 24;
// How much farther than the solve without holds one with them may turn a tangent from the G2
// curve's (radians): freed, a held corner's tangent could wind a short hook into a loop
// (Femke Klaver's I, 0.44 against 0; a one-segment run of dkg's, a whole turn).
constexpr double max_held_turn = 0.2;
// How far past its budget a run's G3 curve may stray when no round brings it within: the share
// comes out of the writeback's, and the contour is still held to the tolerance after it
// (Cantarell's S strayed 0.308 units of 0.30 through six rounds, FreeSerif's s 0.354, and
// more rounds moved neither).
constexpr double g3_overrun = 1.2;
// Halvings of the pieces whose spirals fail, G3 piece by piece (try_local_g3).
constexpr int max_local_rounds = 5;

// How far each G3 spiral is from the source run (geom/polyline_distance's distance_by_piece),
// each side carried along a line the run meets as far as the other side reaches there (a line
// end slides along its line, and the line with it).
std::vector<double> distance_by_spiral(const G3Result& g3, const G3Problem& problem, const RunReference& source,
                                       double budget) {
  std::vector<Vec2> faired;
  std::vector<std::size_t> spiral_of;
  const std::vector<std::vector<Vec2>> pieces = sample_each<PolynomialSpiral>(g3.spirals, budget);
  for (std::size_t i = 0; i < pieces.size(); ++i)
    for (std::size_t k = faired.empty() ? 0 : 1; k < pieces[i].size(); ++k) faired.push_back(pieces[i][k]), spiral_of.push_back(i);
  std::vector<Vec2> original = source.polyline(0.0, source.length());
  if (!problem.closed)
    for (const bool at_start : {true, false}) {
      const std::size_t j = at_start ? 0 : problem.nodes.size() - 1;
      const G3Node& held = problem.nodes[j];
      if (held.kind != G3NodeKind::line && held.kind != G3NodeKind::line_g2) continue;
      const Vec2 slid = g3.ends[j].point;
      const Vec2 outwards = direction_of(held.tangent_angle) * (at_start ? -1.0 : 1.0);
      const Vec2 source_end = source.point_at(at_start ? 0.0 : source.length());
      if (dot(slid - source_end, outwards) > 0.0) {
        original.insert(at_start ? original.begin() : original.end(), slid);
      } else {
        faired.insert(at_start ? faired.begin() : faired.end(), source_end);
        spiral_of.insert(at_start ? spiral_of.begin() : spiral_of.end(), at_start ? 0 : pieces.size() - 1);
      }
    }
  return distance_by_piece(PolylineGrid(std::move(faired), 8.0), spiral_of, PolylineGrid(std::move(original), 8.0));
}

// How often κ changes sign along `pieces` (a run's, in order), from 16 samples a piece; |κ|
// under `zero` counts as no sign.
int sign_changes_along(const std::vector<PathPiece>& pieces, double zero) {
  int count = 0;
  double last = 0.0;
  for (const PathPiece& piece : pieces)
    for (const LacPoint& q : piece.sample(16)) {
      if (std::abs(q.curvature) < zero) continue;
      const double sign = q.curvature > 0.0 ? 1.0 : -1.0;
      count += last != 0.0 && sign != last;
      last = sign;
    }
  return count;
}

std::vector<PathPiece> pieces_of(const std::vector<FairedChain>& chains) {
  std::vector<PathPiece> pieces;
  for (const FairedChain& c : chains)
    for (PathPiece& p : chain_pieces(c)) pieces.push_back(std::move(p));
  return pieces;
}

int sign_changes_along(const std::vector<FairedChain>& chains, double zero) {
  return sign_changes_along(pieces_of(chains), zero);
}

// How much κ varies along `pieces` (a run's, in order): Σ|Δκ| over 64 samples a piece.
double curvature_variation_along(const std::vector<PathPiece>& pieces) {
  double variation = 0.0;
  std::optional<double> last;
  for (const PathPiece& piece : pieces)
    for (const LacPoint& q : piece.sample(64)) {
      if (last) variation += std::abs(q.curvature - *last);
      last = q.curvature;
    }
  return variation;
}

// The nodes (smooth, or corner ends) the G3 solve carried across zero, away from the G2 curve's
// sign, held at the G2 curve's κ instead (their tangents, and a smooth node's place along its
// normal, left free): between nodes κ is monotone, so once no node crosses, κ changes sign only
// where the G2 curve's does. `farthest`: only the one carried farthest. How many crossed.
std::size_t hold_crossed_nodes(G3Problem& problem, std::span<const CurvatureEnd> solved, double zero, bool farthest) {
  std::vector<std::size_t> crossed;
  for (std::size_t j = 0; j < problem.nodes.size(); ++j) {
    const G3Node& n = problem.nodes[j];
    if (n.kind != G3NodeKind::smooth && n.kind != G3NodeKind::corner) continue;
    if (n.curvature * solved[j].curvature >= 0.0 || std::abs(solved[j].curvature) < zero) continue;
    crossed.push_back(j);
  }
  const std::size_t count = crossed.size();
  if (farthest && count > 1)
    crossed = {*std::max_element(crossed.begin(), crossed.end(), [&](std::size_t i, std::size_t j) {
      return std::abs(solved[i].curvature) < std::abs(solved[j].curvature);
    })};
  for (const std::size_t j : crossed) {
    G3Node& n = problem.nodes[j];
    n.kind = n.kind == G3NodeKind::smooth ? G3NodeKind::held : G3NodeKind::corner_held;
  }
  return count;
}

// How far the solve turned the run's tangents from the G2 curve's, at the node turned most.
double largest_turn(const G3Problem& problem, const G3Result& g3) {
  double out = 0.0;
  for (std::size_t j = 0; j < g3.ends.size(); ++j)
    out = std::max(out, std::abs(g3.ends[j].tangent_angle - problem.nodes[j].tangent_angle));
  return out;
}

// While `g3` changes κ's sign more often than the G2 curve (`g2_sign_changes`), up to
// `max_zero_holds` times: the nodes it carried across zero held (all of them, or, should that
// stall or turn a tangent `max_held_turn` farther than the solve without holds did, the one
// carried farthest) and the run solved again. The sign changes left.
int solve_holding_crossed_nodes(G3Problem& problem, G3Result& g3, int sign_changes, int g2_sign_changes, double zero) {
  const double turned = largest_turn(problem, g3);
  const auto sound = [&](const G3Problem& p, const G3Result& r) {
    return r.ok() && largest_turn(p, r) <= turned + max_held_turn;
  };
  for (int hold = 0; hold < max_zero_holds && sign_changes > g2_sign_changes; ++hold) {
    bool taken = false;
    for (const bool farthest : {false, true}) {
      G3Problem holding = problem;
      const std::size_t crossed = hold_crossed_nodes(holding, g3.ends, zero, farthest);
      if (crossed == 0) return sign_changes;
      G3Result again = make_g3(holding);
      if (sound(holding, again)) {
        problem = std::move(holding), g3 = std::move(again), taken = true;
        break;
      }
      if (crossed == 1) break;  // the farthest alone is the same problem
    }
    if (!taken) break;
    sign_changes = sign_changes_along(curve_pieces(g3.spirals), zero);
  }
  return sign_changes;
}

// A G3 run not met in full: held at its line joins, or strayed a little.
struct PartialG3 {
  G3Problem problem;
  std::vector<PolynomialSpiral> spirals;
  double deviation;
  int g2_line_joins;
};

// What one attempt gives: the run made G3 in full (its spirals adopted), or what is next best
// (not adopted) and why not.
struct G3Attempt {
  bool met = false;
  std::optional<PartialG3> partial;
  std::string why;
  bool stalled = false;  ///< whether a round's solve stalled (so cuts after it could differ)
};

void adopt(FairedRun& result, const PartialG3& g3) {
  adopt_spirals(result.chains, g3.problem, g3.spirals);
  result.deviation = g3.deviation;
  result.g2_line_joins = g3.g2_line_joins;
}

// G3 over the whole run (fair/g3_run.hpp), kept only when it stays within the budget of the
// source and, where part of it follows the smoothing guide, changes the sign of κ no more often
// than the G2 run. Re-expressed, a guide's nearly straight pieces could swing across zero
// (Because We Learn's i stem): such a run is cut everywhere and tried again, and after
// `sign_cuts_before_holding` rounds each round also holds the nodes the solve carried across
// zero at the G2 curve's κ, cutting on where that fails, `max_sign_rounds` rounds in all. A
// chain's run holds them from the first round (dkg's f: a spiral turned back past its
// y-minimum) and is not refused when that fails. A log-aesthetic segment whose spirals stray
// is cut in two, up to `max_g3_rounds` times. Where only holding its line joins to G2 solves
// the run, the segments at those joins are cut in two for the next round, which tries G3 there
// again with the room a shorter spiral gives κ to rise from 0 with zero slope. Where no round
// makes it G3 in full, the attempt answers with the first run held so, else the G3 run that
// strayed least within `g3_overrun` of the budget, and why.
// `rule`: κ′ at the junctions; `after_stall`: where pieces are cut once a solve has stalled
// (before, at equal lengths); `most_variation`: where given, a G3 curve whose κ varies more
// (curvature_variation_along) is no answer.
G3Attempt try_g3(FairedRun& result, const RunReference& source, const SmoothRun& run, double budget,
                 double zero_curvature, SlopeRule rule, CutPlacement after_stall,
                 std::optional<double> most_variation) {
  std::vector<int> pieces;
  std::string why;
  // Only a guide stretch is refused for it: a log-aesthetic chain's spirals keep their pieces'
  // monotone curvature, and swing about zero only where held nodes do not mend it.
  const bool guided =
      std::any_of(result.chains.begin(), result.chains.end(), [](const FairedChain& c) { return c.guide.has_value(); });
  const int g2_inflections = sign_changes_along(result.chains, zero_curvature);
  std::optional<PartialG3> held;  // the first run solved with its line joins held to G2
  std::optional<PartialG3> strayed;  // the G3 run that strayed least, within g3_overrun of the budget
  CutPlacement placement = CutPlacement::by_length;
  bool stalled = false;
  for (int round = 0; round < max_g3_rounds; ++round) {
    std::optional<G3Problem> problem = g3_problem(result.chains, run, pieces, placement);
    if (!problem) return {true, std::nullopt, ""};  // no chain: nothing to re-express
    problem->slope_rule = rule;
    pieces.resize(problem->run_piece.back() + 1, 1);
    G3Result g3 = make_g3(*problem);
    int g2_line_joins = 0;
    // No room on a line for G3 there, perhaps: G2 at the line joins, G3 elsewhere. Every round
    // tries G3 at the lines first again: after a cut the run may find the room.
    if (!g3.ok())
      for (G3Node& n : problem->nodes)
        if (n.kind == G3NodeKind::line) n.kind = G3NodeKind::line_g2, ++g2_line_joins;
    if (!g3.ok() && g2_line_joins > 0) g3 = make_g3(*problem);
    // The run's pieces (segments or guide pieces) to cut in two before the next round.
    std::vector<bool> split(pieces.size(), false);
    if (g3.ok()) {
      int inflections = sign_changes_along(curve_pieces(g3.spirals), zero_curvature);
      // A guided run tries shorter spirals first, then holds the nodes the solve carried across
      // zero too; a chain's run holds them from the first round.
      if (!guided || round >= sign_cuts_before_holding)
        inflections = solve_holding_crossed_nodes(*problem, g3, inflections, g2_inflections, zero_curvature);
      if (guided && inflections > g2_inflections) {
        why = "the G3 curve changes the sign of its curvature " + std::to_string(inflections) + " times, the G2 one " +
              std::to_string(g2_inflections);
        // Shorter spirals follow the guide's pieces closer, and give held nodes more room.
        if (round + 1 >= max_sign_rounds) break;
        for (int& n : pieces) n *= 2;
        continue;
      }
      const std::vector<double> d = distance_by_spiral(g3, *problem, source, budget);
      const double worst = *std::max_element(d.begin(), d.end());
      if (worst <= budget && g2_line_joins == 0) {
        const double variation = curvature_variation_along(curve_pieces(g3.spirals));
        if (most_variation && variation > *most_variation)
          return {false, std::nullopt, "the G3 curve's curvature varies " + std::to_string(variation) + ", past " +
                                           std::to_string(*most_variation)};
        adopt(result, PartialG3{*problem, std::move(g3.spirals), worst, 0});
        return {true, std::nullopt, ""};
      }
      if (worst <= budget) {
        if (!held) held = PartialG3{*problem, std::move(g3.spirals), worst, g2_line_joins};
        const std::size_t last = problem->nodes.size() - 1;
        if (problem->nodes.front().kind == G3NodeKind::line_g2) split[problem->run_piece.front()] = true;
        if (problem->nodes[last].kind == G3NodeKind::line_g2) split[problem->run_piece.back()] = true;
      } else {
        if (g2_line_joins == 0 && worst <= g3_overrun * budget && (!strayed || worst < strayed->deviation))
          strayed = PartialG3{*problem, std::move(g3.spirals), worst, 0};
        why = "the G3 curve strays " + std::to_string(worst) + " units from the source (budget " +
              std::to_string(budget) + ")";
        for (std::size_t i = 0; i < d.size(); ++i)
          if (d[i] > budget) split[problem->run_piece[i]] = true;
      }
    } else {
      // A stall may be a segment too long for one spiral's cubic κ: every one is cut.
      why = g3.reason;
      split.assign(pieces.size(), true);
      placement = after_stall;
      stalled = true;
    }
    for (std::size_t i = 0; i < pieces.size(); ++i)
      if (split[i]) pieces[i] *= 2;
  }
  return {false, held ? std::move(held) : std::move(strayed), why, stalled};
}

// G3 piece by piece (fair/g3_local.hpp) where no whole-run attempt meets it: the G2 curve's
// pieces refitted between their own nodes, one κ′ shared at each node; a piece whose spiral
// turns κ back or across zero, or strays past the budget, is cut in two at its middle, at most
// `max_local_rounds` times. Kept only where κ changes sign no more often than along the G2
// curve and varies at most `most_variation`.
bool try_local_g3(FairedRun& result, const RunReference& source, const SmoothRun& run, double budget,
                  double zero_curvature, double most_variation) {
  const std::optional<RunPieces> pieces = run_pieces(result.chains);
  if (!pieces) return false;
  std::vector<std::vector<double>> cuts;
  for (const PathPiece& p : pieces->pieces) cuts.push_back({0.0, p.length});
  for (int round = 0; round < max_local_rounds; ++round) {
    G3Problem problem = g3_problem(*pieces, run, cuts, false);
    const LocalG3 local = fit_g3_locally(problem, local_targets(*pieces, cuts, run.closed), zero_curvature);
    std::vector<bool> failed;
    for (const std::optional<PolynomialSpiral>& s : local.spirals) failed.push_back(!s);
    if (local.ok()) {
      G3Result g3;
      g3.spirals = local.found(), g3.ends = local.ends;
      const std::vector<double> d = distance_by_spiral(g3, problem, source, budget);
      for (std::size_t i = 0; i < d.size(); ++i) failed[i] = d[i] > budget;
      if (std::none_of(failed.begin(), failed.end(), [](bool f) { return f; })) {
        const std::vector<PathPiece> faired = curve_pieces(g3.spirals);
        if (sign_changes_along(faired, zero_curvature) > sign_changes_along(result.chains, zero_curvature) ||
            curvature_variation_along(faired) > most_variation)
          return false;
        const double worst = *std::max_element(d.begin(), d.end());
        adopt(result, PartialG3{std::move(problem), std::move(g3.spirals), worst, 0});
        return true;
      }
    }
    // Segment i is the interval of its run piece that starts at the piece's i − first cut.
    std::vector<std::vector<double>> next = cuts;
    for (std::size_t i = 0, first = 0; i < failed.size(); ++i) {
      const std::size_t p = problem.run_piece[i];
      if (i > 0 && p != problem.run_piece[i - 1]) first = i;
      if (failed[i]) next[p].push_back(0.5 * (cuts[p][i - first] + cuts[p][i - first + 1]));
    }
    for (std::vector<double>& c : next) std::sort(c.begin(), c.end());
    cuts = std::move(next);
  }
  return false;
}

}  // namespace

void reexpress_as_g3(FairedRun& result, const RunReference& source, const SmoothRun& run, double budget,
                     double zero_curvature) {
  const auto attempt = [&](SlopeRule rule, CutPlacement after_stall, std::optional<double> most) {
    return try_g3(result, source, run, budget, zero_curvature, rule, after_stall, most);
  };
  G3Attempt first = attempt(SlopeRule::harmonic_mean, CutPlacement::by_length, std::nullopt);
  if (first.met) return;
  const double most_variation = 2.0 * curvature_variation_along(pieces_of(result.chains));
  // Where no solve of the first stalled, the second would repeat it round for round.
  if ((first.stalled &&
       attempt(SlopeRule::harmonic_mean, CutPlacement::by_length_and_curvature, most_variation).met) ||
      attempt(SlopeRule::smooth_mean, CutPlacement::by_length_and_curvature, most_variation).met)
    return;
  if (try_local_g3(result, source, run, budget, zero_curvature, most_variation)) return;
  if (first.partial) adopt(result, *first.partial);
  else result.g3_shortfall = first.why;
}

}  // namespace gf
