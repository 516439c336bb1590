// A smooth run of the source sampled along its length: the reference the fairing measures
// itself against. Positions are exact points of the source cubics; s is the arc length along
// the run and θ the tangent angle, unwrapped, so that θ(s) carries the run's whole turning
// (the small breaks at joins that are not corners included).
#pragma once

#include <span>
#include <utility>
#include <vector>

#include "aesthetic/log_aesthetic_segment.hpp"
#include "fair/contour_plan.hpp"

namespace gf {

struct ReferenceSample {
  double s;
  Vec2 point;
  double theta;
  std::size_t cubic;  ///< which source cubic, and where on it
  double t;
};

class RunReference {
 public:
  explicit RunReference(const SmoothRun& run, int samples_per_cubic = 48);

  bool closed() const { return closed_; }
  double length() const { return length_; }
  /// θ(end) − θ(start) of an open run; 2π × winding of a closed one.
  double total_turning() const { return samples_.back().theta - samples_.front().theta; }
  std::span<const ReferenceSample> samples() const { return samples_; }

  /// The exact source point at arc length s (wrapped for a closed run).
  Vec2 point_at(double s) const;
  /// The unit tangent at s (from θ).
  Vec2 tangent_at(double s) const;
  /// The exact curvature of the source cubic at s (0 where a retracted handle leaves it unbounded).
  double curvature_at(double s) const;
  /// Point, tangent and κ at s as a curve point (the source's dκ/ds is not reported: nullopt).
  LacPoint frame_at(double s) const { return {point_at(s), tangent_at(s), curvature_at(s), std::nullopt}; }
  /// θ at s, continued across the seam of a closed run (θ(s + L) = θ(s) + total turning).
  double theta_at(double s) const;
  /// The mean curvature over [s − w/2, s + w/2]: (θ(s + w/2) − θ(s − w/2)) / w, the window
  /// clipped to an open run's ends.
  double mean_curvature(double s, double window) const;
  /// The mean position over the same window (shrunk to stay inside an open run, so the ends
  /// stay exact): the point with wobbles averaged out.
  Vec2 mean_point(double s, double window) const;
  /// The direction of the chord over the same window: the tangent with wobbles averaged out.
  Vec2 mean_tangent(double s, double window) const;
  /// The sample polyline over [s0, s1] (s1 may pass the seam of a closed run), ends included.
  std::vector<Vec2> polyline(double s0, double s1) const;
  /// The source between s0 and s1 as cubics (for the LCG estimate).
  std::vector<Cubic> cubics_between(double s0, double s1) const;

 private:
  /// The samples i, i + 1 around s ∈ [0, L] and where s lies between them (0 … 1).
  struct Bracket {
    std::size_t i;
    double f;
  };
  Bracket bracket(double s) const;
  /// The source cubic and its parameter at s (the nearer sample's where s falls between two cubics).
  struct Location {
    std::size_t cubic;
    double t;
  };
  Location locate(double s) const;
  double wrap(double s) const;
  /// [s − w/2, s + w/2], clipped to an open run's ends.
  std::pair<double, double> window_around(double s, double window) const;
  std::vector<Cubic> cubics_;
  std::vector<ReferenceSample> samples_;
  double length_ = 0.0;
  bool closed_ = false;
};

}  // namespace gf
