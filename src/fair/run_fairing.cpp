#include "fair/run_fairing.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <span>

#include "aesthetic/lcg_slope.hpp"
#include "fair/g2_chain.hpp"
#include "fair/g3_local.hpp"
#include "fair/g3_run.hpp"
#include "fair/initial_tangents.hpp"
#include "fair/junctions.hpp"
#include "fair/path_piece.hpp"
#include "fair/run_reference.hpp"
#include "geom/curvature.hpp"
#include "geom/polyline_distance.hpp"
#include "geom/smoothing_spline.hpp"

namespace gf {

namespace {

constexpr double default_alpha = 1.0;  // for arcs (every α fits) and pieces without a usable LCG
constexpr double alpha_candidates[] = {-2.0, -1.5, -1.0, -0.5, 0.0, 0.5, 1.0, 1.5, 2.0, 3.0, 4.0};
constexpr int max_rounds = 10;
constexpr int fallback_rounds = 4;  // a text run on its guide, after its own outline failed
constexpr double max_relative_mismatch = 1e-9;  // |Δκ| / max|κ| the G2 solve must reach
// A stalled chain is kept with its jumps only while none exceeds the largest |κ| its segments'
// ends had before the solve (G2Result::curvature_scale): past that the solve has bent its
// junctions beyond anything the run draws (Lato's W, where a stem meets its notch 2° off
// tangent: κ of opposite signs across them), and the writeback's mean curvature there became a
// knot of cubics a few units long (κ·UPM 4,000, six inflections); the run is kept as drawn.
constexpr double max_kept_mismatch = 1.0;
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
constexpr int max_guide_refinements = 3;  // doublings of a smoothing guide's spans
constexpr double transition_shift_share = 0.25;  // of the budget, spent where a κ = 0 end leaves its line earlier

// α of each piece of a run's reference from its LCG, estimated once: a round of refinement
// solves again only the spans whose junctions changed, and most of their pieces are pieces of
// the round before (DejaVu Sans: one estimate in two was a repeat).
class PieceAlphas {
 public:
  explicit PieceAlphas(const RunReference& ref) : ref_(ref) {}
  double operator()(double s0, double s1) {
    const auto [at, added] = known_.try_emplace({s0, s1}, 0.0);
    if (added) {
      const std::vector<Cubic> cubics = ref_.cubics_between(s0, s1);
      const std::vector<Segment> segments(cubics.begin(), cubics.end());
      const LcgSlope slope = estimate_lcg_slope(segments);
      at->second = slope.kind == LcgSlope::Kind::slope ? std::clamp(slope.alpha, -2.0, 4.0) : default_alpha;
    }
    return at->second;
  }

