#include "fair/outline_nodes.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numeric>

#include "geom/tangent_crossing.hpp"

namespace gf {

bool join_nearly_smooth_node(OutlineNode& node, double limit_rad, double most_move) {
  if (!node.in_handle || !node.out_handle) return false;
  const Vec2 in = node.point - *node.in_handle, out = *node.out_handle - node.point;
  const double a = norm(in), b = norm(out);
  if (a == 0.0 || b == 0.0) return false;
  if (!exactly_collinear(in, out)) {
    const double turn = std::abs(turning_angle(in, out));
    if (turn >= limit_rad || (4.0 / 9.0) * std::max(a, b) * 0.5 * turn > most_move) return false;
    const Vec2 along = in / a + out / b;
    const Vec2 unit = along / norm(along);
    node.in_handle = node.point - unit * a;
    node.out_handle = node.point + unit * b;
  }
  node.smooth = true;
  return true;
}

Cubic outline_cubic(const std::vector<OutlineNode>& nodes, std::size_t i) {
  const OutlineNode &a = nodes[i], &b = nodes[(i + 1) % nodes.size()];
  return {a.point, *a.out_handle, *b.in_handle, b.point};
}

Vec2 arriving_direction(const std::vector<OutlineNode>& nodes, std::size_t k) {
  const OutlineNode& q = nodes[k];
  return q.in_handle ? q.point - *q.in_handle : q.point - nodes[(k + nodes.size() - 1) % nodes.size()].point;
}

Vec2 leaving_direction(const std::vector<OutlineNode>& nodes, std::size_t k) {
  const OutlineNode& q = nodes[k];
  return q.out_handle ? *q.out_handle - q.point : nodes[(k + 1) % nodes.size()].point - q.point;
}

Contour to_contour(const std::vector<OutlineNode>& nodes, bool closed) {
  Contour c;
  c.closed = closed;
  const std::size_t n = nodes.size();
  for (std::size_t i = 0; i < n; ++i) {
    c.nodes.push_back(NodeFlags{false, nodes[i].smooth});
    if (!closed && i + 1 == n) break;
    const OutlineNode &a = nodes[i], &b = nodes[(i + 1) % n];
    if (a.out_handle && b.in_handle) c.segments.emplace_back(outline_cubic(nodes, i));
    else c.segments.emplace_back(Line{a.point, b.point});
  }
  return c;
}

double whole_steps(Vec2 from, Vec2 handle, Vec2 d, double sign) {
  return std::round(sign * dot(handle - from, d) / dot(d, d));
}

Vec2 stepped_handle(Vec2 node, Vec2 d, double sign, Vec2 from, Vec2 handle) {
  return node + d * (sign * std::max(1.0, whole_steps(from, handle, d, sign)));
}

std::size_t nearest_node(const std::vector<OutlineNode>& nodes, Vec2 p) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < nodes.size(); ++i)
    if (distance(nodes[i].point, p) < distance(nodes[best].point, p)) best = i;
  return best;
}

std::vector<Vec2> grid_directions(int longest) {
  std::vector<Vec2> out;
  const int reach = static_cast<int>(std::sqrt(double(longest)));
  for (int p = -reach; p <= reach; ++p)
    for (int q = -reach; q <= reach; ++q)
      if (p * p + q * q <= longest && is_primitive({double(p), double(q)})) out.push_back({double(p), double(q)});
  return out;
}

std::optional<Vec2> primitive_step(Vec2 along) {
  const long long g = std::gcd(std::llabs(std::llround(along.x)), std::llabs(std::llround(along.y)));
  if (g == 0) return std::nullopt;
  return along / static_cast<double>(g);
}

double node_curvature(const Cubic& c, SegmentEnd end) { return end_curvature(c, end).curvature.value_or(0.0); }

namespace {

// Nodes i and i + 1 replaced by `merged`; a closed contour's first node stays first.
void replace_pair(std::vector<OutlineNode>& nodes, std::size_t i, const OutlineNode& merged) {
  const std::size_t j = (i + 1) % nodes.size();
  const std::size_t keep = j == 0 ? j : i, drop = j == 0 ? i : j;
  nodes[keep] = merged;
  nodes.erase(nodes.begin() + static_cast<std::ptrdiff_t>(drop));
}

bool on_axis(const OutlineNode& n) { return n.grid_step && (n.grid_step->x == 0.0 || n.grid_step->y == 0.0); }

// Whether the grid can draw the cubic from a to b: not under `shortest`, nor, under
// flat_cubic_chord, bending less at both ends than the least curvature other than 0 whole
// steps give a cubic that short: κ = (2/3)·d/h² with the far handle d ≥ 1/|s| off the tangent
// for a grid direction s and the handle h whole steps, |s| ≤ h ≤ c for a chord c, so
// κ ≥ (2/3)·(1/c)/c² = 2/(3c³).
bool too_short_for_the_grid(const OutlineNode& a, const OutlineNode& b, double shortest) {
  const double chord = distance(a.point, b.point);
  if (chord < shortest) return true;
  if (chord >= flat_cubic_chord) return false;
  const Cubic c{a.point, *a.out_handle, *b.in_handle, b.point};
  const double least = 2.0 / (3.0 * chord * chord * chord);
  return std::abs(node_curvature(c, SegmentEnd::start)) < least && std::abs(node_curvature(c, SegmentEnd::end)) < least;
}

}  // namespace

