// Starting tangents for the G2 solve. The junction tangents are chosen so that every segment
// turns about as much at one end as at the other (least squares of φ_i + φ_{i+1} − 2c_i, c_i the
// chord direction of segment i, with a light pull towards the bisector of the chords at each
// junction). A symmetric segment is a circular arc, which every α can draw (lac-math.md §2.2),
// so the solve starts inside the feasible region even where the turning per junction is
// uneven, as on the nearly straight stretches of a handwritten stroke.
#pragma once

#include <optional>
#include <vector>

#include "geom/vec2.hpp"

namespace gf {

/// Angles (radians) for `points`; an open chain's end tangents are given. A segment that ends
/// in κ = 0 is aimed at twice the angle at its other end instead (a clothoid from κ = 0 turns
/// its chord by a third of its turning, lac-math.md §3.2 needs less than half).
std::vector<double> balanced_tangents(const std::vector<Vec2>& points, bool closed, std::optional<double> start_angle,
                                      std::optional<double> end_angle, bool zero_curvature_start = false,
                                      bool zero_curvature_end = false);

/// Turns each free junction's angle into the wedge between its two chords, a tenth of the
/// wedge in from either side, where the chords turn `way` (the sign of the chain's turning)
/// there. A segment bends one way only where its end tangents lie on opposite sides of its
/// chord: a junction outside its wedge starts one of its segments bending both ways, which no
/// log-aesthetic segment can (of dkg's G2 solves that failed, 867 of 958 started so). An open
/// chain's end junctions are given, and so is the free neighbour of a κ = 0 end (aimed).
void keep_tangents_between_chords(const std::vector<Vec2>& points, bool closed, double way,
                                  std::vector<double>& angles, bool zero_curvature_start = false,
                                  bool zero_curvature_end = false);

}  // namespace gf