 private:
  const RunReference& ref_;
  std::map<std::pair<double, double>, double> known_;
};

/// A chain over junctions first … last (indices into `junctions`, wrapping for a closed run).
struct ChainSpan {
  std::vector<double> s;  ///< arc lengths of its points (increasing; may pass L on a closed run)
  bool closed = false;
  bool zero_start = false, zero_end = false;
  bool operator==(const ChainSpan&) const = default;
};

std::vector<ChainSpan> chain_spans(const std::vector<Junction>& junctions, const RunReference& ref, const SmoothRun& run) {
  std::vector<ChainSpan> spans;
  const double L = ref.length();
  if (ref.closed()) {
    std::size_t first = junctions.size();
    for (std::size_t i = 0; i < junctions.size(); ++i)
      if (junctions[i].kind == JunctionKind::inflection) {
        first = i;
        break;
      }
    if (first == junctions.size()) {
      ChainSpan c;
      c.closed = true;
      for (const Junction& j : junctions) c.s.push_back(j.s);
      spans.push_back(std::move(c));
      return spans;
    }
    const std::size_t n = junctions.size();
    ChainSpan c;
    for (std::size_t k = 0; k <= n; ++k) {
      const std::size_t i = (first + k) % n;
      const double s = junctions[i].s + (first + k >= n ? L : 0.0);
      c.s.push_back(s);
      if (k > 0 && junctions[i].kind == JunctionKind::inflection) {
        c.zero_start = c.zero_end = true;
        spans.push_back(c);
        c = ChainSpan{};
        c.s.push_back(s);
      }
    }
    return spans;
  }
  ChainSpan c;
  c.zero_start = run.start.kind == RunEndKind::line;
  for (std::size_t i = 0; i < junctions.size(); ++i) {
    c.s.push_back(junctions[i].s);
    const bool last = i + 1 == junctions.size();
    if (i > 0 && (last || junctions[i].kind == JunctionKind::inflection)) {
      c.zero_end = last ? run.end.kind == RunEndKind::line : true;
      spans.push_back(c);
      c = ChainSpan{};
      c.zero_start = true;
      c.s.push_back(junctions[i].s);
    }
  }
  return spans;
}

struct ChainOutcome {
  std::optional<FairedChain> chain;
  std::vector<double> cuts;   ///< arc lengths where the chain needs another junction
  std::vector<double> drops;  ///< junctions (by arc length) the chain cannot use
  double deviation = 0.0;
  bool too_far = false;  ///< some piece strayed farther than the budget (else the cuts are for G2 or drawability)
  bool adjusts() const { return !cuts.empty() || !drops.empty(); }
};

// Each segment's points, so many that the chords stay within 2 % of the tolerance of the curve
// (log-aesthetic segments and spirals have monotone curvature: the larger end's bounds it).
template <class Curve>
std::vector<std::vector<Vec2>> sampled(std::span<const Curve> curves, double tolerance) {
  std::vector<std::vector<Vec2>> out;
  for (const Curve& c : curves) {
    const double k = std::max({std::abs(c.start().curvature), std::abs(c.end().curvature), 1e-9});
    const double h = std::sqrt(8.0 * 0.02 * tolerance / k);
    out.emplace_back();
    for (const LacPoint& p : c.sample(std::clamp(static_cast<int>(std::ceil(c.length() / h)), 8, 400)))
      out.back().push_back(p.point);
  }
  return out;
}

// Segment i's chord direction and its end tangents' angles from it, in (−π, π].
struct ChordAngles {
  double chord, at_start, at_end;
};
ChordAngles chord_angles(const LacChain& chain, std::size_t i) {
  const std::size_t j = (i + 1) % chain.points.size();
  const double c = angle_of(chain.points[j] - chain.points[i]);
  return {c, wrapped_angle(chain.tangent_angles[i] - c), wrapped_angle(chain.tangent_angles[j] - c)};
}

/// The arc length at the end of the span's segment i.
double segment_end_s(const ChainSpan& span, std::size_t i, double L) {
  return i + 1 < span.s.size() ? span.s[i + 1] : span.s[0] + L;
}

// Junctions a span lacks before a chain can be built on it: three for a closed chain, and a
// free junction of its own for each κ = 0 end (the longest piece is cut).
std::vector<double> missing_junctions(const ChainSpan& span, double L) {
  const std::size_t points = span.s.size();
  if (span.closed && points < 3) {
    if (points == 0) return {0.0, L / 3, 2 * L / 3};
    std::vector<double> cuts;
    for (std::size_t i = 0; i < points; ++i) cuts.push_back(0.5 * (span.s[i] + segment_end_s(span, i, L)));
    return cuts;
  }
  if (span.closed || !(span.zero_start || span.zero_end)) return {};
  const std::size_t needed = span.zero_start && span.zero_end ? 4 : 3;
  if (points >= needed) return {};
  std::size_t longest = 0;
  for (std::size_t i = 1; i + 1 < points; ++i)
    if (span.s[i + 1] - span.s[i] > span.s[longest + 1] - span.s[longest]) longest = i;
  return {0.5 * (span.s[longest] + span.s[longest + 1])};
}

// The tangent an open span holds at its end s: the run's own at the run's ends (a line's, or
// the guide's at a corner), else an inflection's, averaged over the window.
Vec2 end_tangent_of(double s, const RunReference& ref, const SmoothRun& run, double w) {
  if (!ref.closed() && s == 0.0) return run.start.tangent;
  if (!ref.closed() && s == ref.length()) return run.end.tangent;
  const Vec2 t = ref.mean_tangent(s, w);
  return t / norm(t);
}

// A corner the source turns by the kink limit or more keeps turning by this much (or by what
// the source turns, if less) when its tangent is turned: turned further, the kink pass would
// make it smooth, and the corner the source drew would be lost (Carlito's X: a terminal's
// curve met its diagonal at 6.6°, and the symmetric arc at 2.4°). corner_floor_deg leaves
// room for rounding.

// The angle a corner's tangent (now `current`) may be turned to on the way to `wanted`: all
// the way, or as far as the corner still turns by the floor against the piece beyond it, the
// way the source turns; nullopt where the floor leaves no turn at all, and at a corner opened
// to the floor (RunEnd::opened), whose tangent was set to turn so.
std::optional<double> kept_corner_angle(const RunEnd& end, bool at_start, double current, double wanted) {
  if (end.opened) return std::nullopt;
  if (end.beyond == Vec2{}) return wanted;
  const double beyond = angle_of(end.beyond);
  // Signed turn at the corner along the contour: from the piece beyond to the run at its start,
  // from the run to the piece beyond at its end.
  const auto turn = [&](double a) { return at_start ? wrapped_angle(a - beyond) : wrapped_angle(beyond - a); };
  const double drawn = turn(angle_of(end.tangent));
  if (std::abs(drawn) < radians(kink_limit_deg)) return wanted;
  // A curve beyond turns its own tangent within the same rule: each side takes half the room.
  const double least = std::min(std::abs(drawn), radians(corner_floor_deg));
  const double floor = end.beyond_line ? least : 0.5 * (least + std::abs(drawn));
  const double t = turn(wanted);
  if (t * drawn > 0.0 && std::abs(t) >= floor) return wanted;
  const double now = turn(current);
  if (now * drawn <= 0.0 || std::abs(now) <= floor) return std::nullopt;
  const double kept = std::copysign(floor, drawn);
  return current + wrapped_angle((at_start ? beyond + kept : beyond - kept) - current);
}

// The run's end that junction p of an open span is, where that end is a corner: only a corner's
// tangent is the chain's own to turn (an inflection's is shared with the next chain, a line's
// is the line's).
const RunEnd* corner_at(const ChainSpan& span, const RunReference& ref, const SmoothRun& run, std::size_t p) {
  if (span.closed || ref.closed()) return nullptr;
  if (p == 0 && span.s.front() == 0.0 && run.start.kind == RunEndKind::corner) return &run.start;
  if (p + 1 == span.s.size() && span.s.back() == ref.length() && run.end.kind == RunEndKind::corner) return &run.end;
  return nullptr;
}

// The chain on the span's junctions, before any repair: points averaged over the window and
// made to turn one way, balanced starting tangents, κ = 0 ends aimed, each free junction's
// tangent between its chords (`between_chords`), α from each piece's LCG.
LacChain initial_chain(const ChainSpan& span, const RunReference& ref, PieceAlphas& alphas, const SmoothRun& run,
                       double w, double budget, bool between_chords) {
  const double L = ref.length();
  const std::size_t points = span.s.size();
  LacChain chain;
  chain.closed = span.closed;
  chain.zero_curvature_start = span.zero_start;
  chain.zero_curvature_end = span.zero_end;
  for (std::size_t i = 0; i < points; ++i) chain.points.push_back(ref.mean_point(span.s[i], w));
  // A chain turns one way; a free junction that turns the other way (a wobble the window did
  // not average out) moves across its neighbours' chord, by little more than the wobble.
  const double way = span.closed ? ref.total_turning() : ref.theta_at(span.s.back()) - ref.theta_at(span.s.front());
  for (int pass = 0; pass < 3; ++pass)
    for (std::size_t i = 0; i < points; ++i) {
      if (!span.closed && (i == 0 || i + 1 == points)) continue;
      const Vec2 a = chain.points[(i + points - 1) % points], b = chain.points[(i + 1) % points];
      Vec2& q = chain.points[i];
      if (cross(q - a, b - q) * way > 0.0 || a == b) continue;
      const Vec2 d = (b - a) / norm(b - a);
      const Vec2 foot = a + d * dot(q - a, d);
      // A left-turning chain bulges to the right of the chord between neighbours.
      const Vec2 moved = foot - perpendicular(d) * (way > 0.0 ? 1.0 : -1.0) * (0.01 * budget);
      if (distance(moved, q) < 0.5 * budget) q = moved;
    }
  std::optional<double> start_angle, end_angle;
  if (!span.closed) {
    start_angle = angle_of(end_tangent_of(span.s.front(), ref, run, w));
    end_angle = angle_of(end_tangent_of(span.s.back(), ref, run, w));
  }
  chain.tangent_angles = balanced_tangents(chain.points, chain.closed, start_angle, end_angle, span.zero_start, span.zero_end);
  // A κ = 0 end needs the segment's other end to turn more than twice as much as its chord
  // (lac-math.md §3.2): aim the free neighbour there outright, where every segment keeps a
  // control triangle.
  if (!span.closed)
    for (const auto& [fixed, free] : {std::pair{std::size_t{0}, std::size_t{1}}, std::pair{points - 1, points - 2}}) {
      if (fixed == 0 ? !span.zero_start : !span.zero_end) continue;
      const ChordAngles g = chord_angles(chain, std::min(fixed, free));
      const double a = fixed == 0 ? g.at_start : g.at_end, b = fixed == 0 ? g.at_end : g.at_start;
      if (!(std::abs(b) < 2.2 * std::abs(a) || a * b > 0.0)) continue;
      std::optional<double> aimed = g.chord - 3.0 * a;
      if (const RunEnd* corner = corner_at(span, ref, run, free))
        aimed = kept_corner_angle(*corner, free == 0, chain.tangent_angles[free], *aimed);
      if (!aimed) continue;
      const std::vector<double> before = chain.tangent_angles;
      chain.tangent_angles[free] = *aimed;
      for (std::size_t i = 0; i + 1 < points; ++i)
        if (!tangents_meet_in_front(chain, i)) chain.tangent_angles = before;
    }
  if (between_chords)
    keep_tangents_between_chords(chain.points, chain.closed, way, chain.tangent_angles, span.zero_start, span.zero_end);
  for (std::size_t i = 0; i < chain.segment_count(); ++i)
    chain.alphas.push_back(alphas(span.s[i], segment_end_s(span, i, L)));
  return chain;
}

/// How far an open chain's κ = 0 ends may slide back into the lines they meet, in units (0: held).
struct LineRoom {
  double start = 0.0, end = 0.0;
};

// Whether the span's start (else its end) is where its run meets a line, not an inflection
// junction whose point the next chain shares.
bool meets_line(const ChainSpan& span, const RunReference& ref, const SmoothRun& run, bool at_start) {
  if (span.closed || ref.closed()) return false;
  return at_start ? span.s.front() == 0.0 && run.start.kind == RunEndKind::line
                  : span.s.back() == ref.length() && run.end.kind == RunEndKind::line;
}

// How far the span's κ = 0 ends may slide back into the lines they meet: half the run's share
// of each line (a line slid down to a sliver came out kinked once rounded: dkg Bold's y and D);
// none at an inflection.
LineRoom line_room(const ChainSpan& span, const RunReference& ref, const SmoothRun& run) {
  LineRoom room;
  if (span.zero_start && meets_line(span, ref, run, true)) room.start = 0.5 * run.start.line_share;
  if (span.zero_end && meets_line(span, ref, run, false)) room.end = 0.5 * run.end.line_share;
  return room;
}

// How far a κ = 0 end leaves its line earlier than the source does, where the source meets the
// line with curvature κ (a corner rounded between two lines, Lato's w; an arc ending on a
// stem): half the length l of the clothoid that takes the curvature from 0 to κ and shifts the
// curve off the source's by p, a share of the budget (a railway's transition curve: p = l²κ/24),
// within the room.
double transition_slide(double end_curvature, double budget, double room) {
  const double shift = transition_shift_share * budget;
  return std::min(0.5 * std::sqrt(24.0 * shift / std::max(std::abs(end_curvature), 1e-12)), room);
}

// The chain's κ = 0 end at a line (its start, or its end, which segment i ends at) put its
// transition_slide back along the line from where the reference meets the line, where that
// segment is still drawn; whether it moved (not when it was there already: make_drawable may
// have put it there before the solve stalled). `farther`: where that slide does not draw the
// segment, twice, four times… it, up to the room, the first that does (a curve whose source
// bends hard into the line: its transition slide is short).
bool leave_line_earlier(LacChain& chain, std::size_t i, bool at_start, const RunReference& ref, double budget,
                        LineRoom room, bool farther = false) {
  const double r = at_start ? room.start : room.end;
  if (!(r > 0.0)) return false;
  const double s = at_start ? 0.0 : ref.length();
  const double first = transition_slide(ref.curvature_at(s), budget, r);
  if (!(first > 0.0)) return false;
  const std::size_t p = at_start ? 0 : chain.points.size() - 1;
  const Vec2 held = chain.points[p];
  const auto drawn_slid = [&](double slide) {
    chain.points[p] = ref.point_at(s) + direction_of(chain.tangent_angles[p]) * (at_start ? -slide : slide);
    return chain.points[p] != held && build_chain_segment(chain, i).ok();
  };
  if (drawn_slid(first)) return true;
  for (double slide = first; farther && slide < r;)
    if (drawn_slid(slide = std::min(2.0 * slide, r))) return true;
  chain.points[p] = held;
  return false;
}

// Both κ = 0 ends of the chain at lines moved so; whether any moved.
bool leave_lines_earlier(LacChain& chain, const RunReference& ref, double budget, LineRoom room) {
  const bool start = chain.zero_curvature_start && leave_line_earlier(chain, 0, true, ref, budget, room);
  const bool end = chain.zero_curvature_end && leave_line_earlier(chain, chain.segment_count() - 1, false, ref, budget, room);
  return start || end;
}

// Makes every segment exist before the solve, or says which junctions to add or drop. In turn:
// a κ = 0 end at a line leaves the line earlier (transition_slide), and, where that does not
// draw its segment, twice as early and so on within its room (Liberation Sans 2.1's M: the
// curve from the inner vertex bends into the right stem's line with κ·UPM 45, its transition
// slide of a few units drew nothing, and the end went G1 with κ·UPM 2.3 left at the join); a
// κ = 0 end at a line the source's shape does not allow (its curvature falls towards the end)
// becomes a free end, G1 there, but on a guided run, whose guide meets the line with κ = 0
// where no chain does (dkg, Because We Learn and Kristi a–z A–Z unrounded: g2-jumps
// 0.9, 0.1 and 1.8 % → 0), and never at an inflection junction, where the next chain still
// meets it with κ = 0 (Linux Libertine's T and D, a jump each, κ·UPM 152 against 0 on T's
// serif); a corner's noisy tangent is turned; the nearest drawable α; a junction that does not
// turn with its neighbours is dropped; else the piece is cut.
void make_drawable(LacChain& chain, const ChainSpan& span, const RunReference& ref, const SmoothRun& run,
                   bool guided, double budget, LineRoom room, ChainOutcome& out) {
  const double L = ref.length();
  const std::size_t points = span.s.size(), segments = chain.segment_count();
  for (std::size_t i = 0; i < segments; ++i) {
    if (build_chain_segment(chain, i).ok()) continue;
    const bool at_start = i == 0 && chain.zero_curvature_start;
    const bool zero_here = !chain.closed && (at_start || (i + 1 == segments && chain.zero_curvature_end));
    // (The room is the line's only where the end meets one: line_room.)
    if (zero_here && leave_line_earlier(chain, i, at_start, ref, budget, room, true)) continue;
    if (zero_here && !guided && meets_line(span, ref, run, at_start)) {
      LacChain released = chain;
      (at_start ? released.zero_curvature_start : released.zero_curvature_end) = false;
      if (build_chain_segment(released, i).ok()) {
        chain = std::move(released);
        continue;
      }
    }
    // A corner's own tangent may be noise that leaves its piece undrawable (on the wrong side
    // of the chord, or so lopsided that no α draws it): turn it until the piece is the
    // symmetric arc, which every α draws, or as far as the corner stays one.
    const RunEnd* start_corner = i == 0 ? corner_at(span, ref, run, i) : nullptr;
    const RunEnd* end_corner = i + 1 == segments ? corner_at(span, ref, run, i + 1) : nullptr;
    if (start_corner || end_corner) {
      const ChordAngles g = chord_angles(chain, i);
      const bool at_start = start_corner && g.at_end != 0.0, at_end = !at_start && end_corner && g.at_start != 0.0;
      const std::size_t p = at_start ? i : i + 1;
      const std::optional<double> kept =
          at_start || at_end ? kept_corner_angle(at_start ? *start_corner : *end_corner, at_start, chain.tangent_angles[p],
                                                 g.chord - (at_start ? g.at_end : g.at_start))
                             : std::nullopt;
      if (kept) {
        LacChain turned = chain;  // copied only where a turn is to be tried
        turned.tangent_angles[p] = *kept;
        if (build_chain_segment(turned, i).ok()) {
          chain = std::move(turned);
          continue;
        }
      }
    }
    const double wanted = chain.alphas[i];
    std::vector<double> candidates(std::begin(alpha_candidates), std::end(alpha_candidates));
    std::sort(candidates.begin(), candidates.end(),
              [&](double a, double b) { return std::abs(a - wanted) < std::abs(b - wanted); });
    bool found = false;
    for (const double a : candidates) {
      chain.alphas[i] = a;
      if ((found = build_chain_segment(chain, i).ok())) break;
    }
    if (found) continue;
    chain.alphas[i] = wanted;
    // Junctions that do not turn one way (a wobble between them): drop one; cutting would
    // only make the pieces shorter and the wobble relatively larger. Not a κ = 0 end's own
    // free junction.
    const std::size_t j = (i + 1) % points;
    const bool start_free = chain.closed || i > 0, end_free = chain.closed || j + 1 < points;
    const bool needs_free_junction =
        !chain.closed && (span.zero_start || span.zero_end) && points <= (span.zero_start && span.zero_end ? 4u : 3u);
    if (!tangents_meet_in_front(chain, i) && (start_free || end_free) && !needs_free_junction)
      out.drops.push_back(span.s[end_free ? j : i]);
    else
      out.cuts.push_back(0.5 * (span.s[i] + segment_end_s(span, i, L)));
  }
}

// Where an open chain's κ = 0 end lies once it slid along its line (leave_line_earlier), against
// the source's end there; `back` > 0 into the line.
struct SlidEnd {
  Vec2 point, source_point;
  double back;
};
struct SlidEnds {
  std::optional<SlidEnd> start, end;
};
// The chain's ends that slid: those off the reference's own ends (where initial_chain put them).
SlidEnds slid_ends(const LacChain& chain, const RunReference& ref, const RunReference& source, LineRoom room) {
  SlidEnds out;
  for (const bool at_start : {true, false}) {
    if (!((at_start ? room.start : room.end) > 0.0)) continue;
    const std::size_t p = at_start ? 0 : chain.points.size() - 1;
    if (chain.points[p] == ref.point_at(at_start ? 0.0 : ref.length())) continue;
    const Vec2 held = source.point_at(at_start ? 0.0 : source.length());
    const Vec2 back = direction_of(chain.tangent_angles[p]) * (at_start ? -1.0 : 1.0);
    (at_start ? out.start : out.end) = SlidEnd{chain.points[p], held, dot(chain.points[p] - held, back)};
  }
  return out;
}

// Fidelity, piece by piece against the source between the same junctions (the guide's arc
// length mapped onto the source's in proportion; with a guide (`guided`: ref is the guide,
// not the source), the source side gets a margin for the difference and the source is
// compared with the piece and its neighbours). Pieces over the budget are cut in the middle.
void check_fidelity(const std::vector<std::vector<Vec2>>& lac, const ChainSpan& span, const RunReference& ref,
                    const RunReference& source, bool guided, const SlidEnds& slid, double budget, ChainOutcome& out) {
  const std::size_t segments = lac.size();
  const double L = ref.length();
  const double scale = source.length() / L, margin = guided ? 0.02 * source.length() : 0.0;
  for (std::size_t i = 0; i < segments; ++i) {
    const double s0 = span.s[i], s1 = segment_end_s(span, i, L);
    std::vector<Vec2> near = source.polyline(s0 * scale - margin, s1 * scale + margin);
    std::vector<Vec2> own = guided ? source.polyline(s0 * scale, s1 * scale) : near;
    std::vector<Vec2> piece = lac[i];
    // An end slid along its line: the line is the source's as far as the end went back into
    // it, and the faired outline's as far as it went forwards.
    for (const bool at_start : {true, false}) {
      if (at_start ? i > 0 : i + 1 < segments) continue;
      const std::optional<SlidEnd>& e = at_start ? slid.start : slid.end;
      if (!e) continue;
      const auto put = [at_start](std::vector<Vec2>& v, Vec2 p) { v.insert(at_start ? v.begin() : v.end(), p); };
      if (e->back > 0.0) put(near, e->point), put(own, e->point);
      else put(piece, e->source_point);
    }
    std::vector<Vec2> around = piece;
    if (guided)
      for (const std::size_t k : {i + segments - 1, i + 1}) {  // the neighbours, wrapping on a closed chain
        if (!span.closed && (k == i + segments - 1 ? i == 0 : i + 1 == segments)) continue;
        around.insert(around.end(), lac[k % segments].begin(), lac[k % segments].end());
      }
    const double d = std::max(directed_hausdorff(piece, near), directed_hausdorff(own, around));
    out.deviation = std::max(out.deviation, d);
    if (d > budget) out.cuts.push_back(0.5 * (s0 + s1)), out.too_far = true;
  }
}

// `guided`: ref is the run's smoothing guide, source the run itself (else both are the source).
// Once `accept_mismatch`, a chain whose G2 solve stalls is kept with its best angles where
// `keep_stalled`, else gives way (to the guide on a guided run, else to the next RunBasis).
// κ = 0 ends may leave their lines earlier where `leave_lines`.
ChainOutcome fair_chain(const ChainSpan& span, const RunReference& ref, PieceAlphas& alphas, const RunReference& source,
                        bool guided, const SmoothRun& run, const FairSettings& settings, double budget,
                        bool accept_mismatch, bool keep_stalled, bool leave_lines) {
  ChainOutcome out;
  const double L = ref.length();
  out.cuts = missing_junctions(span, L);
  if (out.adjusts()) return out;
  LacChain chain = initial_chain(span, ref, alphas, run, settings.feature_window_units, budget,
                                 settings.tangents_between_chords);
  const LineRoom room = leave_lines ? line_room(span, ref, run) : LineRoom{};
  make_drawable(chain, span, ref, run, guided, budget, room, out);
  if (out.adjusts()) return out;

  std::vector<LogAestheticSegment> built;
  double mismatch = 0.0;
  if (settings.continuity != Continuity::g1 && chain.free_junction_count() > 0) {
    const G2Tolerance g2_tolerance{0.0, 0.1 * max_relative_mismatch};
    G2Result g2 = make_g2(chain, g2_tolerance);
    if (g2.segments.empty()) return out;
    const auto relative = [](const G2Result& r) { return r.curvature_scale > 0.0 ? r.max_mismatch / r.curvature_scale : 0.0; };
    // Held where the source meets its lines, κ = 0 ends may leave no G2 within the feasible
    // angles; leaving the lines earlier, they may.
    if (relative(g2) > max_relative_mismatch)
      if (LacChain placed = chain; leave_lines_earlier(placed, ref, budget, room))
        if (G2Result again = make_g2(placed, g2_tolerance); !again.segments.empty() && relative(again) < relative(g2))
          g2 = std::move(again);
    mismatch = relative(g2);
    if (mismatch > max_relative_mismatch) {
      if (accept_mismatch && (!keep_stalled || mismatch > max_kept_mismatch)) return out;
      if (!accept_mismatch) {
        // No G2 within reach of these junctions: more freedom next to the worst junction.
        const auto worst = std::max_element(g2.mismatches.begin(), g2.mismatches.end(),
                                            [](double a, double b) { return std::abs(a) < std::abs(b); });
        const std::size_t j = g2.chain.first_free_junction() + static_cast<std::size_t>(worst - g2.mismatches.begin());
        const std::size_t segments = chain.segment_count();
        for (const std::size_t i : {(j + segments - 1) % segments, j % segments})
          out.cuts.push_back(0.5 * (span.s[i] + segment_end_s(span, i, L)));
        return out;
      }
    }
    built = std::move(g2.segments);
    chain = std::move(g2.chain);
  } else {
    built = build_chain(chain).segments;
  }
  const SlidEnds slid = slid_ends(chain, ref, source, room);
  check_fidelity(sampled<LogAestheticSegment>(built, budget), span, ref, source, guided, slid, budget, out);
  if (out.adjusts()) return out;
  FairedChain faired;
  faired.slid_line_ends = slid.start || slid.end;
  faired.segments = std::move(built);
  faired.closed = chain.closed;
  faired.zero_curvature_start = chain.zero_curvature_start;
  faired.zero_curvature_end = chain.zero_curvature_end;
  faired.max_mismatch_relative = mismatch;
  out.chain = std::move(faired);
  return out;
}

// Handwriting traced from scans wobbles at every scale below the tolerance: the junctions and
// the chain are built on a guide, the smoothest cubic spline of the run within `tolerance` of
// it (geom/smoothing_spline; one span per half feature window, up to eight where that cannot
// come within it), while fidelity is measured against the source itself. A line's tangent is
// held at its end (and κ = 0 there, given `straight_line_ends`); a corner's is the guide's.
// None when no spline comes within the tolerance. A professional outline is its own guide until
// no chain on it comes within the budget (fair_run).
std::optional<SmoothRun> guide_for(const SmoothRun& run, const RunReference& source, double tolerance, double window,
                                   SmoothingPenalty penalty, const LobeMerging& merging, bool straight_line_ends) {
  const double L = source.length();
  const int count = std::clamp(static_cast<int>(L / 1.5), 40, 1200);
  std::vector<Vec2> points;
  for (int i = 0; i <= count; ++i) {
    if (run.closed && i == count) break;
    points.push_back(source.point_at(L * i / count));
  }
  SmoothingEnds ends;
  if (run.starts_at_line()) ends.start_tangent = run.start.tangent;
  if (run.ends_at_line()) ends.end_tangent = run.end.tangent;
  ends.straight_ends = straight_line_ends;
  int spans = std::clamp(static_cast<int>(std::ceil(L / (0.5 * window))), run.closed ? 4 : 1, 80);
  const auto within = [&](const BSplineFit& f) { return !f.spans.empty() && f.max_residual <= 1.05 * tolerance; };
  BSplineFit fit = fit_smoothing_spline(points, tolerance, spans, run.closed, ends, penalty, merging);
  // A thin contour's tolerance is half its thickness, a tenth of a unit on a brush font's
  // hairline (Because We Create's t): finer spans there, at least two points each.
  for (int k = 0; k < max_guide_refinements && !within(fit) && 4 * spans <= static_cast<int>(points.size()); ++k) {
    spans *= 2;
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

// How far each G3 spiral is from the source run (geom/polyline_distance's distance_by_piece),
// each side carried along a line the run meets as far as the other side reaches there (a line
// end slides along its line, and the line with it).
std::vector<double> distance_by_spiral(const G3Result& g3, const G3Problem& problem, const RunReference& source,
                                       double budget) {
  std::vector<Vec2> faired;
  std::vector<std::size_t> spiral_of;
  const std::vector<std::vector<Vec2>> pieces = sampled<PolynomialSpiral>(g3.spirals, budget);
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

// The run made G3 in full by the first of three attempts that does it:
// - Fritsch–Butland κ′ (g3_run.hpp's SlopeRule), cut at equal lengths;
// - the same, but cut where κ changes fast too once a solve stalls (a stall is mostly a spiral
//   whose cubic κ cannot follow a steep rise);
// - that with the smooth mean, whose Newton does not stall where a secant crosses zero (dkg's T).
// A run the first meets is as it was (with the second first, many of Because We Learn's guided
// runs, cut for their signs and then stalled, came out otherwise: 8 curvature extrema more in
// all). The second and
// third are taken only where κ varies at most twice as much as along the G2 curve (a run of
// Leckerli's F came out G3 varying 5.6 times as much, one of dkg's T 10.6 times; of the 521
// runs of dkg the first attempt makes G3, 7 vary over 1.5 times as much, the most 5.7). a–z
// A–Z, the smooth joins of the segments off G3: dkg Bold 193 → 23, dkg 18 → 10, Ruf 57 → 9,
// Leckerli 17 → 0.
// None in full: the first attempt's partial G3, else G2 and why.
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

}  // namespace

LacPoint FairedChain::start_frame() const {
  if (!spirals.empty()) return spirals.front().start();
  if (!segments.empty()) return segments.front().start();
  return closed ? guide->guide->frame_at(guide->s0) : guide->start;
}

LacPoint FairedChain::end_frame() const {
  if (!spirals.empty()) return spirals.back().end();
  if (!segments.empty()) return segments.back().end();
  return closed ? guide->guide->frame_at(guide->s1) : guide->end;
}

namespace {

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
    return guide_for(run, source, budget * settings.guide_share, settings.feature_window_units, penalty,
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