void drop_empty_cubics(std::vector<OutlineNode>& nodes, bool closed) {
  for (std::size_t i = 0; nodes.size() > (closed ? 2u : 1u) && i < nodes.size();) {
    const std::size_t j = (i + 1) % nodes.size();
    if ((!closed && j == 0) || !nodes[i].out_handle || !nodes[j].in_handle) {
      ++i;
      continue;
    }
    const Vec2 p = nodes[i].point;
    if (nodes[j].point != p || *nodes[i].out_handle != p || *nodes[j].in_handle != p) {
      ++i;
      continue;
    }
    // Node i arrives as it did and leaves as node j does.
    OutlineNode merged = nodes[i];
    merged.out_handle = nodes[j].out_handle;
    merged.smooth = nodes[i].smooth && nodes[j].smooth;
    if (!merged.grid_step) merged.grid_step = nodes[j].grid_step;
    replace_pair(nodes, i, merged);
  }
}

void merge_tiny_cubics(std::vector<OutlineNode>& nodes, bool closed, double shortest) {
  for (std::size_t i = 0; nodes.size() > (closed ? 3u : 2u) && i < nodes.size();) {
    const std::size_t n = nodes.size(), j = (i + 1) % n;
    const bool interior = closed || (i > 0 && j + 1 < n && j != 0);
    const OutlineNode &a = nodes[i], &b = nodes[j];
    // A line's end (no handle on its side) is kept where it is; its tangent runs along the line.
    const bool a_ends_line = !a.in_handle, b_ends_line = !b.out_handle;
    if (!interior || !a.smooth || !b.smooth || !a.out_handle || !b.in_handle || (a_ends_line && b_ends_line) ||
        !too_short_for_the_grid(a, b, shortest)) {
      ++i;
      continue;
    }
    const double chord = distance(a.point, b.point);
    // Extrema on both axes: the curve turns a right angle within the chord, a corner on the
    // grid. Merged into one smooth node, the other's extremum fell inside the next cubic
    // (Because We Create's s: a brush hook's level foot and upright side 0.9 units apart). The
    // corner sits where their tangents cross, each handle where it was: both extrema stay on it.
    if (!a_ends_line && !b_ends_line && on_axis(a) && on_axis(b) && cross(*a.grid_step, *b.grid_step) != 0.0) {
      if (const std::optional<Vec2> x = tangent_crossing(a.point, a.point - *a.in_handle, b.point, *b.out_handle - b.point)) {
        replace_pair(nodes, i, OutlineNode{*x, a.in_handle, b.out_handle, false, std::nullopt});
        continue;
      }
    }
    const bool keep_first = a_ends_line || (!b_ends_line && (on_axis(a) || !on_axis(b)));
    const Vec2 tangent = keep_first ? a.point - (a_ends_line ? nodes[(i + n - 1) % n].point : *a.in_handle)
                                    : (b_ends_line ? nodes[(j + 1) % n].point : *b.out_handle) - b.point;
    if (norm(tangent) == 0.0) {
      ++i;
      continue;
    }
    const Vec2 u = tangent / norm(tangent);
    // An extremum dropped for a line's end must lie along the line: past a slanted line's end
    // the curve turns through the axis inside the merged cubic (DejaVu Sans's ☃, a line 5.7°
    // off the vertical: an x-extremum with no node).
    const OutlineNode& dropped = keep_first ? b : a;
    if ((a_ends_line || b_ends_line) && on_axis(dropped) && std::abs(cross(u, *dropped.grid_step)) > 1e-9) {
      ++i;
      continue;
    }
    OutlineNode merged = keep_first ? a : b;
    if (keep_first) merged.out_handle = a.point + u * (distance(*b.out_handle, b.point) + chord);
    else merged.in_handle = b.point - u * (distance(*a.in_handle, a.point) + chord);
    replace_pair(nodes, i, merged);
  }
}

std::optional<std::size_t> node_within(const std::vector<OutlineNode>& nodes, Vec2 p, double reach) {
  if (nodes.empty()) return std::nullopt;
  const std::size_t k = nearest_node(nodes, p);
  if (distance(nodes[k].point, p) > reach) return std::nullopt;
  return k;
}

}  // namespace gf
