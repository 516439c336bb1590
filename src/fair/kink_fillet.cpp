#include "fair/kink_fillet.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <span>
#include <variant>
#include <vector>

#include "fair/contour_plan.hpp"
#include "fair/outline_nodes.hpp"
#include "geom/curvature.hpp"
#include "geom/join.hpp"
#include "geom/polyline_distance.hpp"

namespace gf {

namespace {

// A fillet's longer leg at most this many times its shorter (fillet_legs).
constexpr double longest_leg_ratio = 4.0;

// How far the fillet (P0, C, C, P3) strays from the polyline P0–C–P3.
double fillet_deviation(Vec2 p0, Vec2 c, Vec2 p3) {
  constexpr int n = 32;
  const Cubic fillet{p0, c, c, p3};
  std::array<Vec2, n + 1> samples;
  for (int k = 0; k <= n; ++k) samples[k] = fillet.point_at(double(k) / n);
  const std::array<Vec2, 3> lines{p0, c, p3};
  return directed_hausdorff(samples, lines);
}

// The legs a fillet along `line` (from the vertex) may take, at most `most` long, longest
// first: on the grid whole numbers of the line's primitive steps (a dozen at most, spread
// geometrically), else lengths in the same ratios.
std::vector<Vec2> leg_choices(Vec2 line, double most, bool integer_grid) {
  std::vector<Vec2> out;
  const std::optional<Vec2> step = integer_grid ? primitive_step(line) : line / norm(line);
  if (!step) return out;
  double previous = 0.0;
  for (double r = most; r >= 1.0 && out.size() < 12; r *= 0.75) {
    const double whole = integer_grid ? std::floor(r / norm(*step)) : r;
    if (whole < (integer_grid ? 1.0 : 1e-9) || whole == previous) continue;
    out.push_back(*step * whole);
    previous = whole;
  }
  return out;
}

}  // namespace

std::optional<FilletLegs> fillet_legs(const Line& before, const Line& after, double most_back, double most_on,
                                      double allowance_units, bool integer_grid) {
  const Vec2 c = before.end();
  std::optional<FilletLegs> best;
  double best_short = 0.0, best_sum = 0.0;
  const std::vector<Vec2> backs = leg_choices(before.start() - c, most_back, integer_grid);
  const std::vector<Vec2> ons = leg_choices(after.end() - c, most_on, integer_grid);
  for (const Vec2 b : backs)
    for (const Vec2 o : ons) {
      const double shorter = std::min(norm(b), norm(o)), sum = norm(b) + norm(o);
      if (shorter < best_short || (shorter == best_short && sum <= best_sum)) continue;
      // The longer leg at most longest_leg_ratio times the shorter, or its line's shortest leg:
      // past that it only turns more of its line into curve (FreeSerif Italic's V: a stroke
      // split 7 units from its serif's curve, drawn whole as the fillet).
      const double longer = std::max(norm(b), norm(o));
      const double shortest_leg = norm(norm(b) >= norm(o) ? backs.back() : ons.back());
      if (longer > std::max(longest_leg_ratio * shorter, shortest_leg)) continue;
      if (fillet_deviation(c + b, c, c + o) > allowance_units) continue;
      best = FilletLegs{b, o}, best_short = shorter, best_sum = sum;
    }
  return best;
}

namespace {

// The way a join turns: +1 left, −1 right.
int way(const Join& j) { return (j.angle_deg > 0.0) - (j.angle_deg < 0.0); }

// Whether a join is a kink a fillet may take: under the kink limit (a join the source flags
// smooth is a kink at any angle, but a fillet cannot pass for it past the limit).
bool small_kink(const Join& j) { return j.kind == JoinKind::kink && std::abs(j.angle_deg) < kink_limit_deg; }

// The way (+1 left, −1 right, 0 none) a contour bends next to node k, going back (step −1)
// or on (+1) from it along joins under the kink limit: the kinks' turns and the curves'
// curvature near their end towards k, lines passed over. A fillet that turns against either
// would add an inflection where the kink had none. `join_at`: each node's join (geom/join.hpp).
int neighbour_bend(const Contour& contour, const std::vector<std::optional<Join>>& join_at, std::size_t k, int step) {
  const std::size_t n = contour.segments.size();
  for (std::size_t walked = 1; walked < n; ++walked) {
    if (!contour.closed && (step > 0 ? k + walked > n : walked > k)) return 0;
    // The next segment that way, and the node beyond it.
    const std::size_t seg = step > 0 ? (k + walked - 1) % n : (k + n - walked) % n;
    const Segment& s = contour.segments[seg];
    if (!is_line(s)) {
      const double kappa = curvature(derivatives_at(s, step > 0 ? 0.25 : 0.75)).value_or(0.0);
      return (kappa > 0.0) - (kappa < 0.0);
    }
    const std::size_t node = step > 0 ? (k + walked) % n : seg;
    const std::optional<Join>& j = node < join_at.size() ? join_at[node] : std::nullopt;
    if (!j || j->kind == JoinKind::degenerate || std::abs(j->angle_deg) >= kink_limit_deg) return 0;
    if (j->kind != JoinKind::smooth) return way(*j);
  }
  return 0;
}

// Node k joins segment k − 1 to segment k: the kinks between two lines that a fillet may take,
// where it bends the way its neighbours do, or they bend opposite ways.
std::vector<bool> kinks_to_fillet(const Contour& contour, const std::vector<std::optional<Join>>& join_at) {
  const std::size_t n = contour.segments.size();
  const auto is_line_at = [&](std::size_t i) { return std::holds_alternative<Line>(contour.segments[i % n]); };
  std::vector<bool> kink(contour.node_count(), false);
  for (std::size_t k = 0; k < n; ++k) {
    const std::optional<Join>& j = join_at[k];
    if (!j || !small_kink(*j) || !is_line_at(k + n - 1) || !is_line_at(k)) continue;
    // Against both (or the one known): an inflection the kink did not count as. Between a
    // bend each way the kink already lies on an inflection, which the fillet only moves
    // (Gentium Plus Italic's V: a stroke split near its top serif, which bends the other way
    // from the foot's curve 1,191 units on).
    const int back = neighbour_bend(contour, join_at, k, -1), on = neighbour_bend(contour, join_at, k, 1);
    const auto agrees = [&](int bend) { return bend == 0 || bend == way(*j); };
    kink[k] = (agrees(back) && agrees(on)) || (back != 0 && on != 0 && back != on);
  }
  return kink;
}

// A fillet at a moved vertex: (start, vertex, vertex, end), the lines redrawn to the vertex.
struct MovedVertex {
  Vec2 start, vertex, end;
};

// Points along a polyline at most a unit apart, its corners included.
std::vector<Vec2> densely(std::span<const Vec2> polyline) {
  std::vector<Vec2> out{polyline.front()};
  for (std::size_t i = 1; i < polyline.size(); ++i) {
    const int steps = std::max(1, static_cast<int>(std::ceil(distance(polyline[i - 1], polyline[i]))));
    for (int k = 1; k <= steps; ++k) out.push_back(polyline[i - 1] + (polyline[i] - polyline[i - 1]) * (double(k) / steps));
  }
  return out;
}

// The two-sided distance between the stretch as drawn and as redrawn with the fillet.
double redrawn_deviation(std::span<const Vec2> path, const MovedVertex& m) {
  std::vector<Vec2> redrawn{path.front()};
  const Cubic fillet{m.start, m.vertex, m.vertex, m.end};
  for (int k = 0; k <= 32; ++k) redrawn.push_back(fillet.point_at(double(k) / 32.0));
  redrawn.push_back(path.back());
  const std::vector<Vec2> a = densely(redrawn), b = densely(path);
  return std::max(directed_hausdorff(a, path), directed_hausdorff(b, redrawn));
}

// Where a kink's lines leave no whole legs on the grid, its vertex moved: the fillet's handles
// at a grid point V near `near` (the kink, or for two kinks with a line between them where the
// outer lines meet), each outer line redrawn from its far end to V, and the fillet's ends at
// grid points of those (each leg a whole number of the redrawn line's steps, at most half of
// it). `path`: the stretch replaced, from the first line's far end to the last line's; `turn`:
// the way it turns (+1 left), which V must keep.
std::optional<MovedVertex> moved_vertex_fillet(std::span<const Vec2> path, Vec2 near, int turn, double allowance) {
  const Vec2 from = path.front(), to = path.back();
  std::optional<MovedVertex> best;
  double best_short = 0.0, best_sum = std::numeric_limits<double>::infinity();
  const double reach = std::min(2.0 * allowance, 4.0);
  for (double dx = std::floor(near.x - reach); dx <= near.x + reach; dx += 1.0)
    for (double dy = std::floor(near.y - reach); dy <= near.y + reach; dy += 1.0) {
      const Vec2 v{dx, dy};
      if (distance(v, near) > reach) continue;
      const double c = cross(v - from, to - v);
      if ((c > 0.0 ? 1 : c < 0.0 ? -1 : 0) != turn) continue;  // the kink's way, or it would bend against it
      const std::optional<Vec2> back = primitive_step(from - v), on = primitive_step(to - v);
      if (!back || !on) continue;
      // Each leg at most half its redrawn line: the fillet rounds the kink, the lines stay lines.
      for (const Vec2 b : leg_choices(*back, 0.5 * norm(from - v), true))
        for (const Vec2 o : leg_choices(*on, 0.5 * norm(to - v), true)) {
          // The longest shorter leg, then the least of the lines taken: a stem stays a line.
          const double shorter = std::min(norm(b), norm(o)), sum = norm(b) + norm(o);
          if (shorter < best_short || (shorter == best_short && sum >= best_sum)) continue;
          const MovedVertex m{v + b, v, v + o};
          if (redrawn_deviation(path, m) > allowance) continue;
          best = m, best_short = shorter, best_sum = sum;
        }
    }
  return best;
}

// Where the lines through a0–a1 and b0–b1 meet; none where they run parallel.
std::optional<Vec2> lines_meet(Vec2 a0, Vec2 a1, Vec2 b0, Vec2 b1) {
  const Vec2 da = a1 - a0, db = b1 - b0;
  const double c = cross(da, db);
  if (std::abs(c) < 1e-12 * norm(da) * norm(db)) return std::nullopt;
  return a0 + da * (cross(b0 - a0, db) / c);
}

// Node k's join, for every node.
std::vector<std::optional<Join>> joins_by_node(const Contour& contour) {
  std::vector<std::optional<Join>> join_at(contour.node_count());
  for (const Join& j : joins_of(contour)) join_at[j.node] = j;
  return join_at;
}

// Each kink's legs for a fillet with whole legs at node k, none where no legs do.
std::vector<std::optional<FilletLegs>> whole_legs(const Contour& contour, const std::vector<bool>& kink,
                                                  double allowance_units, bool integer_grid) {
  const std::size_t n = contour.segments.size();
  const auto line = [&](std::size_t i) { return std::get_if<Line>(&contour.segments[i % n]); };
  // A line with a kink at both ends gives each fillet half of it; else the whole.
  const auto most = [&](std::size_t i, std::size_t other_end) {
    const Line& l = *line(i);
    return norm(l.end() - l.start()) * (other_end < kink.size() && kink[other_end] ? 0.5 : 1.0);
  };
  std::vector<std::optional<FilletLegs>> at(kink.size());
  for (std::size_t k = 0; k < n; ++k) {
    if (!kink[k]) continue;
    const std::size_t before = (k + n - 1) % n;
    at[k] = fillet_legs(*line(before), *line(k), most(before, before), most(k, contour.closed ? (k + 1) % n : k + 1),
                        allowance_units, integer_grid);
  }
  return at;
}

// fillet_kinks_at_moved_vertices, only at the kinks `wanted` marks (all where it is empty), or
// at a pair of which it marks either.
Contour moved_vertex_fillets(const Contour& contour, double allowance, const std::vector<bool>& wanted) {
  const std::size_t n = contour.segments.size();
  if (n < 3 || !contour.closed) return contour;
  const auto line = [&](std::size_t i) { return std::get_if<Line>(&contour.segments[i % n]); };
  const std::vector<std::optional<Join>> join_at = joins_by_node(contour);
  const auto corner = [&](std::size_t k) {
    const std::optional<Join>& j = join_at[k % n];
    return j && j->kind == JoinKind::corner;
  };
  const std::vector<bool> kink = kinks_to_fillet(contour, join_at);
  // Each replacement: the first line it takes and how many, and the fillet.
  struct Replacement {
    std::size_t first, lines;
    MovedVertex fillet;
  };
  std::vector<Replacement> done;
  std::vector<bool> taken(n, false);
  for (std::size_t k = 0; k < n; ++k) {
    if (!kink[k] || taken[(k + n - 1) % n] || taken[k]) continue;
    const bool pair = kink[(k + 1) % n] && !taken[(k + 1) % n] && way(*join_at[(k + 1) % n]) == way(*join_at[k]);
    if (!wanted.empty() && !wanted[k] && !(pair && wanted[(k + 1) % n])) continue;
    const std::size_t first = (k + n - 1) % n, lines = pair ? 3 : 2, last = first + lines - 1;
    // Not across the contour's seam, whose first node stays where it was.
    if (last >= n || !corner(first) || !corner((last + 1) % n)) continue;
    std::vector<Vec2> path;
    for (std::size_t i = 0; i < lines; ++i) path.push_back(line(first + i)->start());
    path.push_back(line(last)->end());
    const std::optional<Vec2> near = pair ? lines_meet(path[0], path[1], path[2], path[3]) : path[1];
    if (!near) continue;
    const std::optional<MovedVertex> m = moved_vertex_fillet(path, *near, way(*join_at[k]), allowance);
    if (!m) continue;
    for (std::size_t i = 0; i < lines; ++i) taken[(first + i) % n] = true;
    done.push_back({first, lines, *m});
  }
  if (done.empty()) return contour;
  std::vector<std::optional<std::size_t>> starts_here(n);
  for (std::size_t r = 0; r < done.size(); ++r) starts_here[done[r].first] = r;
  Contour out;
  out.closed = true;
  const NodeFlags smooth{false, true};
  for (std::size_t i = 0; i < n; ++i) {
    if (taken[i] && !starts_here[i]) continue;
    if (!starts_here[i]) {
      out.segments.push_back(contour.segments[i]);
      out.nodes.push_back(contour.nodes[i]);
      continue;
    }
    const Replacement& r = done[*starts_here[i]];
    const Vec2 from = line(r.first)->start(), to = line(r.first + r.lines - 1)->end();
    out.segments.push_back(Line{{from, r.fillet.start}});
    out.nodes.push_back(contour.nodes[i]);
    out.segments.push_back(Cubic{{r.fillet.start, r.fillet.vertex, r.fillet.vertex, r.fillet.end}});
    out.nodes.push_back(smooth);
    out.segments.push_back(Line{{r.fillet.end, to}});
    out.nodes.push_back(smooth);
  }
  return out;
}

}  // namespace

Contour fillet_kinks_at_moved_vertices(const Contour& contour, double allowance) {
  return moved_vertex_fillets(contour, allowance, {});
}

namespace {

// The kinks whose lines have whole legs for a fillet, filleted.
Contour fillet_with_whole_legs(const Contour& contour, double allowance_units, bool integer_grid) {
  const std::size_t n = contour.segments.size();
  const std::vector<std::optional<FilletLegs>> at =
      whole_legs(contour, kinks_to_fillet(contour, joins_by_node(contour)), allowance_units, integer_grid);
  if (std::none_of(at.begin(), at.end(), [](const std::optional<FilletLegs>& l) { return l.has_value(); }))
    return contour;

  Contour out;
  out.closed = contour.closed;
  const NodeFlags smooth{false, true};
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t end = contour.closed ? (i + 1) % n : i + 1;
    const bool filleted_end = end < at.size() && at[end].has_value();
    Vec2 from = start_point(contour.segments[i]), to = end_point(contour.segments[i]);
    if (at[i]) from = from + at[i]->on;
    if (filleted_end) to = to + at[end]->back;
    // A line a fillet took whole leaves its far node to the fillet (a corner stays one).
    const bool taken = is_line(contour.segments[i]) && from == to;
    if (!taken) {
      out.segments.push_back(is_line(contour.segments[i]) ? Segment{Line{from, to}} : contour.segments[i]);
      out.nodes.push_back(at[i] ? smooth : contour.nodes[i]);
    }
    if (filleted_end) {
      const Vec2 c = end_point(contour.segments[i]);
      out.segments.push_back(Cubic{to, c, c, c + at[end]->on});
      out.nodes.push_back(taken && !at[i] ? contour.nodes[i] : smooth);
    }
  }
  if (!contour.closed) out.nodes.push_back(contour.nodes.back());
  return out;
}

// Whether node `k`, a join of `contour`, would join the line `line` (starting or ending there)
// to a curve at a kink. A kink between lines the fillets take after.
bool kinks_a_curve(const Contour& contour, std::size_t k, const std::array<Vec2, 2>& line, SegmentEnd line_end) {
  const std::size_t n = contour.segments.size();
  if (!contour.closed && (k == 0 || k >= n)) return false;
  const Segment& beside = contour.segments[line_end == SegmentEnd::start ? (k + n - 1) % n : k];
  const std::optional<Vec2> other = end_tangent(beside, line_end == SegmentEnd::start ? SegmentEnd::end : SegmentEnd::start);
  if (is_line(beside) || !other) return false;
  return join_kind(degrees(turning_angle(*other, line[1] - line[0])), false) == JoinKind::kink;
}

}  // namespace

