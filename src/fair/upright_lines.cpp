#include "fair/upright_lines.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

#include "fair/contour_plan.hpp"
#include "fair/node_moves.hpp"
#include "geom/curvature.hpp"

namespace gf {

namespace {

constexpr double shortest_curve_share = 4.0;  // a neighbouring curve's chord, in moves
constexpr double collinear_line_deg = 10.0;   // a neighbouring line this near the axis: a kink
constexpr double parallel_turning_share = 0.25;  // of a curve's turning, the most a parallel handle leaves to turn

// A line's neighbour `now` (`was` in the source) with its node at `end` moved by `v`: its handle
// turned onto `axis` where it met the line tangentially; where that moves a long handle past
// the limit (DejaVu Sans's ☏: a quadratic's 317-unit handle 3° off the level, 17 units), kept
// parallel, if the fairing then has little to turn: the join within the kink limit, and a
// small share of what the curve turns (Heros's R: a 0.9° leg whose curves turn by 24° and 90°
// and whose 90-unit handles would move by a unit; not Caladea's z, a 1.9° foot whose bar turns
// by 1.9°, and would gain an S). None where the move is too far either way.
std::optional<Segment> neighbour_moved(const Segment& was, const Segment& now, SegmentEnd end, Vec2 v, bool tangential,
                                       Vec2 axis, const UprightLimits& limits) {
  if (tangential) {
    Segment turned = with_end_moved(now, end, v, axis);
    if (largest_move(was, turned) <= limits.max_move_units) return turned;
  }
  Segment parallel = with_end_moved(now, end, v);
  if (largest_move(was, parallel) > limits.max_move_units) return std::nullopt;
  if (!tangential) return parallel;
  const std::optional<Vec2> t0 = end_tangent(parallel, SegmentEnd::start), t1 = end_tangent(parallel, SegmentEnd::end);
  if (!t0 || !t1) return std::nullopt;
  const double turning = turning_angle(*t0, *t1);
  const double change = end == SegmentEnd::end ? turning_angle(*t1, axis) : turning_angle(axis, *t0);
  if (std::abs(change) >= radians(kink_limit_deg) || std::abs(change) > parallel_turning_share * std::abs(turning))
    return std::nullopt;
  return parallel;
}

}  // namespace

MovedContour stand_lines_upright(const Contour& source, const UprightLimits& limits) {
  MovedContour out{source, 0.0, 0};
  const Contour contour = with_cubics(source);
  Contour result = contour;
  const std::size_t n = contour.segments.size();
  std::vector<bool> node_moved(contour.node_count(), false);
  const double kink = radians(kink_limit_deg), max_angle = radians(limits.max_angle_deg);
  const auto node_after = [&](std::size_t i) { return contour.closed ? (i + 1) % n : i + 1; };

  for (std::size_t i = 0; i < n; ++i) {
    if (!is_line(contour.segments[i])) continue;
    const std::size_t a_node = i, b_node = node_after(i);
    const Vec2 a = contour.node_point(a_node), b = contour.node_point(b_node);
    const Vec2 d = b - a;
    const bool vertical = std::abs(d.y) >= std::abs(d.x);
    const double across = vertical ? d.x : d.y, along = vertical ? d.y : d.x;
    const double move = 0.5 * std::abs(across);
    if (move < 1e-6 || move > limits.max_move_units || std::atan2(std::abs(across), std::abs(along)) > max_angle) continue;
    if (node_moved[a_node] || node_moved[b_node]) continue;

    const Segment* before = (contour.closed || i > 0) ? &contour.segments[(i + n - 1) % n] : nullptr;
    const Segment* after = (contour.closed || i + 1 < n) ? &contour.segments[(i + 1) % n] : nullptr;
    const Vec2 axis = vertical ? Vec2{0.0, along > 0.0 ? 1.0 : -1.0} : Vec2{along > 0.0 ? 1.0 : -1.0, 0.0};
    // A neighbour the move would spoil, and whether a curve meets the line tangentially there.
    bool spoiled = false;
    const auto tangential_at = [&](const Segment* s, SegmentEnd its_end, std::size_t node) {
      if (!s) return false;
      const std::optional<Vec2> t = end_tangent(*s, its_end);
      if (!t) return false;
      if (is_straight_segment(*s)) {
        const double off_axis = std::abs(turning_angle(axis, *t));
        spoiled = spoiled || std::min(off_axis, std::numbers::pi - off_axis) < radians(collinear_line_deg);
        return false;
      }
      spoiled = spoiled || distance(start_point(*s), end_point(*s)) < shortest_curve_share * move;
      return contour.nodes[node].smooth.value_or(true) && std::abs(turning_angle(*t, d)) < kink;
    };
    const bool tangent_before = tangential_at(before, SegmentEnd::end, a_node);
    const bool tangent_after = tangential_at(after, SegmentEnd::start, b_node);
    if (spoiled || !(tangent_before || tangent_after)) continue;

    const Vec2 mid = 0.5 * (a + b);
    const Vec2 a_to = vertical ? Vec2{mid.x, a.y} : Vec2{a.x, mid.y};
    const Vec2 b_to = vertical ? Vec2{mid.x, b.y} : Vec2{b.x, mid.y};
    // On what earlier lines left (a curve between two stood lines moves at both ends).
    const std::size_t i_before = (i + n - 1) % n, i_after = (i + 1) % n;
    Contour trial = result;
    // Neighbour k (if any) moved at `end` by v; whether it could be.
    const auto move_neighbour = [&](const Segment* s, std::size_t k, SegmentEnd end, Vec2 v, bool tangent) {
      if (!s) return true;
      const std::optional<Segment> moved = neighbour_moved(contour.segments[k], trial.segments[k], end, v, tangent, axis, limits);
      if (moved) trial.segments[k] = *moved;
      return moved.has_value();
    };
    if (!move_neighbour(before, i_before, SegmentEnd::end, a_to - a, tangent_before) ||
        !move_neighbour(after, i_after, SegmentEnd::start, b_to - b, tangent_after))
      continue;
    trial.segments[i] = Line{a_to, b_to};
    double moved = move;
    for (const std::size_t k : {i_before, i_after})
      moved = std::max(moved, largest_move(contour.segments[k], trial.segments[k]));
    result = std::move(trial);
    node_moved[a_node] = node_moved[b_node] = true;
    out.moved = std::max(out.moved, moved);
    ++out.changes;
  }
  if (out.changes == 0) return out;
  out.contour = std::move(result);
  return out;
}

}  // namespace gf
