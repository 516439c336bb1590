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

/// What a fit may move besides the handle lengths.
struct G2FitFreedom {
  /// Per node (node i starts frame i; an open chain's last node ends the last frame): whether
  /// it may slide along its tangent, by at most `slide_reach` units. A horizontal or vertical
  /// extremum so stays one. The points at a sliding node (its cubics' first or last) are not
  /// fitted: the node goes where the others put it.
  std::vector<bool> slides;
  double slide_reach = 0.0;
  /// Whether the last frame ends where the first starts, κ continuous there too (`start` and
  /// `end` then bind nothing).
  bool closed = false;
  /// Where above 0, each round moves no unknown by more than this share of the mean chord,
  /// over up to 200 rounds: with its nodes sliding a fit has far minima, and a full step can
  /// land in one (EB Garamond's inner O: quarters with one handle a tenth of the other, 4 units
  /// from the source, against 0.45 so).
  double step_share = 0.0;
};

/// The frame of a cubic whose handles do not lie on its ends; none where one does.
std::optional<CubicFrame> frame_of(const Cubic& c);

/// The cubics on `frames` (a chain: each frame ends where the next starts) nearest
/// `points[i]` (points cubic i should pass, in order, its ends included), with κ continuous
/// at every inner join to 1e-9 of the larger side (or of 1/the chain's chord sum), and meeting
/// `start`/`end` at the chain's ends where given; its nodes slid as `freedom` lets them (a slide
/// enters each point's offset linearly, and the curvature equations as a handle length does).
/// From the handle lengths `initial` (a, b per frame). None where a handle would leave
/// (0.001 chord, 1.5 chord] or a slide its reach, or the curvature equations are not met after
/// the rounds and a few least-norm Newton steps onto them.
std::optional<std::vector<Cubic>> fit_g2_handles(std::span<const CubicFrame> frames,
                                                 std::span<const std::vector<Vec2>> points,
                                                 std::span<const std::pair<double, double>> initial,
                                                 std::optional<double> start, std::optional<double> end,
                                                 const G2FitFreedom& freedom = {});

}  // namespace gf
