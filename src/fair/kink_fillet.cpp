#include "fair/kink_fillet.hpp"

#include <array>
#include <cmath>
#include <optional>
#include <vector>

#include "fair/contour_plan.hpp"
#include "fair/outline_nodes.hpp"
#include "geom/curvature.hpp"
#include "geom/join.hpp"
#include "geom/polyline_distance.hpp"

namespace gf {

namespace {

// The two legs of the fillet at a kink: from the vertex back along the line before, and on
// along the line after.
struct Legs {
  Vec2 back, on;
};

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

// The legs within the allowance whose shorter is longest (then whose sum is): the fillet
// turns most gently there.
std::optional<Legs> fillet_legs(const Line& before, const Line& after, double most_back, double most_on,
                                double allowance, bool integer_grid) {
  const Vec2 c = before.end();
  std::optional<Legs> best;
  double best_short = 0.0, best_sum = 0.0;
  for (const Vec2 b : leg_choices(before.start() - c, most_back, integer_grid))
    for (const Vec2 o : leg_choices(after.end() - c, most_on, integer_grid)) {
      const double shorter = std::min(norm(b), norm(o)), sum = norm(b) + norm(o);
      if (shorter < best_short || (shorter == best_short && sum <= best_sum)) continue;
      if (fillet_deviation(c + b, c, c + o) > allowance) continue;
      best = Legs{b, o}, best_short = shorter, best_sum = sum;
    }
  return best;
}

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

}  // namespace

Contour fillet_line_kinks(const Contour& contour, double allowance_units, bool integer_grid) {
  const std::size_t n = contour.segments.size();
  const auto line = [&](std::size_t i) { return std::get_if<Line>(&contour.segments[i % n]); };
  std::vector<std::optional<Join>> join_at(contour.node_count());
  for (const Join& j : joins_of(contour)) join_at[j.node] = j;
  // Node k joins segment k − 1 to segment k; filleted only where the fillet bends the way its
  // neighbours do.
  std::vector<bool> kink(contour.node_count(), false);
  for (std::size_t k = 0; k < n; ++k) {
    const std::optional<Join>& j = join_at[k];
    if (!j || !small_kink(*j) || !line(k + n - 1) || !line(k)) continue;
    kink[k] = true;
    for (const int step : {-1, 1}) {
      const int other = neighbour_bend(contour, join_at, k, step);
      if (other != 0 && other != way(*j)) kink[k] = false;
    }
  }
  // A line with a kink at both ends gives each fillet half of it; else the whole.
  const auto most = [&](std::size_t i, std::size_t other_end) {
    const Line& l = *line(i);
    return norm(l.end() - l.start()) * (other_end < kink.size() && kink[other_end] ? 0.5 : 1.0);
  };
  std::vector<std::optional<Legs>> at(kink.size());
  bool any = false;
  for (std::size_t k = 0; k < n; ++k) {
    if (!kink[k]) continue;
    const std::size_t before = (k + n - 1) % n;
    at[k] = fillet_legs(*line(before), *line(k), most(before, before), most(k, contour.closed ? (k + 1) % n : k + 1),
                        allowance_units, integer_grid);
    any = any || at[k].has_value();
  }
  if (!any) return contour;

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

}  // namespace gf
