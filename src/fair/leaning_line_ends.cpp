#include "fair/leaning_line_ends.hpp"

#include <algorithm>
#include <cmath>

#include "fair/curve_line_joins.hpp"
#include "geom/outline_move.hpp"

namespace gf {

namespace {

constexpr double sample_spacing = 1.0;  // units, at most, between the points the move is measured on
// Units, the shortest first handle m of a fillet from an extremum: on the grid it gives the
// extremum κ = (2/3)·d/m² for whole d and m, and below this a unit of m changes κ by more than
// a quarter (Comic Neue's d: 1.5-unit ramps of κ·UPM 19 asked for m = 5.6).
constexpr double shortest_extremum_handle = 8.0;

// The unit axis direction nearest the unit vector d.
Vec2 nearest_axis(Vec2 d) {
  return std::abs(d.x) >= std::abs(d.y) ? Vec2{d.x > 0.0 ? 1.0 : -1.0, 0.0} : Vec2{0.0, d.y > 0.0 ? 1.0 : -1.0};
}

// A line leaning between the limits' angles off its nearest axis.
struct Lean {
  Vec2 direction;  ///< unit, from the join to the line's far end
  Vec2 axis;       ///< the axis nearest it, the same way
  double angle;    ///< radians between them
};

// The line from the join j to `far` as it leans; none where it has no length or leans outside
// the limits.
std::optional<Lean> leaning(Vec2 j, Vec2 far, const LeaningLineLimits& limits) {
  const double length = distance(j, far);
  if (!(length > 0.0)) return std::nullopt;
  const Vec2 t = (far - j) / length, axis = nearest_axis(t);
  const double angle = std::atan2(std::abs(cross(axis, t)), dot(axis, t));
  if (angle < radians(limits.min_lean_deg) || angle > radians(limits.max_lean_deg)) return std::nullopt;
  return Lean{t, axis, angle};
}

// The join of `curve` (ending at the join) and the line from there to `far`, rebuilt as the
// curve turned onto the axis, the fillet and the line's new start; none where the limits say no.
struct Filleted {
  Cubic curve, fillet;
  Vec2 axis;  ///< the curve's new direction at the join
};
std::optional<Filleted> fillet_join(const Cubic& curve, Vec2 far, const LeaningLineLimits& limits) {
  const Vec2 j = curve.p[3];
  const std::optional<Lean> lean = leaning(j, far, limits);
  if (!lean) return std::nullopt;
  const Vec2 axis = lean->axis;
  const double handle = distance(curve.p[2], j), step = shortest_line_step(j, far);
  if (!(handle > 0.0) || step <= handle || distance(j, far) < 3.0 * step) return std::nullopt;
  // From the axis onto a line leaning the other way from the curve's bend is an inflection
  // (where the curve's handle is too short for any grid direction on its own side).
  if (cross(axis, lean->direction) * end_bend(curve) <= 0.0) return std::nullopt;
  // The axis leg: half a step, at most as long as keeps the vertex within the move of the line.
  const double m = std::min(0.5 * step, limits.max_move_units / std::sin(lean->angle));
  if (m < 1.0) return std::nullopt;
  const Vec2 v = j + axis * m;
  const Vec2 q = v + (far - v) / norm(far - v) * step;
  Filleted out;
  out.axis = axis;
  out.curve = curve;
  out.curve.p[2] = j - axis * handle;
  out.curve.p[1] = j + axis * dot(curve.p[1] - j, axis);
  out.fillet = Cubic{{j, v, v, q}};
  // From the curve's start to the line's far end.
  if (outline_move({curve, Line{{j, far}}}, {out.curve, out.fillet, Line{{q, far}}}, sample_spacing,
                   limits.max_move_units) > limits.max_move_units)
    return std::nullopt;
  return out;
}

// The join of `ramp` (from a smooth H/V extremum N to the join, its curvature running down to
// 0 there) and the line from there to `far`, where the ramp stays within half a unit of N's axis
// line: the grid lays such a ramp flat against the curvature the extremum carries, a jump
// (Liberation Serif 2.1's D: 9 units from the bowl's foot to a line 0.48° off the level;
// Pagella's F). So the fillet starts at N itself and takes the ramp's place: (N, V, P2, Q) with
// V = N + m·axis and P2, Q on the line from V to `far`, a step of it apart, so κ = 0 at Q and,
// at N, κ = (2/3)·cross(axis, P2 − V)/m² (a cubic's curvature at its start), the ramp's own:
// m = √((2/3)·step·sin(lean)/|κ_N|), then |P2 − V| solved for that κ exactly. None where the
// limits say no, the ramp bends against the line's lean, N's tangent leaves the axis or m is
// under shortest_extremum_handle.
std::optional<Cubic> fillet_from_extremum(const Cubic& ramp, Vec2 far, const LeaningLineLimits& limits) {
  const Vec2 n = ramp.p[0], j = ramp.p[3], leaving = ramp.p[1] - n;
  const std::optional<Lean> lean = leaning(j, far, limits);
  if (!lean || !(norm(leaving) > 0.0)) return std::nullopt;
  const Vec2 axis = lean->axis;
  if (dot(axis, leaving) <= 0.0 || std::abs(cross(axis, leaving)) > 1e-9 * norm(leaving)) return std::nullopt;
  for (const Vec2 p : ramp.p)
    if (std::abs(cross(axis, p - n)) >= 0.5) return std::nullopt;
  const double kappa = node_curvature(ramp, SegmentEnd::start), side = cross(axis, lean->direction);
  if (kappa * side <= 0.0) return std::nullopt;
  const double step = shortest_line_step(j, far);
  const double m = std::sqrt(2.0 / 3.0 * step * std::abs(side) / std::abs(kappa));
  if (!(m >= shortest_extremum_handle)) return std::nullopt;
  const Vec2 v = n + axis * m;
  const Vec2 along = (far - v) / norm(far - v);
  if (cross(axis, along) * side <= 0.0) return std::nullopt;
  const double w = 1.5 * std::abs(kappa) * m * m / std::abs(cross(axis, along));
  const Vec2 p2 = v + along * w, q = p2 + along * step;
  if (distance(q, far) < step || dot(q - v, far - v) <= 0.0) return std::nullopt;
  const Cubic fillet{{n, v, p2, q}};
  if (outline_move({ramp, Line{{j, far}}}, {fillet, Line{{q, far}}}, sample_spacing, limits.max_move_units) >
      limits.max_move_units)
    return std::nullopt;
  return fillet;
}

}  // namespace

int fillet_leaning_line_ends(std::vector<OutlineNode>& nodes, bool closed, const LeaningLineLimits& limits) {
  int filleted = 0;
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    const std::optional<CurveLineJoin> join = curve_line_join(nodes, closed, k);
    if (!join) continue;
    const std::size_t n = nodes.size(), prev = (k + n - 1) % n, next = (k + 1) % n;
    OutlineNode& node = nodes[k];
    const bool arrives = join->arrives;  // a cubic arrives, the line leaves
    const Cubic& cubic = join->curve;
    if (cubic.p[1] == cubic.p[2]) continue;  // a fillet already (both handles on its vertex)
    const Vec2 far = nodes[join->far].point;
    // A ramp from a smooth extremum: the fillet from the extremum, in the ramp's place.
    const OutlineNode& start = nodes[arrives ? prev : next];
    if (start.smooth && (arrives ? start.in_handle : start.out_handle))
      if (const std::optional<Cubic> f = fillet_from_extremum(cubic, far, limits)) {
        const Cubic fillet = arrives ? *f : f->reversed();
        if (arrives) {
          *nodes[prev].out_handle = fillet.p[1];
          node.in_handle = fillet.p[2];
        } else {
          *nodes[next].in_handle = fillet.p[2];
          node.out_handle = fillet.p[1];
        }
        node.point = arrives ? fillet.p[3] : fillet.p[0];
        node.grid_step.reset();
        ++filleted;
        continue;
      }
    const std::optional<Filleted> f = fillet_join(cubic, far, limits);
    if (!f) continue;
    const Cubic curve = arrives ? f->curve : f->curve.reversed();
    const Cubic fillet = arrives ? f->fillet : f->fillet.reversed();
    OutlineNode q;
    q.smooth = true;
    if (arrives) {
      *nodes[prev].out_handle = curve.p[1];
      node.in_handle = curve.p[2];
      node.out_handle = fillet.p[1];
      node.grid_step = f->axis;
      q.point = fillet.p[3], q.in_handle = fillet.p[2];
      nodes.insert(nodes.begin() + static_cast<std::ptrdiff_t>(k + 1), q);
      ++k;  // past the fillet's end
    } else {
      *nodes[next].in_handle = curve.p[2];
      node.out_handle = curve.p[1];
      node.in_handle = fillet.p[2];
      node.grid_step = -f->axis;
      q.point = fillet.p[0], q.out_handle = fillet.p[1];
      // Before the join; after the last node where the join is the first (the contour keeps
      // its start).
      if (k == 0) {
        nodes.push_back(q);
      } else {
        nodes.insert(nodes.begin() + static_cast<std::ptrdiff_t>(k), q);
        ++k;  // the join moved up one
      }
    }
    ++filleted;
  }
  return filleted;
}

}  // namespace gf
