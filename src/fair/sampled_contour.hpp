// A contour as dense samples bucketed for distances to it, and the distances the fairing
// measures with them: between two outlines (two-sided Hausdorff), and what an outline leaves of
// the tolerance cubic by cubic.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "fair/outline_nodes.hpp"
#include "geom/contour.hpp"
#include "geom/polyline_distance.hpp"

namespace gf {

/// Points along a contour, at least one every 3 units and dense enough by each curve's turning
/// that chords keep within about a hundredth of a unit of it (two hundredths on unevenly
/// parametrised cubics), and for each the segment whose stretch of polyline (to the next point)
/// it starts.
struct ContourSamples {
  std::vector<Vec2> points;
  std::vector<std::size_t> segment_of;
};
ContourSamples contour_samples(const Contour& c);

/// A contour's samples, bucketed for distances to it.
struct SampledContour {
  ContourSamples samples;
  PolylineGrid grid;
  explicit SampledContour(const Contour& c) : samples(contour_samples(c)), grid(samples.points, 8.0) {}
  const std::vector<Vec2>& points() const { return samples.points; }
};

/// Two-sided Hausdorff distance between the samples; infinite where one of them has no points
/// and the other has (a contour faired to nothing).
double distance_between(const SampledContour& a, const SampledContour& b);

/// Whether distance_between(a, b) is at most `limit`: the same answer, sooner where it is not
/// (each direction stops at its first point past the limit).
bool within_distance(const SampledContour& a, const SampledContour& b, double limit);

/// What the outline leaves of the tolerance at each cubic (its own distance `by_segment`), less
/// `reserve`, with 5 % kept for sampling: what rounding, or the G3 cubics before it, may spend there.
std::vector<double> tolerance_left(std::span<const double> by_segment, double tolerance_units, double reserve);

/// The same for the outline `nodes` draws, its distances measured from the source here.
std::vector<double> tolerance_left_at(const std::vector<OutlineNode>& nodes, bool closed,
                                      const SampledContour& sampled_source, double tolerance_units, double reserve);

}  // namespace gf