Contour merge_line_kinks(const Contour& contour, double allowance_units, bool only_against_neighbours) {
  const std::size_t n = contour.segments.size();
  const std::vector<std::optional<Join>> join_at = joins_by_node(contour);
  std::vector<bool> kink(n, false);
  for (std::size_t k = 0; k < n && k < join_at.size(); ++k) {
    const bool between_lines = is_line(contour.segments[(k + n - 1) % n]) && is_line(contour.segments[k]);
    if (join_at[k] && between_lines && small_kink(*join_at[k])) kink[k] = true;
  }
  if (only_against_neighbours) {
    const std::vector<bool> filleted = kinks_to_fillet(contour, join_at);
    for (std::size_t k = 0; k < n; ++k) kink[k] = kink[k] && !filleted[k];
  }
  // Each chain of kinks walked from the node before it (a closed contour from a node that is no
  // kink): a kink goes where the line from the chain's last kept node to the kink's far node
  // keeps every node between them within the allowance.
  const auto first = std::find(kink.begin(), kink.end(), false);
  if (first == kink.end()) return contour;
  const std::size_t start = contour.closed ? static_cast<std::size_t>(first - kink.begin()) : 0;
  std::vector<bool> merged(n, false);  // node k goes: segments k − 1 and k become one line
  bool any = false;
  std::size_t anchor = start;
  for (std::size_t step = 1; step < n; ++step) {
    const std::size_t k = (start + step) % n;
    if (!kink[k]) {
      anchor = k;
      continue;
    }
    const std::array<Vec2, 2> line{contour.node_point(anchor), end_point(contour.segments[k])};
    // Nor may the line meet a curve at a kink: Liberation Sans Narrow's v, whose curve leaves
    // the last of its lines along its (1, 4) step, would leave the merged line's (29, 117)
    // 0.12° off.
    bool fits = !kinks_a_curve(contour, anchor, line, SegmentEnd::start) &&
                !kinks_a_curve(contour, (k + 1) % n, line, SegmentEnd::end);
    for (std::size_t m = (anchor + 1) % n; fits && m != (k + 1) % n; m = (m + 1) % n) {
      const Vec2 dropped = contour.node_point(m);
      fits = directed_hausdorff(std::span(&dropped, 1), line) <= allowance_units;
    }
    if (fits) merged[k] = any = true;
    else anchor = k;
  }
  if (!any) return contour;
  Contour out;
  out.closed = contour.closed;
  for (std::size_t k = 0; k < n; ++k) {
    if (merged[k] && k > 0) {
      std::get<Line>(out.segments.back()).p[1] = end_point(contour.segments[k]);
      continue;
    }
    out.segments.push_back(contour.segments[k]);
    out.nodes.push_back(contour.nodes[k]);
  }
  if (merged[0] && out.segments.size() > 1) {  // the seam too: the last line runs on into the first
    std::get<Line>(out.segments.front()).p[0] = start_point(out.segments.back());
    out.nodes.front() = out.nodes.back();
    out.segments.pop_back(), out.nodes.pop_back();
  }
  if (!contour.closed) out.nodes.push_back(contour.nodes.back());
  if (out.closed && out.segments.size() < 3) return contour;  // a sliver folded onto itself
  return out;
}

Contour fillet_line_kinks(const Contour& contour, double allowance_units, bool integer_grid) {
  const Contour filleted = fillet_with_whole_legs(contour, allowance_units, integer_grid);
  return integer_grid ? fillet_kinks_at_moved_vertices(filleted, allowance_units) : filleted;
}

Contour fillet_legless_kinks_at_moved_vertices(const Contour& contour, double leg_allowance_units,
                                               double allowance_units) {
  const std::vector<bool> kink = kinks_to_fillet(contour, joins_by_node(contour));
  const std::vector<std::optional<FilletLegs>> legs = whole_legs(contour, kink, leg_allowance_units, true);
  std::vector<bool> legless(kink.size());
  for (std::size_t k = 0; k < kink.size(); ++k) legless[k] = kink[k] && !legs[k];
  if (std::none_of(legless.begin(), legless.end(), [](bool b) { return b; })) return contour;
  return moved_vertex_fillets(contour, allowance_units, legless);
}

}  // namespace gf
