#include "fair/run_reference.hpp"

#include <algorithm>
#include <cmath>

#include "geom/curvature.hpp"

namespace gf {

namespace {

Vec2 cubic_tangent(const Cubic& c, double t) {
  if (t == 0.0) return *end_tangent(c, SegmentEnd::start);
  if (t == 1.0) return *end_tangent(c, SegmentEnd::end);
  const Vec2 d = derivative_at(c, t);
  const double n = norm(d);
  return n > 0.0 ? d / n : *end_tangent(c, t < 0.5 ? SegmentEnd::start : SegmentEnd::end);
}

}  // namespace

RunReference::RunReference(const SmoothRun& run, int samples_per_cubic) : cubics_(run.cubics), closed_(run.closed) {
  double s = 0.0, theta = 0.0;
  Vec2 last_tangent;
  for (std::size_t i = 0; i < cubics_.size(); ++i) {
    const Cubic& c = cubics_[i];
    for (int k = 0; k <= samples_per_cubic; ++k) {
      const double t = static_cast<double>(k) / samples_per_cubic;
      const Vec2 p = c.point_at(t), tangent = cubic_tangent(c, t);
      if (samples_.empty()) {
        theta = angle_of(tangent);
      } else {
        s += distance(samples_.back().point, p);
        theta += turning_angle(last_tangent, tangent);
      }
      last_tangent = tangent;
      samples_.push_back({s, p, theta, i, t});
    }
  }
  if (closed_) {  // close the loop: the seam's break and chord
    const Vec2 p = cubics_.front().p[0], tangent = cubic_tangent(cubics_.front(), 0.0);
    s += distance(samples_.back().point, p);
    theta += turning_angle(last_tangent, tangent);
    samples_.push_back({s, p, theta, 0, 0.0});
  }
  length_ = s;
}

double RunReference::wrap(double s) const {
  if (!closed_) return std::clamp(s, 0.0, length_);
  s = std::fmod(s, length_);
  return s < 0.0 ? s + length_ : s;
}

RunReference::Bracket RunReference::bracket(double s) const {
  const auto it = std::upper_bound(samples_.begin(), samples_.end(), s,
                                   [](double v, const ReferenceSample& r) { return v < r.s; });
  const std::size_t k = static_cast<std::size_t>(it - samples_.begin());
  const std::size_t i = std::min(k == 0 ? 0 : k - 1, samples_.size() - 2);
  const ReferenceSample &a = samples_[i], &b = samples_[i + 1];
  return {i, b.s > a.s ? (s - a.s) / (b.s - a.s) : 0.0};
}

Vec2 RunReference::point_at(double s) const {
  const auto [i, f] = bracket(wrap(s));
  const ReferenceSample &a = samples_[i], &b = samples_[i + 1];
  if (a.cubic == b.cubic && b.t > a.t) return cubics_[a.cubic].point_at(a.t + f * (b.t - a.t));
  return lerp(a.point, b.point, f);
}

Vec2 RunReference::tangent_at(double s) const { return direction_of(theta_at(s)); }

RunReference::Location RunReference::locate(double s) const {
  const auto [i, f] = bracket(wrap(s));
  const ReferenceSample &a = samples_[i], &b = samples_[i + 1];
  if (a.cubic == b.cubic && b.t > a.t) return {a.cubic, a.t + f * (b.t - a.t)};
  return f < 0.5 ? Location{a.cubic, a.t} : Location{b.cubic, b.t};
}

double RunReference::curvature_at(double s) const {
  const Location at = locate(s);
  const std::optional<double> k = curvature(derivatives_at(cubics_[at.cubic], at.t));
  return k && std::isfinite(*k) ? *k : 0.0;
}

double RunReference::theta_at(double s) const {
  double turns = 0.0;
  if (closed_) {
    turns = std::floor(s / length_);
    s -= turns * length_;
  } else {
    s = std::clamp(s, 0.0, length_);
  }
  const auto [i, f] = bracket(s);
  const ReferenceSample &a = samples_[i], &b = samples_[i + 1];
  return a.theta + f * (b.theta - a.theta) + turns * total_turning();
}

std::pair<double, double> RunReference::window_around(double s, double window) const {
  double lo = s - window / 2, hi = s + window / 2;
  if (!closed_) lo = std::max(lo, 0.0), hi = std::min(hi, length_);
  return {lo, hi};
}

double RunReference::mean_curvature(double s, double window) const {
  const auto [lo, hi] = window_around(s, window);
  return hi > lo ? (theta_at(hi) - theta_at(lo)) / (hi - lo) : 0.0;
}

Vec2 RunReference::mean_point(double s, double window) const {
  double half = window / 2;
  if (!closed_) half = std::min({half, s, length_ - s});
  if (!(half > 0.0)) return point_at(s);
  // Simpson's rule on 9 points.
  constexpr int n = 8;
  Vec2 sum{0.0, 0.0};
  for (int k = 0; k <= n; ++k) {
    const double w = (k == 0 || k == n) ? 1.0 : (k % 2 ? 4.0 : 2.0);
    sum = sum + point_at(s - half + 2.0 * half * k / n) * w;
  }
  return sum / (3.0 * n);
}

Vec2 RunReference::mean_tangent(double s, double window) const {
  const auto [lo, hi] = window_around(s, window);
  const Vec2 d = point_at(hi) - point_at(lo);
  const double n = norm(d);
  return n > 0.0 ? d / n : tangent_at(s);
}

std::vector<Vec2> RunReference::polyline(double s0, double s1) const {
  std::vector<Vec2> out{point_at(s0)};
  // The samples strictly between s0 and s1, across the seam if needed.
  const double base = closed_ ? std::floor(s0 / length_) * length_ : 0.0;
  for (double offset = base; offset < s1; offset += length_) {
    auto it = std::upper_bound(samples_.begin(), samples_.end(), s0 - offset,
                               [](double v, const ReferenceSample& r) { return v < r.s; });
    for (; it != samples_.end() && it->s + offset < s1; ++it) out.push_back(it->point);
    if (!closed_) break;
  }
  out.push_back(point_at(s1));
  return out;
}

std::vector<Cubic> RunReference::cubics_between(double s0, double s1) const {
  const auto [c0, t0] = locate(s0);
  const auto [c1, t1] = locate(s1);
  std::vector<Cubic> out;
  const std::size_t n = cubics_.size();
  for (std::size_t c = c0, guard = 0; guard <= n; c = (c + 1) % n, ++guard) {
    const double a = c == c0 ? t0 : 0.0;
    const double b = c == c1 && (guard > 0 || t1 >= t0) ? t1 : 1.0;
    if (b > a) out.push_back(cubics_[c].subsegment(a, b));
    if (c == c1 && (guard > 0 || t1 >= t0)) break;
  }
  return out;
}

}  // namespace gf
