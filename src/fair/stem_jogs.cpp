#include "fair/stem_jogs.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <span>
#include <vector>

#include "fair/contour_plan.hpp"

namespace gf {

namespace {

constexpr int most_jog_cubics = 3;
constexpr double least_jog_units = 1.0;  // narrower, the grid's nearest points may straighten it
constexpr double jog_slack_units = 0.5;  // how far a jog's control points may pass its far side
constexpr double s_return = 0.25;        // of the farthest a jog turns, the most its ends may
constexpr double shortest_curve_share = 2.0;  // a moved curve's chord, in jog widths (4 moves)

// A jog read in the direction of travel: from the line's end `b` (the line along unit `u`),
// the cubics `jog`, in order. How far across the line (signed, along u's left normal) the jog
// ends, where it is one.
std::optional<double> jog_offset(Vec2 b, Vec2 u, std::span<const Cubic> jog, double max_across, bool s_only) {
  const double kink = radians(kink_limit_deg);
  const Vec2 normal{-u.y, u.x};
  const std::optional<Vec2> leaves = end_tangent(Segment{jog.front()}, SegmentEnd::start);
  const std::optional<Vec2> arrives = end_tangent(Segment{jog.back()}, SegmentEnd::end);
  if (!leaves || !arrives || std::abs(turning_angle(u, *leaves)) >= kink || std::abs(turning_angle(u, *arrives)) >= kink)
    return std::nullopt;
  const Vec2 e = jog.back().p[3];
  const double across = dot(e - b, normal), along = dot(e - b, u);
  if (std::abs(across) < least_jog_units || std::abs(across) > max_across || along <= 0.0 ||
      std::atan2(std::abs(across), along) >= kink)
    return std::nullopt;
  // An S, not a bend: its tangent turns away from the line's direction and comes back, both
  // ends within a quarter of the farthest it turns (Liberation Sans's n: its stem's top bends
  // 1.7° towards the corner, a taper the designer drew). Between two parallel lines a bend is
  // a jog too (`s_only` false).
  double farthest = 0.0;
  for (const Cubic& c : jog)
    for (int k = 1; k < 16; ++k)
      if (const Vec2 d = c.hodograph().point_at(k / 16.0); norm(d) > 0.0)
        farthest = std::max(farthest, std::abs(turning_angle(u, d)));
  if (s_only && (std::abs(turning_angle(u, *leaves)) > s_return * farthest ||
                 std::abs(turning_angle(u, *arrives)) > s_return * farthest))
    return std::nullopt;
  // Every control point between the line and the jog's far side, give or take the slack.
  const double low = std::min(0.0, across) - jog_slack_units, high = std::max(0.0, across) + jog_slack_units;
  for (const Cubic& c : jog) {
    if (is_straight(c)) return std::nullopt;
    for (const Vec2 q : c.p)
      if (const double off = dot(q - b, normal); off < low || off > high) return std::nullopt;
  }
  return across;
}

// The contour with segments `gone` (indices, mod n) and the nodes starting them removed, and
// segment `line_at` replaced by `line`.
Contour without(const Contour& c, std::size_t line_at, const Line& line, std::span<const std::size_t> gone) {
  Contour out;
  out.closed = c.closed;
  for (std::size_t j = 0; j < c.segments.size(); ++j) {
    if (std::find(gone.begin(), gone.end(), j) != gone.end()) continue;
    out.segments.push_back(j == line_at ? Segment{line} : c.segments[j]);
    out.nodes.push_back(c.nodes[j]);
  }
  if (!c.closed) out.nodes.push_back(c.nodes.back());
  return out;
}

// The first jog of `c` (a line, then the jog forwards; or the jog, then the line, read
// backwards) straightened, where one moves no control point past `limit`; nullopt where none.
std::optional<std::pair<Contour, double>> straighten_first_jog(const Contour& c, double limit) {
  const std::size_t n = c.segments.size();
  if (n < 3) return std::nullopt;
  const auto at = [&](std::ptrdiff_t j) -> std::optional<std::size_t> {
    if (c.closed) return static_cast<std::size_t>(((j % std::ptrdiff_t(n)) + std::ptrdiff_t(n)) % std::ptrdiff_t(n));
    if (j < 0 || j >= std::ptrdiff_t(n)) return std::nullopt;
    return static_cast<std::size_t>(j);
  };
  const auto cubic = [&](std::optional<std::size_t> j) -> const Cubic* {
    return j ? std::get_if<Cubic>(&c.segments[*j]) : nullptr;
  };
  for (std::size_t i = 0; i < n; ++i) {
    if (!is_line(c.segments[i]) || is_degenerate(c.segments[i])) continue;  // Lato closes its N on a line of no length
    const Line& line = std::get<Line>(c.segments[i]);
    for (const int way : {1, -1}) {
      // Read in the jog's direction of travel: forwards from the line's end, or backwards from its start.
      const Vec2 from = way > 0 ? line.start() : line.end(), to = way > 0 ? line.end() : line.start();
      const Vec2 u = (to - from) / distance(to, from);
      std::vector<Cubic> jog;
      for (int k = 1; k <= most_jog_cubics; ++k) {
        const Cubic* next = cubic(at(std::ptrdiff_t(i) + way * k));
        if (!next) break;
        jog.push_back(way > 0 ? *next : next->reversed());
        // A node the source flags a corner (the line's end, or one inside the jog) ends the search.
        const std::size_t node = way > 0 ? *at(std::ptrdiff_t(i) + k) : *at(std::ptrdiff_t(i) - k + 1);
        if (!c.nodes[node].smooth.value_or(true)) break;
        // The curve after the jog (a cubic, or a line turning away from it) and the segment
        // before the line.
        const std::optional<std::size_t> after = at(std::ptrdiff_t(i) + way * (k + 1));
        const std::optional<std::size_t> before = at(std::ptrdiff_t(i) - way);
        if (!after || *after == i || (before && *before == *after)) break;
        const Segment& next_one = c.segments[*after];
        const Vec2 onwards = way > 0 ? end_point(next_one) - start_point(next_one) : start_point(next_one) - end_point(next_one);
        const bool straight_on = is_straight_segment(next_one) && std::abs(turning_angle(u, onwards)) < radians(kink_limit_deg);
        // Or a line going on parallel along the jog's far side: the jog is between two lines,
        // which become one (Liberation Sans Narrow's d: its stem 674 units across up to 990,
        // a quadratic bending 2.4° off it, then 673 across; on the grid a cubic between two
        // parallel tangents a unit apart cannot leave both with κ = 0).
        const bool onto_line = straight_on && is_line(next_one) && !is_degenerate(next_one);
        const std::optional<double> across = jog_offset(to, u, jog, 2.0 * limit, !onto_line);
        if (!across) continue;
        const Vec2 normal{-u.y, u.x};
        const Vec2 far = onto_line ? (way > 0 ? end_point(next_one) : start_point(next_one)) : jog.back().p[3];
        // Another straight segment going on along the far side would meet the new line at a kink.
        if (straight_on && (!onto_line || std::abs(dot(far - to, normal) - *across) > jog_slack_units)) break;
        // Past a line, the segment beyond it moves instead of the curve after the jog.
        const std::optional<std::size_t> moving = onto_line ? at(std::ptrdiff_t(i) + way * (k + 2)) : after;
        if (!moving || *moving == i || (before && *before == *moving)) break;
        // A short curve at either end would be bent out of shape by the move.
        const auto too_short = [&](std::optional<std::size_t> j) {
          return j && !is_straight_segment(c.segments[*j]) &&
                 distance(start_point(c.segments[*j]), end_point(c.segments[*j])) < shortest_curve_share * std::abs(*across);
        };
        if (too_short(before) || too_short(moving)) break;
        const Vec2 shift = normal * (0.5 * *across);
        Contour moved = c;
        double most = 0.5 * std::abs(*across);
        // Forwards the line's start takes +shift and the segment after the jog (or after the
        // line beyond it) −shift from its start; backwards the same, read the other way round.
        const SegmentEnd after_end = way > 0 ? SegmentEnd::start : SegmentEnd::end;
        moved.segments[*moving] = with_end_moved(c.segments[*moving], after_end, -1.0 * shift);
        if (before)
          moved.segments[*before] = with_end_moved(c.segments[*before], way > 0 ? SegmentEnd::end : SegmentEnd::start, shift);
        for (const std::optional<std::size_t> j : {before, moving})
          if (j) most = std::max(most, largest_move(c.segments[*j], moved.segments[*j]));
        if (most > limit) break;
        const Vec2 start = from + shift, end = far - shift;
        const int last = onto_line ? k + 1 : k;  // the segments the new line replaces after the line
        std::vector<std::size_t> gone;
        std::size_t line_at = i;
        if (way > 0) {
          for (int g = 1; g <= last; ++g) gone.push_back(*at(std::ptrdiff_t(i) + g));
        } else {
          // The new line starts where the jog (or the line beyond it) did: the segments from
          // there to the old line go, and the new line takes the first one's place.
          line_at = *at(std::ptrdiff_t(i) - last);
          for (int g = 0; g < last; ++g) gone.push_back(*at(std::ptrdiff_t(i) - g));
        }
        const Line straight = way > 0 ? Line{start, end} : Line{end, start};
        return std::pair{without(moved, line_at, straight, gone), most};
      }
    }
  }
  return std::nullopt;
}

}  // namespace

MovedContour straighten_stem_jogs(const Contour& source, const JogLimits& limits) {
  MovedContour out{source, 0.0, 0};
  Contour contour = with_cubics(source);
  // One at a time: each changes the indices of the rest. A contour has few.
  while (out.changes < int(contour.segments.size())) {
    const std::optional<std::pair<Contour, double>> next = straighten_first_jog(contour, limits.max_move_units);
    if (!next) break;
    contour = next->first;
    out.moved += next->second;  // a control point two jogs move moves by at most the sum
    ++out.changes;
  }
  if (out.changes > 0) out.contour = std::move(contour);
  return out;
}

}  // namespace gf
