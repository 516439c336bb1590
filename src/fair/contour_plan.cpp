#include "fair/contour_plan.hpp"

#include <algorithm>
#include <cmath>

#include "geom/curvature.hpp"

namespace gf {

namespace {

struct Piece {
  Segment segment;
  std::size_t source_node;
  bool straight;
};

// A handle under 1 % of its cubic's chord (a stub: Inconsolata's q has 0.4 units on a 154-unit
// bowl, beside its stem) turns the curve within a fraction of a unit, so the curve is seen to
// leave towards its next control point: the stub retracted onto its node, which moves the
// curve by at most 4/9 of the stub. What reads as a corner stays one, rather than a line join
// whose κ = 0 no curve within the tolerance can meet.
Cubic without_stub(const Cubic& c, SegmentEnd end) {
  Cubic out = c;
  const bool at_start = end == SegmentEnd::start;
  const Vec2 node = at_start ? c.p[0] : c.p[3], far = at_start ? c.p[3] : c.p[0];
  const Vec2 next = at_start ? c.p[2] : c.p[1];
  Vec2& handle = at_start ? out.p[1] : out.p[2];
  if (distance(handle, node) < 0.01 * distance(far, node) && next != node) handle = node;
  return out;
}

Vec2 drawn_tangent(const Segment& s, SegmentEnd end) {
  const Cubic* c = std::get_if<Cubic>(&s);
  return c ? *end_tangent(without_stub(*c, end), end) : *end_tangent(s, end);
}

// A curve meeting a line at a kink that turns against the curve's own bend, by more than the
// curve's whole cubic turns, can meet the line tangentially only through an inflection the
// source does not draw: TeX Gyre Pagella's E, whose base (κ·UPM −0.1, its last cubic turning
// 1.5°) meets its serif's line 2.5° the other way, had no G2 chain within the budget, and its
// smoothing guide rang into a wave of nodes. A curve that turns more takes the kink within its
// own turning (EB Garamond's W enters its notch at 2° against a hairpin), and under 2° the
// inflection stays within the rounding (Noto Sans's v, 1.4° against a nearly straight side,
// came out a 6.7° corner over a hook of κ·UPM −30 once rounded). So does it where the curve's
// handle at the join is too short for whole grid steps to hold the corner's direction within
// 1.5° (DejaVu Sans's ✌, a 7-unit handle, came out a 11.8° corner from the source's 2.7°).
constexpr double against_line_kink_deg = 2.0;
constexpr double against_line_least_handle = 1.0 / radians(1.5);  // a grid step across turns it by 1.5°

// The curve's tangent at its join with a line, turned the way the join turns until the join
// turns by the corner floor, where the join is a kink against the curve as above. `ta`, `tb`:
// the tangents of `a` and `b` at the join.
std::optional<Vec2> opened_against_line(const Piece& a, const Piece& b, Vec2 ta, Vec2 tb) {
  const double floor = radians(corner_floor_deg), turn = turning_angle(ta, tb);
  if (a.straight == b.straight || std::abs(turn) < radians(against_line_kink_deg) || std::abs(turn) >= floor)
    return std::nullopt;
  const Piece& curve = a.straight ? b : a;
  const Cubic& c = std::get<Cubic>(curve.segment);
  const Vec2 node = a.straight ? c.p[0] : c.p[3], handle = a.straight ? c.p[1] : c.p[2];
  if (distance(node, handle) < against_line_least_handle) return std::nullopt;
  const std::optional<double> k =
      end_curvature(curve.segment, a.straight ? SegmentEnd::start : SegmentEnd::end).curvature;
  if (!k || *k * turn >= 0.0) return std::nullopt;
  const double own = turning_angle(drawn_tangent(curve.segment, SegmentEnd::start),
                                   drawn_tangent(curve.segment, SegmentEnd::end));
  if (std::abs(own) > std::abs(turn)) return std::nullopt;
  const double opened = std::copysign(floor, turn);
  return a.straight ? direction_of(angle_of(ta) + opened) : direction_of(angle_of(tb) - opened);
}

// Whether the caller made the join in front of `node` smooth.
bool is_made_smooth(std::span<const std::size_t> smooth_nodes, std::size_t node) {
  return std::find(smooth_nodes.begin(), smooth_nodes.end(), node) != smooth_nodes.end();
}

// A line shorter than `stub_line_units` that a curve meets tangentially (within `tangential`
// radians: the tangential line angle, or PlanOptions::stub_turn_deg), with a corner (turning
// by more than `corner`) or another such curve at its other end, is the curve's last stretch
// drawn straight, not a line to meet with κ = 0: no curve leaves a one-unit line flat within
// it (Linux Biolinum's f, whose crossbar's curve ends on a line of one unit into the stem's
// corner, kept κ·UPM −0.73 there). It becomes a straight cubic of the curve's run.
void absorb_stub_lines(std::vector<Piece>& pieces, const Contour& contour, std::span<const std::size_t> smooth_nodes,
                       double tangential, double corner, double stub_line_units) {
  const std::size_t n = pieces.size();
  if (n < 3) return;
  // The join in front of piece b, from piece a (one of them the stub): +1 a curve meeting the
  // line tangentially, −1 a corner, 0 neither (another line, or a curve at a kink).
  const auto kind = [&](const Piece& a, const Piece& b) {
    const std::optional<bool> flag = contour.nodes[b.source_node].smooth;
    const double angle = std::abs(turning_angle(drawn_tangent(a.segment, SegmentEnd::end), drawn_tangent(b.segment, SegmentEnd::start)));
    if (!is_made_smooth(smooth_nodes, b.source_node) && (flag ? !*flag : angle > corner)) return -1;
    const Piece& other = a.straight ? b : a;
    return !other.straight && angle <= tangential ? 1 : 0;
  };
  std::vector<std::size_t> stubs;
  for (std::size_t i = 0; i < n; ++i) {
    const Piece& line = pieces[i];
    if (!line.straight || (!contour.closed && (i == 0 || i + 1 == n)) ||
        distance(start_point(line.segment), end_point(line.segment)) >= stub_line_units)
      continue;
    const Piece& prev = pieces[(i + n - 1) % n];
    const Piece& next = pieces[(i + 1) % n];
    const int in = kind(prev, line), out = kind(line, next);
    if (in != 0 && out != 0 && in + out >= 0) stubs.push_back(i);
  }
  for (const std::size_t i : stubs) {
    const Vec2 a = start_point(pieces[i].segment), b = end_point(pieces[i].segment);
    pieces[i].segment = Cubic{a, a + (b - a) / 3.0, a + (b - a) * (2.0 / 3.0), b};
    pieces[i].straight = false;
  }
}

}  // namespace

ContourPlan plan_contour(const Contour& source, std::span<const std::size_t> smooth_nodes, const PlanOptions& options) {
  const Contour contour = with_cubics(source);
  const auto made_smooth = [&](std::size_t node) { return is_made_smooth(smooth_nodes, node); };
  std::vector<Piece> pieces;
  for (std::size_t i = 0; i < contour.segments.size(); ++i) {
    const Segment& s = contour.segments[i];
    if (is_degenerate(s)) continue;
    const bool straight = is_straight_segment(s);
    const Segment piece = straight ? Segment{Line{start_point(s), end_point(s)}} : s;
    // Two lines meeting at a join made smooth are one line.
    if (straight && !pieces.empty() && pieces.back().straight && made_smooth(i))
      pieces.back().segment = Line{start_point(pieces.back().segment), end_point(s)};
    else
      pieces.push_back({piece, i, straight});
  }
  if (contour.closed && pieces.size() > 2 && pieces.front().straight && pieces.back().straight &&
      made_smooth(pieces.front().source_node)) {
    pieces.front() = {Line{start_point(pieces.back().segment), end_point(pieces.front().segment)}, pieces.back().source_node, true};
    pieces.pop_back();
  }
  ContourPlan plan;
  plan.closed = contour.closed;
  const std::size_t n = pieces.size();
  if (n == 0) return plan;
  const double corner = radians(options.corner_angle_deg);
  const double tangential_line = radians(options.tangential_line_deg);
  const double stub_turn = options.stub_turn_deg ? radians(*options.stub_turn_deg) : tangential_line;
  absorb_stub_lines(pieces, contour, smooth_nodes, std::min(corner, stub_turn), corner, options.stub_line_units);
  const bool corners_stay = options.corners_stay;

  // The join in front of piece i (between piece i−1 and i): its kind, nullopt when smooth
  // between two curves, and the curve's tangent there where it is a corner opened against its
  // line (opened_against_line).
  struct JoinPlan {
    std::optional<RunEndKind> kind;
    std::optional<Vec2> opened;
  };
  auto join_before = [&](std::size_t i) -> JoinPlan {
    if (!contour.closed && i == 0) return {RunEndKind::corner, std::nullopt};
    const Piece& a = pieces[(i + n - 1) % n];
    const Piece& b = pieces[i];
    if (a.straight && b.straight) return {RunEndKind::corner, std::nullopt};
    const Vec2 ta = drawn_tangent(a.segment, SegmentEnd::end), tb = drawn_tangent(b.segment, SegmentEnd::start);
    const std::optional<bool> flag = contour.nodes[b.source_node].smooth;
    const double angle = std::abs(turning_angle(ta, tb));
    // A curve meets a line tangentially only within the kink limit: bending a curve that leaves
    // a line at 10° into the line's direction would put a bump where the designer drew none.
    const bool line_join = a.straight || b.straight;
    std::optional<Vec2> opened;
    if (options.open_against_lines && !made_smooth(b.source_node) && !flag) opened = opened_against_line(a, b, ta, tb);
    const bool is_corner = made_smooth(b.source_node) ? false
                           : flag                     ? !*flag
                                                      : opened || angle > (line_join ? std::min(corner, tangential_line) : corner);
    if (is_corner) return {RunEndKind::corner, opened};
    return {line_join ? std::optional{RunEndKind::line} : std::nullopt, std::nullopt};  // opened is a corner
  };

  // The share of a line a run meeting it may take, by the kind of the line's far join.
  const auto line_share = [](const Piece& line, const std::optional<RunEndKind>& far_join) {
    const double length = distance(start_point(line.segment), end_point(line.segment));
    return far_join == RunEndKind::line ? 0.5 * length : length;
  };
  std::vector<std::optional<RunEndKind>> breaks(n);
  std::vector<std::optional<Vec2>> opened(n);
  for (std::size_t i = 0; i < n; ++i) {
    const JoinPlan join = join_before(i);
    breaks[i] = join.kind;
    opened[i] = join.opened;
  }
  const std::size_t first = static_cast<std::size_t>(
      std::find_if(breaks.begin(), breaks.end(), [](const auto& b) { return b.has_value(); }) - breaks.begin());
  if (first == n) {  // one closed run
    SmoothRun run;
    run.closed = true;
    for (const Piece& p : pieces) run.cubics.push_back(std::get<Cubic>(p.segment));
    plan.start_nodes.push_back(pieces[0].source_node);
    plan.pieces.emplace_back(std::move(run));
    return plan;
  }
  const std::size_t count = contour.closed ? n : n - first;
  for (std::size_t k = 0; k < count; ++k) {
    const std::size_t i = (first + k) % n;
    const Piece& p = pieces[i];
    if (p.straight) {
      plan.start_nodes.push_back(p.source_node);
      plan.pieces.emplace_back(std::get<Line>(p.segment));
      continue;
    }
    const std::optional<RunEndKind> before = breaks[i];
    if (before) {
      SmoothRun run;
      const Piece& prev = pieces[(i + n - 1) % n];
      run.start.kind = *before;
      run.start.tangent = *before == RunEndKind::line && prev.straight && (contour.closed || i > 0)
                              ? *end_tangent(prev.segment, SegmentEnd::end)
                              : opened[i].value_or(drawn_tangent(p.segment, SegmentEnd::start));
      run.start.opened = opened[i].has_value();
      if (*before == RunEndKind::line && prev.straight) run.start.line_share = line_share(prev, breaks[(i + n - 1) % n]);
      if (corners_stay && *before == RunEndKind::corner && (contour.closed || i > 0)) {
        run.start.beyond = drawn_tangent(prev.segment, SegmentEnd::end);
        run.start.beyond_line = prev.straight;
      }
      plan.start_nodes.push_back(p.source_node);
      plan.pieces.emplace_back(std::move(run));
    }
    SmoothRun& run = std::get<SmoothRun>(plan.pieces.back());
    const Cubic& cubic = std::get<Cubic>(p.segment);
    run.cubics.push_back(before == RunEndKind::corner ? without_stub(cubic, SegmentEnd::start) : cubic);
    const std::size_t next = (i + 1) % n;
    const bool ends = !contour.closed && i + 1 == n ? true : breaks[next].has_value();
    if (ends) {
      const RunEndKind kind = !contour.closed && i + 1 == n ? RunEndKind::corner : *breaks[next];
      run.end.kind = kind;
      run.end.tangent = kind == RunEndKind::line && pieces[next].straight
                            ? *end_tangent(pieces[next].segment, SegmentEnd::start)
                            : opened[next].value_or(drawn_tangent(p.segment, SegmentEnd::end));
      run.end.opened = opened[next].has_value();
      if (kind == RunEndKind::corner) run.cubics.back() = without_stub(run.cubics.back(), SegmentEnd::end);
      if (corners_stay && kind == RunEndKind::corner && (contour.closed || i + 1 < n)) {
        run.end.beyond = drawn_tangent(pieces[next].segment, SegmentEnd::start);
        run.end.beyond_line = pieces[next].straight;
      }
      if (kind == RunEndKind::line && pieces[next].straight) run.end.line_share = line_share(pieces[next], breaks[(next + 1) % n]);
    }
  }
  return plan;
}

std::size_t opened_corners(const ContourPlan& plan) {
  std::size_t count = 0;
  for (const auto& piece : plan.pieces)
    if (const SmoothRun* run = std::get_if<SmoothRun>(&piece)) count += run->start.opened + run->end.opened;
  return count;
}

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

}  // namespace gf
