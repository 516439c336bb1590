#include "fair/spurs.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <variant>

#include "geom/curvature.hpp"
#include "geom/polyline_distance.hpp"

namespace gf {

namespace {

constexpr double sample_spacing = 0.5;  // units between the samples that stand for the outline
constexpr int most_spurs = 8;           // per contour

struct Sample {
  std::size_t segment;
  double t;
  Vec2 point;
};

// The outline as points about sample_spacing apart, each segment from its start (t = 0).
std::vector<Sample> samples_of(const Contour& c) {
  std::vector<Sample> out;
  for (std::size_t i = 0; i < c.segments.size(); ++i) {
    const int count =
        std::clamp(static_cast<int>(std::ceil(control_polygon_length(c.segments[i]) / sample_spacing)), 1, 1024);
    for (int k = 0; k < count; ++k) {
      const double t = static_cast<double>(k) / count;
      out.push_back({i, t, point_at(c.segments[i], t)});
    }
  }
  return out;
}

struct Spur {
  std::size_t cusp;    ///< the node at the spur's foot
  bool after;          ///< the spur follows the cusp along the outline (else it precedes it)
  std::size_t segment; ///< where the outline returns to the cusp
  double t;
};

// The spur at the cusp at sample `at` (a node's) going `way` (+1 on along the outline, −1
// back), if there is one.
std::optional<Spur> spur_from(const std::vector<Sample>& samples, std::size_t at, int way, const SpurLimits& limits) {
  const std::size_t n = samples.size();
  const Vec2 cusp = samples[at].point;
  const auto index = [&](std::size_t steps) { return way > 0 ? (at + steps) % n : (at + n - steps % n) % n; };
  bool left = false;
  double along = 0.0;
  std::optional<std::size_t> back;
  for (std::size_t k = 1; k < n; ++k) {
    const std::size_t s = index(k);
    along += distance(samples[index(k - 1)].point, samples[s].point);
    if (along > limits.max_length_units) return std::nullopt;
    const double off = distance(samples[s].point, cusp);
    if (off > limits.width_units) left = true;
    else if (left) {
      // The nearest approach while within the width: where the outline comes back.
      back = s;
      for (std::size_t j = k + 1; j < n && distance(samples[index(j)].point, cusp) <= distance(samples[*back].point, cusp); ++j)
        back = index(j);
      break;
    }
  }
  if (!back) return std::nullopt;
  // Every point of the spur within the width of the outline outside it: the samples from the
  // cusp to the return (along the outline, the way the spur runs), against the rest in order.
  const std::size_t first = way > 0 ? at : *back, last = way > 0 ? *back : at;
  std::vector<Vec2> spur, rest;
  for (std::size_t s = first;; s = (s + 1) % n) {
    spur.push_back(samples[s].point);
    if (s == last) break;
  }
  for (std::size_t s = (last + 1) % n; s != first; s = (s + 1) % n) rest.push_back(samples[s].point);
  if (rest.size() < 2 || directed_hausdorff(spur, rest, limits.width_units) > limits.width_units) return std::nullopt;
  return Spur{samples[at].segment, way > 0, samples[*back].segment, samples[*back].t};
}

// The contour without the spur: the segments outside it, the one where the outline returns
// cut there and joined to the cusp.
Contour without(const Contour& c, const Spur& spur, double& moved) {
  const std::size_t n = c.segments.size();
  const Vec2 cusp = c.node_point(spur.cusp);
  Contour out;
  out.closed = true;
  // The segments wholly inside the spur go: from the cusp on to the one where the outline
  // returns (after), or from after that one on to the cusp (before).
  std::vector<bool> inside(n, false);
  for (std::size_t k = spur.after ? spur.cusp : (spur.segment + 1) % n; k != (spur.after ? spur.segment : spur.cusp);
       k = (k + 1) % n)
    inside[k] = true;
  for (std::size_t k = 0; k < n; ++k) {
    if (k == spur.segment) {
      // The part outside the spur (a line or a cubic: with_cubics made every quadratic a cubic).
      const Segment kept = std::visit(
          [&](const auto& b) -> Segment { return spur.after ? b.subsegment(spur.t, 1.0) : b.subsegment(0.0, spur.t); },
          c.segments[k]);
      const SegmentEnd joined = spur.after ? SegmentEnd::start : SegmentEnd::end;
      const Vec2 v = cusp - (spur.after ? start_point(kept) : end_point(kept));
      moved = std::max(moved, norm(v));
      out.segments.push_back(with_end_moved(kept, joined, v));
      out.nodes.push_back(spur.after ? NodeFlags{} : c.nodes[k]);
    } else if (!inside[k]) {
      out.segments.push_back(c.segments[k]);
      out.nodes.push_back(!spur.after && k == spur.cusp ? NodeFlags{} : c.nodes[k]);
    }
  }
  return out;
}

}  // namespace

MovedContour cut_spurs(const Contour& contour, const SpurLimits& limits) {
  MovedContour out{contour, 0.0, 0};
  if (!contour.closed || contour.segments.size() < 2) return out;
  Contour c = with_cubics(contour);
  for (int round = 0; round < most_spurs; ++round) {
    const std::vector<Sample> samples = samples_of(c);
    const std::size_t n = c.segments.size();
    std::optional<Spur> found;
    for (std::size_t at = 0; at < samples.size() && !found; ++at) {
      if (samples[at].t != 0.0) continue;
      const std::size_t node = samples[at].segment;
      const std::optional<Vec2> in = end_tangent(c.segments[(node + n - 1) % n], SegmentEnd::end);
      const std::optional<Vec2> leave = end_tangent(c.segments[node], SegmentEnd::start);
      if (!in || !leave || std::abs(turning_angle(*in, *leave)) < radians(limits.min_turn_deg)) continue;
      for (const int way : {1, -1})
        if (!found) found = spur_from(samples, at, way, limits);
    }
    if (!found) break;
    c = without(c, *found, out.moved);
    ++out.changes;
  }
  if (out.changes > 0) out.contour = std::move(c);
  return out;
}

}  // namespace gf
