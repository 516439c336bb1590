// The faired outline as on-curve nodes with their handles, before and after rounding to the
// integer grid: what a type designer sees in the editor.
#pragma once

#include <cmath>
#include <optional>
#include <vector>

#include "geom/contour.hpp"
#include "geom/curvature.hpp"

namespace gf {

struct OutlineNode {
  Vec2 point;
  std::optional<Vec2> in_handle, out_handle;  ///< absent on the side of a line
  bool smooth = true;
  /// A smooth node whose tangent runs exactly along this primitive integer vector, so that its
  /// handles can sit on the grid collinear with it in steps of the vector's length: (±1, 0) or
  /// (0, ±1) at horizontal and vertical extrema, short diagonals such as (2, 1) where a span
  /// was cut.
  std::optional<Vec2> grid_step;
  /// On the grid already and to stay there when rounded: where a line was split so that both
  /// its parts step short, the vertex and the curve's end (fair/line_splits.hpp).
  bool pinned = false;

  friend bool operator==(const OutlineNode&, const OutlineNode&) = default;
};

/// The cubic from node i to node i + 1 (node 0 after the last): both handles must be present.
Cubic outline_cubic(const std::vector<OutlineNode>& nodes, std::size_t i);

/// The direction the outline arrives in at node k: from its in-handle, else from the node
/// before (cyclically; 0 for a lone node).
Vec2 arriving_direction(const std::vector<OutlineNode>& nodes, std::size_t k);

/// The direction the outline leaves node k in: towards its out-handle, else the node after.
Vec2 leaving_direction(const std::vector<OutlineNode>& nodes, std::size_t k);

/// Whether two directions run exactly the same way: G1 exact, as a smooth node on the grid
/// must be.
inline bool exactly_collinear(Vec2 a, Vec2 b) { return cross(a, b) == 0.0 && dot(a, b) > 0.0; }

/// Node i starts segment i: a cubic when node i has an out-handle and node i + 1 an in-handle,
/// else a line. A closed contour's last segment returns to node 0.
Contour to_contour(const std::vector<OutlineNode>& nodes, bool closed);

/// Removes every cubic of no extent (its node, both handles and the next node at one point),
/// the node before it leaving as the node after it did: rounding finds no direction for such
/// a node (dkg Bold's G had four where a log-aesthetic segment's last units drew as its end
/// point, and one went to the origin). A guard since that segment was mended: on twelve fonts'
/// a–z A–Z and the whole of DejaVu Sans it finds none.
void drop_empty_cubics(std::vector<OutlineNode>& nodes, bool closed);

/// Merges the two smooth nodes of every cubic whose chord is under `shortest` (or under
/// flat_cubic_chord, bending less than the grid can bend a cubic that short) into one, for
/// rounding: the grid cannot draw a cubic of a few units, and whole steps folded such cubics
/// into loops with an extremum inside (Because We Create's P and r) or crossed their handles
/// (Vollkorn's z). Where both nodes are extrema on different axes, they become one corner
/// where their tangents cross, each handle where it was (Because We Create's s). Else the node
/// kept is a line's end (Comic Neue's i: a curve leaving a line stood upright passed the
/// vertical a unit on, and the node there rounded to a cubic folded on that unit), which takes
/// an extremum's place only where the line runs along the extremum's axis; else the one on a
/// horizontal or vertical extremum, else the first. The handle it takes over from the other
/// node keeps its length, plus the chord, along the kept node's tangent.
void merge_tiny_cubics(std::vector<OutlineNode>& nodes, bool closed, double shortest);

/// The chord (units) under which the fairing merges a cubic's nodes before rounding. 2 took
/// Because We Create's missing extrema 9 → 6 (3 then took them to 12). Since stop 85, 3: a cubic
/// of 2.0 units between Vollkorn's z's level foot and the inflection beside it rounded to a
/// unit with its handles crossed. a–z A–Z rounded, 2 → 3: Vollkorn g2-jumps 3 → 0, EB Garamond
/// 52 → 50, Junicode 59 → 52 (inflections 1.027× → 0.997×), Because We Create's TV 0.176× →
/// 0.157× with its missing extrema 2 as before. 4 made four new corners on Gentium Plus.
constexpr double tiny_cubic_chord = 3.0;

/// Under this chord (units) merge_tiny_cubics also merges a cubic whose curvature at both ends
/// lies below the least the grid can give a cubic that short (2/(3c³) for a chord c): whole
/// steps could only draw it straight. Spartan's e: a 5.4-unit cubic from its right side's
/// x-extremum, κ·UPM 7.0 and 3.4 at its ends (UPM 2,000), rounded straight against the next
/// cubic's 3.4. a–z A–Z of 45 text fonts: Junicode's g2-jumps 58, 51, 44, 45 and 47 at 6, 8,
/// 12, 16 and 24 units; EB Garamond 44 up to 12 units, 45 beyond; no other font's bars moved.
constexpr double flat_cubic_chord = 12.0;

/// A node whose handles break G1 by less than `limit_rad` made G1: both handles turned onto
/// their bisector, each by half the break, where that moves neither cubic by more than
/// `most_move` (a handle of length L turned by θ moves its cubic by at most (4/9)·L·θ); smooth
/// where it then is G1. False (the node as it was) where it is not.
bool join_nearly_smooth_node(OutlineNode& node, double limit_rad, double most_move);

/// The integer grid point nearest p.
inline Vec2 nearest_grid_point(Vec2 p) { return {std::round(p.x), std::round(p.y)}; }

/// How many whole steps of the grid direction d, nearest, `handle` lies from `from` on its side
/// of the node: sign +1 for an out-handle, −1 for an in-handle (0 or less: not on its side).
double whole_steps(Vec2 from, Vec2 handle, Vec2 d, double sign);

/// node + sign·m·d: the handle m ≥ 1 whole steps of d from `node` on its side (sign −1 for an
/// in-handle), m = whole_steps(from, handle, d, sign) at least 1.
Vec2 stepped_handle(Vec2 node, Vec2 d, double sign, Vec2 from, Vec2 handle);

/// An integer vector divided by the greatest common divisor of its components: the shortest
/// grid step along it (a handle on it lies a whole number of these from its node); none for 0.
std::optional<Vec2> primitive_step(Vec2 along);

/// Whether `d` is its own primitive step.
inline bool is_primitive(Vec2 d) { return primitive_step(d) == d; }

/// The index of the node of `nodes` (not empty) nearest `p`, the first of equals.
std::size_t nearest_node(const std::vector<OutlineNode>& nodes, Vec2 p);

/// nearest_node where it lies within `reach` of `p` (a float node for a join rounding moved);
/// none where it does not, or `nodes` is empty.
std::optional<std::size_t> node_within(const std::vector<OutlineNode>& nodes, Vec2 p, double reach);

/// The primitive integer directions with |d|² ≤ `longest`, both ways along each: where a span
/// is cut or a cubic split, the node goes where its tangent runs along one of them, so that
/// rounding keeps its handles exactly collinear with it in whole steps of |d|. The shortest,
/// (1, 0), (1, 1), (2, 1) and their mirrors (`longest` 5), are fine enough for whole steps to
/// match curvature (fair/handle_steps.hpp).
std::vector<Vec2> grid_directions(int longest);

/// Curvature where a cubic of the outline leaves its start or reaches its end
/// (geom/curvature.hpp), 0 where a retracted handle leaves it unbounded.
double node_curvature(const Cubic& c, SegmentEnd end);

}  // namespace gf
