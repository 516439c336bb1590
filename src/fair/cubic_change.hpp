// How a cubic of the outline changed from the one it replaces: how far it moved, and what its
// curvature does inside (sign changes, variation, extrema), so that rounding and G3 can move
// handles without adding a wobble, an inflection or an extremum the faired outline lacks.
#pragma once

#include <array>
#include <vector>

#include "geom/bezier.hpp"
#include "geom/critical_points.hpp"
#include "geom/polyline_distance.hpp"

namespace gf {

/// A cubic with its points at t = k/24 (k = 0..24), sampled once for measuring many candidates
/// against it (moved_distance).
struct SampledCubic {
  Cubic cubic;
  BoxedPolyline points;
  SampledCubic() = default;
  explicit SampledCubic(const Cubic& c);
};

/// How far cubic a moved from cubic b: the largest move of a control point (a bound on the
/// distance between the two curves, by the convex hull of their difference) when that is
/// within `within`, else the two-sided distance between the curves themselves, which a handle
/// slid along its own tangent moves far less than it moves the control point. Past `within`,
/// only that it is past.
double moved_distance(const Cubic& a, const SampledCubic& b, double within);

/// A cubic's horizontal and vertical extrema farther along it from both ends than `end_share`
/// of its arc length, ascending in t.
std::vector<AxisExtremum> axis_extrema_inside(const Cubic& c, double end_share);

/// A cubic's horizontal and vertical extrema away from its ends: `all` those more than 1 % of
/// its arc length from both (nearer, they sit on the node); `off_node` those of them also more
/// than half a unit from both, where the check finds no node for them. Rounding cannot keep
/// an extremum within half a unit of its node, but need not carry it farther.
struct InnerAxisExtrema {
  int all = 0;
  int off_node = 0;
};
InnerAxisExtrema inner_axis_extrema_of(const Cubic& c);

/// inner_axis_extrema_of(c).all.
int inner_axis_extrema(const Cubic& c);

/// How far (units) the longer handle reaches beyond twice the chord and two units, 0 when
/// neither does: a short cubic bent back on itself by a long grid step (a fair cubic's handles
/// stay within its chord unless it turns through more than 180°).
double overreach_length(const Cubic& c);

/// Whether a handle is shorter than 3 % of the chord: it crowds the cubic's turn into its node,
/// where whole grid steps cannot hold it (the writeback takes no such cubic; a corner's handle of
/// 0.5 units on a 173-unit stroke rounded onto a 2-unit step back along the line before the
/// corner, a cusp of κ·UPM 19,800: Steve Hand's A).
bool crowds_a_node(const Cubic& c);

/// How far a cubic turns, every bend counted by its size (geom/turning, at 24ths of its
/// parameter between its end tangents): a loop or a cusp turns a half turn or more beyond its
/// end tangents' angle.
double cubic_turning(const Cubic& c);

/// Counts the turns (extrema) of κ along samples, as the check counts them: a rise or fall
/// counts once it exceeds the hysteresis from the last extreme value, so sampling noise on a
/// flat stretch is not a turn.
struct TurnCounter {
  int direction = 0;
  double anchor = 0.0;
  bool started = false;
  int turns = 0;
  void add(double kappa, double hysteresis) {
    if (!started) {
      started = true, anchor = kappa;
    } else if (direction >= 0 && kappa < anchor - hysteresis) {
      turns += direction > 0, direction = -1, anchor = kappa;
    } else if (direction <= 0 && kappa > anchor + hysteresis) {
      turns += direction < 0, direction = 1, anchor = kappa;
    } else if (direction * (kappa - anchor) > 0.0) {
      anchor = kappa;
    }
  }
};

/// How κ runs along a cubic: at sixteenths of its parameter, how often its sign changes (κ = 0
/// has no sign), its total variation and its largest magnitude; at thirty-seconds, how often it
/// turns (TurnCounter with `hysteresis`).
struct CurvatureShape {
  int sign_changes = 0;
  /// +1 or −1 where κ keeps that sign throughout (zeros aside), else 0.
  int bend = 0;
  /// The sign of κ nearest each end (zeros aside; 0 where κ is 0 throughout): where an
  /// inflection at a node may have moved across it (fair/inflection_count.hpp).
  int first_sign = 0, last_sign = 0;
  double variation = 0.0, largest = 0.0;
  int turns = 0;
  /// κ over the first half (t = 0, 1/32, …, 1/2) and the counter's state after the second
  /// half alone: what a node adds to the turns, joined with its neighbour's.
  std::array<double, 17> head{};
  TurnCounter tail;
};
CurvatureShape curvature_shape(const Cubic& c, double hysteresis);

}  // namespace gf
