#include "fair/chain_fairing.hpp"

#include <algorithm>
#include <cmath>
#include <span>

#include "aesthetic/lcg_slope.hpp"
#include "fair/curve_samples.hpp"
#include "fair/g2_chain.hpp"
#include "fair/initial_tangents.hpp"
#include "geom/polyline_distance.hpp"

namespace gf {

namespace {

constexpr double default_alpha = 1.0;  // for arcs (every α fits) and pieces without a usable LCG
constexpr double alpha_candidates[] = {-2.0, -1.5, -1.0, -0.5, 0.0, 0.5, 1.0, 1.5, 2.0, 3.0, 4.0};
constexpr double max_relative_mismatch = 1e-9;  // |Δκ| / max|κ| the G2 solve must reach
// A stalled chain is kept with its jumps only while none exceeds the largest |κ| its segments'
// ends had before the solve (G2Result::curvature_scale): past that the solve has bent its
// junctions beyond anything the run draws (Lato's W, where a stem meets its notch 2° off
// tangent: κ of opposite signs across them), and the writeback's mean curvature there became a
// knot of cubics a few units long (κ·UPM 4,000, six inflections); the run is kept as drawn.
constexpr double max_kept_mismatch = 1.0;
constexpr double transition_shift_share = 0.25;  // of the budget, spent where a κ = 0 end leaves its line earlier

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

}  // namespace

double PieceAlphas::operator()(double s0, double s1) {
  const auto [at, added] = known_.try_emplace({s0, s1}, 0.0);
  if (added) {
    const std::vector<Cubic> cubics = ref_.cubics_between(s0, s1);
    const std::vector<Segment> segments(cubics.begin(), cubics.end());
    const LcgSlope slope = estimate_lcg_slope(segments);
    at->second = slope.kind == LcgSlope::Kind::slope ? std::clamp(slope.alpha, -2.0, 4.0) : default_alpha;
  }
  return at->second;
}

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

Vec2 end_tangent_of(double s, const RunReference& ref, const SmoothRun& run, double w) {
  if (!ref.closed() && s == 0.0) return run.start.tangent;
  if (!ref.closed() && s == ref.length()) return run.end.tangent;
  const Vec2 t = ref.mean_tangent(s, w);
  return t / norm(t);
}

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
  check_fidelity(sample_each<LogAestheticSegment>(built, budget), span, ref, source, guided, slid, budget, out);
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

}  // namespace gf
