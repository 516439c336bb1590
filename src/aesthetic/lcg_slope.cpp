#include "aesthetic/lcg_slope.hpp"

#include <algorithm>
#include <cmath>
#include <variant>
#include <vector>

#include "geom/curvature.hpp"

namespace gf {

namespace {

struct Place {
  std::size_t segment;
  double t;
};

// Places uniform in arc length, from a fine table of cumulative length (trapezoid on |C'|).
std::vector<Place> uniform_in_arc_length(std::span<const Segment> curve, int count) {
  constexpr int steps = 256;
  std::vector<Place> table;
  std::vector<double> length;
  table.reserve(curve.size() * (steps + 1));
  length.reserve(curve.size() * (steps + 1));
  double s = 0.0;
  for (std::size_t i = 0; i < curve.size(); ++i) {
    // |C'(t)| from the hodograph, made once per segment (the whole derivatives at 257 places
    // per segment were most of the LCG estimate's time).
    std::visit(
        [&](const auto& b) {
          const auto h = b.hodograph();
          double previous = norm(h.point_at(0.0));
          for (int k = 0; k <= steps; ++k) {
            const double t = double(k) / steps;
            const double speed = norm(h.point_at(t));
            if (k > 0) s += 0.5 * (previous + speed) / steps;
            previous = speed;
            table.push_back({i, t});
            length.push_back(s);
          }
        },
        curve[i]);
  }
  std::vector<Place> out;
  if (s == 0.0) return out;
  std::size_t j = 0;
  for (int k = 0; k < count; ++k) {
    const double target = s * (k + 0.5) / count;  // midpoints: the ends themselves are trimmed anyway
    while (j + 1 < length.size() && length[j + 1] < target) ++j;
    const double span = length[j + 1] - length[j];
    const double f = span > 0.0 ? (target - length[j]) / span : 0.0;
    const Place a = table[j], b = table[j + 1];
    out.push_back(a.segment == b.segment ? Place{a.segment, a.t + f * (b.t - a.t)} : b);
  }
  return out;
}

}  // namespace

LcgSlope estimate_lcg_slope(std::span<const Segment> curve, const LcgOptions& options) {
  LcgSlope result;
  struct Sample {
    double x, y;
  };
  std::vector<Sample> samples;
  double k_min = INFINITY, k_max = 0.0;
  int rising = 0, falling = 0;
  for (const Place& p : uniform_in_arc_length(curve, options.samples)) {
    const Derivatives d = derivatives_at(curve[p.segment], p.t);
    const std::optional<double> k = curvature(d), ks = curvature_derivative(d);
    if (!k || !ks || *k == 0.0) continue;
    k_min = std::min(k_min, std::abs(*k));
    k_max = std::max(k_max, std::abs(*k));
    if (*ks == 0.0) continue;
    // Along s, |κ| must change one way only for the LCG to exist.
    ((*k > 0) == (*ks > 0) ? rising : falling)++;
    samples.push_back({-std::log(std::abs(*k)), std::log(std::abs(*k / *ks))});
  }
  if (k_max > 0.0 && k_max / k_min < options.arc_curvature_ratio) {
    result.kind = LcgSlope::Kind::arc;
    return result;
  }
  if (samples.size() < 8 || std::min(rising, falling) > static_cast<int>(0.1 * (rising + falling))) return result;

  const auto [lo, hi] = std::minmax_element(samples.begin(), samples.end(), [](Sample a, Sample b) { return a.x < b.x; });
  const double x0 = lo->x + options.trim_fraction * (hi->x - lo->x);
  const double x1 = hi->x - options.trim_fraction * (hi->x - lo->x);
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (const Sample& s : samples) {
    if (s.x < x0 || s.x > x1) continue;
    n += 1, sx += s.x, sy += s.y, sxx += s.x * s.x, sxy += s.x * s.y;
  }
  const double denominator = n * sxx - sx * sx;
  if (n < 8 || denominator <= 0.0) return result;
  result.alpha = (n * sxy - sx * sy) / denominator;
  result.intercept = (sy - result.alpha * sx) / n;
  double sum = 0;
  for (const Sample& s : samples)
    if (s.x >= x0 && s.x <= x1) sum += std::pow(s.y - result.alpha * s.x - result.intercept, 2);
  result.rms_residual = std::sqrt(sum / n);
  result.samples_used = static_cast<int>(n);
  result.kind = LcgSlope::Kind::slope;
  return result;
}

}  // namespace gf
