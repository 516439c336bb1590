// A chain of cubics whose nodes and tangents are fixed, its handle lengths fitted to points
// under curvature continuity: the least-squares shape among the G2 chains through those nodes.
// With P1 = P0 + a·T0, P2 = P3 − b·T3, D = P3 − P0 and c = T0 × T3 (geom/g2_hermite.hpp),
//   κ0 = 2/3 · (T0 × D − b c) / a²,    κ3 = 2/3 · (D × T3 − a c) / b²,
// and a point at a fixed parameter is linear in (a, b); so each round is an equality-
// constrained linear least-squares problem (the points' offsets at their feet, the curvature
// equations linearised), and the rounds are sequential quadratic programming. The first rounds
// fit each point's whole offset: tangent distance alone, from chord-length feet, settled on a
// wrong G2 chain (a split cubic's halves came back 16 units off).
#pragma once

#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "geom/bezier.hpp"

namespace gf {

/// A cubic's fixed part: where it starts and ends and its unit tangents there (along travel).
struct CubicFrame {
  Vec2 start, start_tangent, end, end_tangent;

  Cubic with_handles(double a, double b) const { return {start, start + start_tangent * a, end - end_tangent * b, end}; }
  /// κ at the start for handle lengths (a, b): 2/3 · (T0 × D − b c) / a².
  double start_curvature(double a, double b) const {
    return (2.0 / 3.0) * (cross(start_tangent, end - start) - b * cross(start_tangent, end_tangent)) / (a * a);
  }
  /// κ at the end: 2/3 · (D × T3 − a c) / b².
  double end_curvature(double a, double b) const {
    return (2.0 / 3.0) * (cross(end - start, end_tangent) - a * cross(start_tangent, end_tangent)) / (b * b);
  }
};

/// The frame of a cubic whose handles do not lie on its ends; none where one does.
std::optional<CubicFrame> frame_of(const Cubic& c);

/// The cubics on `frames` (a chain: each frame ends where the next starts) nearest
/// `points[i]` (points cubic i should pass, in order, its ends included), with κ continuous
/// at every inner join to 1e-9 of the larger side (or of 1/the chain's chord sum), and meeting
/// `start`/`end` at the chain's ends where given. From the handle lengths `initial` (a, b per
/// frame). None where a handle would leave (0.001 chord, 1.5 chord] or the curvature
/// equations are not met after 40 rounds and a few least-norm Newton steps onto them.
std::optional<std::vector<Cubic>> fit_g2_handles(std::span<const CubicFrame> frames,
                                                 std::span<const std::vector<Vec2>> points,
                                                 std::span<const std::pair<double, double>> initial,
                                                 std::optional<double> start, std::optional<double> end);

}  // namespace gf
