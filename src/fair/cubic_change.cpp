#include "fair/cubic_change.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <span>
#include <vector>

#include "geom/arc_length.hpp"
#include "geom/critical_points.hpp"
#include "geom/curvature.hpp"
#include "geom/polyline_distance.hpp"
#include "geom/turning.hpp"

namespace gf {

namespace {

constexpr int moved_samples = 24;  // points per cubic where a move past its control points' is measured

std::array<Vec2, moved_samples + 1> samples_of(const Cubic& c) {
  std::array<Vec2, moved_samples + 1> out;
  for (int k = 0; k <= moved_samples; ++k) out[k] = c.point_at(double(k) / moved_samples);
  return out;
}

}  // namespace

SampledCubic::SampledCubic(const Cubic& c) : cubic(c) {
  const auto samples = samples_of(c);
  points = BoxedPolyline(std::vector<Vec2>(samples.begin(), samples.end()));
}

double moved_distance(const Cubic& a, const SampledCubic& b, double within) {
  double d = 0.0;
  for (int k = 0; k < 4; ++k) d = std::max(d, distance(a.p[k], b.cubic.p[k]));
  if (d <= within) return d;
  // The middle, where a far move shows most, first; most candidates past `within` are past
  // there, and a's other points are not needed.
  const Vec2 middle_point = a.point_at(0.5);
  const double middle = directed_hausdorff(std::span<const Vec2>(&middle_point, 1), b.points,
                                          std::numeric_limits<double>::infinity(), moved_samples / 2);
  if (middle > within) return std::min(d, middle);
  const auto pa = samples_of(a);
  const double there = directed_hausdorff(pa, b.points, within);
  return std::min(d, there > within ? there : std::max(there, directed_hausdorff(b.points.points(), pa, within)));
}

namespace {

// Whether x′ (or y′) keeps one sign inside (0, 1): its Bernstein coefficients, 3·(P1 − P0),
// 3·(P2 − P1) and 3·(P3 − P2), none of the nonzero ones of the other sign. A zero one leaves
// the sum of the others, one-signed inside; its roots lie at the ends, which
// inner_axis_extrema does not count.
bool monotone(double a, double b, double c) {
  return (a >= 0.0 && b >= 0.0 && c >= 0.0) || (a <= 0.0 && b <= 0.0 && c <= 0.0);
}

}  // namespace

std::vector<AxisExtremum> axis_extrema_inside(const Cubic& c, double end_share) {
  // Most cubics of an outline run monotone in x and y between nodes at their extrema: no
  // roots to isolate.
  const Vec2 d0 = c.p[1] - c.p[0], d1 = c.p[2] - c.p[1], d2 = c.p[3] - c.p[2];
  if (monotone(d0.x, d1.x, d2.x) && monotone(d0.y, d1.y, d2.y)) return {};
  // By arc length, not t: a long handle crowds the first hundredth of t into a few units.
  const Segment whole(c);
  std::optional<double> length;  // only for a cubic with an extremum inside (0, 1)
  std::vector<AxisExtremum> out;
  for (const AxisExtremum& e : axis_extrema(c)) {
    if (!length) length = arc_length_estimate(whole);
    const double before = arc_length_estimate(whole, 0.0, e.t);
    if (before > end_share * *length && *length - before > end_share * *length) out.push_back(e);
  }
  return out;
}

InnerAxisExtrema inner_axis_extrema_of(const Cubic& c) {
  InnerAxisExtrema out;
  for (const AxisExtremum& e : axis_extrema_inside(c, 0.01)) {
    ++out.all;
    const Vec2 at = c.point_at(e.t);
    out.off_node += std::min(distance(at, c.p[0]), distance(at, c.p[3])) > 0.5;
  }
  return out;
}

int inner_axis_extrema(const Cubic& c) { return inner_axis_extrema_of(c).all; }

double overreach_length(const Cubic& c) {
  const double reach = 2.0 * distance(c.p[0], c.p[3]) + 2.0;
  return std::max({0.0, distance(c.p[0], c.p[1]) - reach, distance(c.p[3], c.p[2]) - reach});
}

bool crowds_a_node(const Cubic& c) {
  constexpr double shortest_handle_share = 0.03;
  return std::min(distance(c.p[0], c.p[1]), distance(c.p[2], c.p[3])) < shortest_handle_share * distance(c.p[0], c.p[3]);
}

double cubic_turning(const Cubic& c) {
  const std::optional<Vec2> start = end_tangent(c, SegmentEnd::start), end = end_tangent(c, SegmentEnd::end);
  if (!start || !end) return 0.0;
  std::array<Vec2, 25> pts;
  for (std::size_t k = 0; k < pts.size(); ++k) pts[k] = c.point_at(static_cast<double>(k) / 24.0);
  return absolute_turning(*start, pts, *end);
}

CurvatureShape curvature_shape(const Cubic& c, double hysteresis) {
  CurvatureShape shape;
  double previous = 0.0, last_signed = 0.0;
  TurnCounter whole;
  const CurvatureAlong along(c);
  for (int k = 0; k <= 32; ++k) {
    const double kappa = along.at(k / 32.0).value_or(0.0);
    whole.add(kappa, hysteresis);
    if (k <= 16) shape.head[static_cast<std::size_t>(k)] = kappa;
    if (k >= 16) shape.tail.add(kappa, hysteresis);
    if (k % 2 != 0) continue;
    if (k > 0) shape.variation += std::abs(kappa - previous);
    shape.largest = std::max(shape.largest, std::abs(kappa));
    previous = kappa;
    if (std::abs(kappa) < 1e-12) continue;
    if (shape.first_sign == 0) shape.first_sign = kappa > 0.0 ? 1 : -1;
    shape.sign_changes += last_signed * kappa < 0.0;
    last_signed = kappa;
  }
  shape.turns = whole.turns;
  if (last_signed != 0.0) shape.last_sign = last_signed > 0.0 ? 1 : -1;
  if (shape.sign_changes == 0) shape.bend = shape.last_sign;
  return shape;
}

}  // namespace gf
