#include "fair/handle_steps.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <numbers>
#include <utility>

#include "fair/bracket_placements.hpp"
#include "fair/contour_plan.hpp"
#include "fair/cubic_change.hpp"
#include "fair/inflection_count.hpp"
#include "geom/curvature.hpp"
#include "geom/join.hpp"
#include "geom/polyline_distance.hpp"

namespace gf {

namespace {

constexpr int reach = 3;              // whole steps either way from the rounded length
constexpr int max_passes = 16;        // of choosing steps and nudging nodes in turn (a corner's
                                      // handle moves a unit a pass: DejaVu's Q tail took 9)
constexpr double turn = 0.1;          // radians a node may turn on the grid (the allowance bounds what that moves)
// How far a line join may slide back along its line (slide_line_joins), in chords of its cubic
// from where the passes found it. a–z A–Z rounded, g2-jumps at 1, 1.5, 2 and 3: Lato 7, 6, 6,
// 8; Carlito 14, 13, 12, 12; TeX Gyre Pagella 82, 78, 78, 78; Noto Serif 13, 12, 12, 12.
constexpr double slide_reach = 2.0;
constexpr int slide_samples = 24;      // points per cubic where a node's slide is measured
constexpr double target_jump = 0.03;  // below the check's 5 %, with room for its sampling
constexpr double checked_jump = 0.05;  // the check's g2-jump (HandleStepLimits::counted_jump_cost)
constexpr double wrong_way = 1e4;     // an inflection or extremum the unrounded cubic lacks
constexpr double moved_inflection_cost = 1.0;  // an inflection moved off its node, in seat_flat_nodes
constexpr double infeasible = std::numeric_limits<double>::infinity();
constexpr double kink_limit = radians(kink_limit_deg);  // fair/contour_plan.hpp's
// Curvature variation a rounded cubic adds inside, relative to its unrounded largest |κ|: free
// up to 5 %, then weighed a third of a matching curvature jump (whose cost rises 100 per unit),
// so G2 stays first. Measured: Because We Learn TV 0.59 → 0.55× with g2-jumps 11.0 → 10.7 %.
constexpr double free_variation = 0.05;
constexpr double variation_weight = 3.0;
// A curvature extremum a rounded cubic adds inside (a wobble of the comb, an extremum the check
// counts): 3 each, at most 1.9 a cubic, so that even both cubics at a node cost less than one
// jump over the target (at least 4) and G2 stays first. Measured, a-z A-Z: dkg extrema 0.77 ->
// 0.70x, Because We Learn 0.79 -> 0.72x; uncapped, Inter's g kept a jump.
constexpr double turn_weight = 3.0, most_turn_cost = 1.9;
// A turn of κ at a node the unrounded outline lacks there (a tooth of the comb where whole
// steps set the node's two ends a few per cent apart; handwriting only): weighed as a jump of
// 8 % (1 + 100·0.08), so the grid would rather leave a small jump the check barely counts than
// a tooth it counts as two extrema. Measured, a–z A–Z rounded, 3 → 9: Because We Learn extrema
// 0.506× → 0.483× (the bar 0.5×; 6 to 20 all come under it), dkg g2-jumps 0.95 → 1.25 % (the
// bar 2 %).
constexpr double node_turn_weight = 9.0;
// A cubic shorter than this (units) is checked for folding into a loop or cusp within its chord
// (cubic_turning); a longer one that folds reaches past its chord (overreach_length). Because
// We Create's brush ends: 3-unit cubics rounded into loops, 14 of its 54 missing extrema.
constexpr double fold_chord = 16.0;
constexpr double fold_turn = 0.5 * std::numbers::pi;  // turning beyond the unrounded cubic's
// A cubic bending wholly the other way from its unrounded self (a nearly straight cubic whose
// rounded ends tilt it across its chord) puts an inflection at a node between it and its
// neighbours: weighed under any jump over the target, over every one within it.
constexpr double flip_weight = 2.0;
double flip_cost(const CurvatureShape& rounded, const CurvatureShape& unrounded) {
  return rounded.bend * unrounded.bend < 0 ? flip_weight : 0.0;
}

double turn_cost(int added) { return std::min(most_turn_cost, turn_weight * std::max(0, added)); }

// The curvature variation a rounded cubic adds inside beyond free_variation of its unrounded
// largest |κ|: a spike a comb would show (a one-step handle with its far handle a unit off the
// tangent gives κ = 2/3 a unit, a hundred times what the cubic had).
double variation_cost(const CurvatureShape& rounded, const CurvatureShape& unrounded, double flat) {
  const double excess = (rounded.variation - unrounded.variation) / std::max(unrounded.largest, flat);
  return excess > free_variation ? variation_weight * (excess - free_variation) : 0.0;
}

// What a rounded cubic's curvature costs beyond its unrounded self's, short of an inflection
// inside it: bending wholly the other way, curvature extrema it gains (a wobble of the comb),
// and curvature variation it gains beyond a little (a spike a comb would show). The choice of
// handles and a node's nudge weigh it alike.
double shape_cost(const CurvatureShape& rounded, const CurvatureShape& unrounded, double flat) {
  return flip_cost(rounded, unrounded) + turn_cost(rounded.turns - unrounded.turns) +
         variation_cost(rounded, unrounded, flat);
}

// relative_jump (fair/handle_steps.hpp), by its short name here.
double jump(double k1, double k2, double flat) { return relative_jump(k1, k2, flat); }

// G2 first: any jump over the target costs more than every choice that meets it.
double jump_cost(double j) { return j <= target_jump ? j * j : 1.0 + 100.0 * j; }

// A jump of dκ/ds (relative to the larger side, as the G3 check measures it) over 4 % costs
// `weight` times 1 to 2 (HandleStepLimits::slope_jump_weight).
constexpr double target_slope_jump = 0.04;
double slope_jump_cost(double d1, double d2, double weight) {
  const double j = jump(d1, d2, 0.0);
  return j <= target_slope_jump ? 0.0 : weight * (1.0 + 0.5 * j);
}

// How many steps (not necessarily whole) of `step` from `node`, on the side `sign` gives, reach
// the line through `line_point` along `line_dir`; none where they run parallel (as far from the
// line at every step).
std::optional<double> steps_to_line(Vec2 node, Vec2 step, double sign, Vec2 line_point, Vec2 line_dir) {
  const double across = sign * cross(line_dir, step);
  if (across == 0.0) return std::nullopt;
  return -cross(line_dir, node - line_point) / across;
}

// The handles node + sign·m·step at the whole counts m either side of `steps` (one where it is
// whole), none under one step.
std::vector<Vec2> whole_steps_around(Vec2 node, Vec2 step, double sign, double steps) {
  std::vector<Vec2> handles;
  for (const double whole : {std::floor(steps), std::ceil(steps)})
    if (whole >= 1.0 && (handles.empty() || whole != std::floor(steps))) handles.push_back(node + step * (sign * whole));
  return handles;
}

// Where one handle of a node may go: whole steps along the node's grid direction, up to
// `corner_reach` units either way for a corner's handle, else where it is. The rounded
// position comes first.
std::vector<Vec2> handle_candidates(const OutlineNode& node, std::optional<Vec2> step, bool out, int corner_reach = 1) {
  const Vec2 h = out ? *node.out_handle : *node.in_handle;
  std::vector<Vec2> c{h};
  if (step) {
    const double sign = out ? 1.0 : -1.0;
    const double m0 = whole_steps(node.point, h, *step, sign);
    for (int k = -reach; k <= reach; ++k)
      if (k != 0 && m0 + k >= 1.0) c.push_back(node.point + *step * (sign * (m0 + k)));
  } else if (!node.smooth) {
    for (int dx = -corner_reach; dx <= corner_reach; ++dx)
      for (int dy = -corner_reach; dy <= corner_reach; ++dy)
        if (dx != 0 || dy != 0) c.push_back(h + Vec2{double(dx), double(dy)});
  }
  return c;
}

// Where one handle of a cubic meeting a line may go besides: the whole steps nearest the line,
// so the cubic leaves it with the least curvature the grid allows (the rounded length is often
// several steps away from them); for a corner's handle, the grid point on the line nearest it.
std::vector<Vec2> handles_meeting_line(const OutlineNode& node, std::optional<Vec2> step, bool out,
                                       const OutlineNode& line_end, Vec2 line_dir) {
  if (step) return handles_near_line(node.point, *step, out ? 1.0 : -1.0, line_end.point, line_dir);
  if (node.smooth) return {};
  const Vec2 h = out ? *node.out_handle : *node.in_handle;
  return {line_end.point + line_dir * whole_steps(line_end.point, h, line_dir, 1.0)};
}

// How far node k turns, radians (absolute), with its in-handle or out-handle replaced where
// given; a side with no handle (a line) runs from or to the neighbouring node; π at an open
// outline's ends and where a side has no length (its tangent comes from farther points).
double turn_at(const std::vector<OutlineNode>& nodes, bool closed, std::size_t k, std::optional<Vec2> in = {},
               std::optional<Vec2> out = {}) {
  const std::size_t n = nodes.size();
  if (!closed && (k == 0 || k + 1 == n)) return std::numbers::pi;
  const OutlineNode& node = nodes[k];
  const Vec2 from = in ? *in : node.in_handle ? *node.in_handle : nodes[(k + n - 1) % n].point;
  const Vec2 to = out ? *out : node.out_handle ? *node.out_handle : nodes[(k + 1) % n].point;
  const Vec2 a = node.point - from, b = to - node.point;
  if (norm(a) == 0.0 || norm(b) == 0.0) return std::numbers::pi;
  return std::abs(turning_angle(a, b));
}

// Whether node k of the unrounded outline is a corner rounding must not turn under the kink
// limit (cubic_choices): the kink pass (fair/contour_fairing) would make it smooth, and the
// corner the source drew would be lost. Between a line and a cubic, any corner turning by the
// limit or more (a–z A–Z, Lato's x at 3.0°, its Y at 3.2° and Carlito's v at 3.1° went so while
// only corners a degree past the limit were kept: Lato lost 6, Carlito 9; now 2 and 3). Between
// two cubics, one turning a degree past it (Carlito's X at 6.6° and 4.7°, FreeSerif's K at
// 5.0°): within that degree, EB Garamond's W found no rounding within the tolerance and kept
// three runs as drawn, after 105 s instead of 18.
bool corner_to_keep(const std::vector<OutlineNode>& ideal, bool closed, std::size_t k) {
  const OutlineNode& node = ideal[k];
  if (node.smooth || (!node.in_handle && !node.out_handle)) return false;
  const bool between_cubics = node.in_handle && node.out_handle;
  const double turn = turn_at(ideal, closed, k);
  return turn >= radians(kink_limit_deg + (between_cubics ? 1.0 : 0.0)) && turn < std::numbers::pi;
}

// Which nodes of an outline join two cubics, meet a line, or start a cubic.
struct OutlineJoins {
  const std::vector<OutlineNode>& nodes;
  bool closed;

  std::size_t size() const { return nodes.size(); }
  bool is_cubic(std::size_t i) const {
    const std::size_t n = size();
    return (closed || i + 1 < n) && nodes[i].out_handle && nodes[(i + 1) % n].in_handle;
  }
  bool interior(std::size_t i) const { return closed || (i > 0 && i + 1 < size()); }
  /// A smooth node between two cubics couples them.
  bool joins_cubics(std::size_t i) const {
    return interior(i) && nodes[i].smooth && is_cubic(i) && is_cubic((i + size() - 1) % size());
  }
  /// A smooth node between a cubic and a line wants κ = 0 on its cubic's side.
  bool meets_line(std::size_t i) const {
    return interior(i) && nodes[i].smooth && is_cubic(i) != is_cubic((i + size() - 1) % size());
  }
};

// What the choices weigh of a candidate cubic.
struct CubicTraits {
  double k_start = 0.0, k_end = 0.0;
  double slope_start = 0.0, slope_end = 0.0;  ///< dκ/ds at the ends
  double moved = 0.0;  ///< from its unrounded self, as moved_distance measures it within the allowance
  bool within = true;  ///< moved within the allowance, or still within the band around the source
  CurvatureShape shape;
  InnerAxisExtrema extrema;  ///< horizontal or vertical turns inside
  double overreach = 0.0;  ///< how far a handle reaches past the chord (overreach_length)
  double turning = 0.0;  ///< of a cubic shorter than fold_chord (cubic_turning), else 0
};

// The turns of κ a node adds, counted as the check counts them over the second half of the
// cubic before it and the first half of the one after, beyond what that first half counts
// alone (the halves' own turns are their cubics').
int turns_at_node(const CubicTraits& before, const CubicTraits& after, double hysteresis) {
  TurnCounter joined = before.shape.tail, alone;
  joined.turns = 0;
  for (const double k : after.shape.head) {
    joined.add(k, hysteresis), alone.add(k, hysteresis);
    // Once both counters stand alike, the rest of the half adds to both alike.
    if (joined.direction == alone.direction && joined.anchor == alone.anchor) break;
  }
  return joined.turns - alone.turns;
}

// The unrounded cubic i with each end that meets a line moved along its tangent as far as
// rounding moved that end along it (line_rounding slides a curve's end along its line, its
// handle's tip kept): what a cubic from the slid end should be measured against. What that
// slide strays line_rounding weighed; the rounded contour is measured whole against the source
// after all (fair/contour_fairing.cpp rounds again within less where it strays).
Cubic along_lines(Cubic c, const std::vector<OutlineNode>& rounded, std::size_t i, const OutlineJoins& joins) {
  const std::size_t j = (i + 1) % joins.size();
  auto slide = [](Vec2& end, Vec2 handle, Vec2 to) {
    const Vec2 t = handle - end;
    const double length = norm(t);
    if (length == 0.0) return;
    const Vec2 u = t / length;
    end = end + u * dot(u, to - end);
  };
  if (joins.meets_line(i)) slide(c.p[0], c.p[1], rounded[i].point);
  if (joins.meets_line(j)) slide(c.p[3], c.p[2], rounded[j].point);
  return c;
}

// A cubic as a polyline for the band around the source: a point every four units of its
// control polygon or so (chords then stray a few hundredths of a unit at glyph curvatures),
// 16 to 96 in all.
std::vector<Vec2> band_samples(const Cubic& c) {
  const double polygon = distance(c.p[0], c.p[1]) + distance(c.p[1], c.p[2]) + distance(c.p[2], c.p[3]);
  const int n = std::clamp(static_cast<int>(polygon / 4.0), 16, 96);
  std::vector<Vec2> out;
  out.reserve(n + 1);
  for (int k = 0; k <= n; ++k) out.push_back(c.point_at(double(k) / n));
  return out;
}

// Every cubic of the outline against its unrounded self. How far each may move to gain G2 is
// set once: its allowance, or as far as rounding alone already put it. Each candidate is
// measured once, however many passes weigh it.
class CubicJudge {
 public:
  CubicJudge(const std::vector<OutlineNode>& rounded, const std::vector<OutlineNode>& ideal,
             const OutlineJoins& joins, const HandleStepLimits& limits)
      : unrounded_(rounded.size()), allowed_(rounded.size(), 0.0), ideal_(rounded.size()), seen_(rounded.size()),
        inflection_handles_(limits.inflection_handles), node_turns_(limits.node_turns), slope_jump_weight_(limits.slope_jump_weight),
        counted_jump_cost_(limits.counted_jump_cost), band_(limits.band), band_pieces_(rounded.size()),
        keeps_corner_(rounded.size(), false), closed_(joins.closed), joins_before_(rounded.size(), false),
        along_outline_(rounded.size()) {
    for (std::size_t i = 0; i < rounded.size(); ++i) band_pieces_[i] = limits.band_piece(i);
    for (std::size_t i = 0; i < rounded.size(); ++i) {
      if (!joins.is_cubic(i)) continue;
      unrounded_[i] = along_lines(outline_cubic(ideal, i), rounded, i, joins);
      const double allowance = limits.allowance_at(i);
      allowed_[i] = std::max(allowance, moved_distance(outline_cubic(rounded, i), unrounded_[i], allowance));
      // κ turns count from 1 % of the outline's largest unrounded |κ|, as the check counts them.
      hysteresis_ = std::max(hysteresis_, 0.01 * curvature_shape(unrounded_[i], 0.0).largest);
    }
    for (std::size_t i = 0; i < rounded.size(); ++i) joins_before_[i] = joins.joins_cubics(i);
    for (std::size_t i = 0; i < rounded.size(); ++i)
      if (joins.is_cubic(i)) ideal_[i] = measure(i, unrounded_[i]);
    for (std::size_t k = 0; k < rounded.size(); ++k) keeps_corner_[k] = corner_to_keep(ideal, closed_, k);
  }

  bool closed() const { return closed_; }
  /// Whether node k is a corner between a line and a cubic that rounding must leave turning by
  /// the kink limit (corner_to_keep).
  bool keeps_corner(std::size_t k) const { return keeps_corner_[k]; }

  double allowed(std::size_t i) const { return allowed_[i]; }
  /// HandleStepLimits::node_turns.
  bool node_turns() const { return node_turns_; }
  /// Whether dκ/ds jumps cost (HandleStepLimits::slope_jump_weight).
  bool match_slopes() const { return slope_jump_weight_ > 0.0; }
  /// HandleStepLimits::inflection_handles.
  bool inflection_handles() const { return inflection_handles_; }
  /// The turns of κ at the node between cubics h and i beyond the unrounded outline's there
  /// (`unrounded_turns`, unrounded_node_turns(h, i)), each node_turn_weight; none unless
  /// HandleStepLimits::node_turns.
  double node_turn_cost(const CubicTraits& before, const CubicTraits& after, int unrounded_turns) const {
    if (!node_turns_) return 0.0;
    return node_turn_weight * std::max(0, turns_at_node(before, after, hysteresis_) - unrounded_turns);
  }
  /// What a curvature jump j at a node costs, one the check counts the more
  /// (HandleStepLimits::counted_jump_cost).
  double g2_cost(double j) const { return jump_cost(j) + (j > checked_jump ? counted_jump_cost_ : 0.0); }
  /// What the jump of dκ/ds at a node costs (HandleStepLimits::slope_jump_weight), else nothing.
  double slope_cost(const CubicTraits& before, const CubicTraits& after) const {
    return match_slopes() ? slope_jump_cost(before.slope_end, after.slope_start, slope_jump_weight_) : 0.0;
  }
  int unrounded_node_turns(std::size_t h, std::size_t i) const {
    return node_turns_ ? turns_at_node(ideal_[h], ideal_[i], hysteresis_) : 0;
  }
  /// Whether κ turns at node i (joining cubics h and i) or inside either cubic where the
  /// unrounded outline does not; never unless HandleStepLimits::node_turns.
  bool turns_too_often(std::size_t h, const CubicTraits& before, std::size_t i, const CubicTraits& after) const {
    return node_turns_ && (node_turn_cost(before, after, unrounded_node_turns(h, i)) > 0.0 ||
                           before.shape.turns > ideal_[h].shape.turns || after.shape.turns > ideal_[i].shape.turns);
  }
  const CubicTraits& unrounded(std::size_t i) const { return ideal_[i]; }
  /// The inflections `t`, in the place of cubic i, adds inside itself; a flip at an end on an
  /// inflection node (inflects_at) is that node's (fair/inflection_count.hpp).
  int inflections_added(std::size_t i, const CubicTraits& t) const {
    const std::size_t n = ideal_.size();
    return inflections_added_within(t.shape, ideal_[i].shape, inflects_at(i), inflects_at((i + 1) % n));
  }
  /// Whether node i joins two cubics whose unrounded κ changes sign across it: an inflection
  /// that may move across it.
  bool inflects_at(std::size_t i) const {
    const std::size_t n = ideal_.size();
    return joins_before_[i] && inflection_between(ideal_[(i + n - 1) % n].shape, ideal_[i].shape);
  }
  /// What happens to an inflection at the node where cubic h (as `before`) meets cubic i (as
  /// `after`): the inflections added there (inflections_at).
  NodeInflections inflections_at_node(std::size_t h, const CubicTraits& before, std::size_t i,
                                      const CubicTraits& after) const {
    return inflections_at(before.shape, ideal_[h].shape, after.shape, ideal_[i].shape);
  }

  /// The traits of `c` in the place of cubic i.
  const CubicTraits& traits(std::size_t i, const Cubic& c) {
    const auto [it, fresh] = seen_[i].try_emplace(std::array{c.p[0].x, c.p[0].y, c.p[1].x, c.p[1].y,
                                                             c.p[2].x, c.p[2].y, c.p[3].x, c.p[3].y});
    if (fresh) it->second = measure(i, c);
    return it->second;
  }

 private:
  // How far `c`, in the place of cubic i, lies from the unrounded outline where its node slid
  // along it: its points from the unrounded cubic and those it joins smoothly, and the points of
  // those between where c's ends lie nearest from c. A node moved along its own tangent shortens
  // one cubic and lengthens the other; each measured against its unrounded self alone, the
  // shortened one "moves" by the whole slide, its end no longer reaching the old node. Past
  // `within`, only that it is past.
  double slid_distance(std::size_t i, const Cubic& c, double within) {
    const std::vector<Vec2>& along = along_outline(i).points;
    std::array<Vec2, slide_samples + 1> pc;
    for (int t = 0; t <= slide_samples; ++t) pc[t] = c.point_at(double(t) / slide_samples);
    const double there = directed_hausdorff(pc, along, within);
    if (there > within) return there;
    const auto nearest = [&](Vec2 p) {
      std::size_t best = 0;
      for (std::size_t k = 1; k < along.size(); ++k)
        if (distance(along[k], p) < distance(along[best], p)) best = k;
      return best;
    };
    const std::size_t a = nearest(c.p[0]), b = nearest(c.p[3]);
    if (a >= b) return std::numeric_limits<double>::infinity();
    const std::span<const Vec2> covered(along.data() + a, b - a + 1);
    return std::max(there, directed_hausdorff(covered, pc, within));
  }

  // Cubic i's unrounded self with the unrounded cubics it joins smoothly, along the outline:
  // `points`, of which [own_first, own_last] are its own. Built when first asked for (most
  // cubics stay within their allowance).
  struct Stretch {
    std::vector<Vec2> points;
    std::size_t own_first = 0, own_last = 0;
  };
  const Stretch& along_outline(std::size_t i) {
    Stretch& along = along_outline_[i];
    if (!along.points.empty()) return along;
    const std::size_t n = unrounded_.size();
    const auto add = [&](const Cubic& c) {
      for (int t = along.points.empty() ? 0 : 1; t <= slide_samples; ++t)
        along.points.push_back(c.point_at(double(t) / slide_samples));
    };
    if (joins_before_[i]) add(unrounded_[(i + n - 1) % n]);
    along.own_first = along.points.empty() ? 0 : along.points.size() - 1;
    add(unrounded_[i]);
    along.own_last = along.points.size() - 1;
    if (joins_before_[(i + 1) % n]) add(unrounded_[(i + 1) % n]);
    return along;
  }

  // Whether `c`, in the place of cubic i, keeps within the band around the source, the source
  // points its unrounded self answered for covered by it or by the unrounded cubics it joins
  // smoothly, spliced on either side of it in place of its unrounded self (a node slid along
  // the outline hands them over; what c itself covers, the splice covers too).
  bool band_holds(std::size_t i, const Cubic& c) {
    const std::vector<Vec2> pc = band_samples(c);
    const Stretch& along = along_outline(i);
    if (along.own_first == 0 && along.own_last + 1 == along.points.size()) return band_->holds(band_pieces_[i], pc);
    std::vector<Vec2> spliced(along.points.begin(), along.points.begin() + static_cast<std::ptrdiff_t>(along.own_first));
    spliced.insert(spliced.end(), pc.begin(), pc.end());
    spliced.insert(spliced.end(), along.points.begin() + static_cast<std::ptrdiff_t>(along.own_last + 1), along.points.end());
    return band_->holds_along(band_pieces_[i], pc, spliced);
  }

  CubicTraits measure(std::size_t i, const Cubic& c) {
    const EndCurvature start = end_curvature(c, SegmentEnd::start), end = end_curvature(c, SegmentEnd::end);
    double moved = moved_distance(c, unrounded_[i], allowed_[i]);
    if (moved > allowed_[i]) moved = std::min(moved, slid_distance(i, c, allowed_[i]));
    return {start.curvature.value_or(0.0),
            end.curvature.value_or(0.0),
            start.curvature_derivative.value_or(0.0),
            end.curvature_derivative.value_or(0.0),
            moved,
            moved <= allowed_[i] || (band_ && band_holds(i, c)),
            curvature_shape(c, hysteresis_),
            inner_axis_extrema_of(c),
            overreach_length(c),
            distance(c.p[0], c.p[3]) < fold_chord ? cubic_turning(c) : 0.0};
  }

  std::vector<Cubic> unrounded_;
  std::vector<double> allowed_;
  double hysteresis_ = 0.0;
  std::vector<CubicTraits> ideal_;
  std::vector<std::map<std::array<double, 8>, CubicTraits>> seen_;
  bool inflection_handles_, node_turns_;
  double slope_jump_weight_, counted_jump_cost_;
  const ToleranceBand* band_;
  std::vector<std::size_t> band_pieces_;  ///< the band's piece for each cubic
  std::vector<bool> keeps_corner_;
  bool closed_;
  std::vector<bool> joins_before_;                 ///< whether node i joins two cubics smoothly
  std::vector<Stretch> along_outline_;             ///< along_outline(i), once asked for
};

// One cubic of the outline and every choice of its two handles (state = out·ins + in).
struct CubicChoices {
  std::size_t start = 0, end = 0;  ///< node indices
  std::vector<Vec2> outs, ins;
  std::vector<double> k_start, k_end, cost;
  std::vector<const CubicTraits*> traits;  ///< each state's, for the turns at its nodes

  std::size_t states() const { return outs.size() * ins.size(); }
};

// `as_is`: the one choice of the handles where they are (a cubic a choice only weighs).
CubicChoices cubic_choices(const std::vector<OutlineNode>& nodes, std::span<const std::optional<Vec2>> steps,
                           std::size_t i, std::size_t j, CubicJudge& judge, double flat, bool line_before,
                           bool line_after, bool as_is = false) {
  CubicChoices c;
  c.start = i, c.end = j;
  c.outs = as_is ? std::vector<Vec2>{*nodes[i].out_handle} : handle_candidates(nodes[i], steps[i], true);
  c.ins = as_is ? std::vector<Vec2>{*nodes[j].in_handle} : handle_candidates(nodes[j], steps[j], false);
  auto add = [](std::vector<Vec2>& to, const std::vector<Vec2>& more) {
    for (const Vec2 h : more)
      if (std::find(to.begin(), to.end(), h) == to.end()) to.push_back(h);
  };
  const Vec2 p0 = nodes[i].point, p3 = nodes[j].point;
  const double allowed = judge.allowed(i);
  const CubicTraits& ideal = judge.unrounded(i);
  // κ = 0 at an end that meets a line, or at a smooth node flat before rounding (an inflection,
  // where asked): the far handles nearest that end's tangent line join the choices
  // (seat_flat_nodes moves the node itself for them).
  const bool inflection = judge.inflection_handles();
  const bool zero_start = line_before || (inflection && nodes[i].smooth && std::abs(ideal.k_start) < flat);
  const bool zero_end = line_after || (inflection && nodes[j].smooth && std::abs(ideal.k_end) < flat);
  if (zero_start && steps[i] && !as_is) add(c.ins, handles_meeting_line(nodes[j], steps[j], false, nodes[i], *steps[i]));
  if (zero_end && steps[j] && !as_is) add(c.outs, handles_meeting_line(nodes[i], steps[i], true, nodes[j], *steps[j]));
  // Whether a handle turns a corner to keep (node k's) under the kink limit.
  const auto turned_under_limit = [&](std::size_t k, std::optional<Vec2> in, std::optional<Vec2> out) {
    return judge.keeps_corner(k) && turn_at(nodes, judge.closed(), k, in, out) < kink_limit;
  };
  auto weigh = [&] {
    c.k_start.clear(), c.k_end.clear(), c.cost.clear(), c.traits.clear();
    for (const Vec2 out : c.outs)
      for (const Vec2 in : c.ins) {
        const CubicTraits& t = judge.traits(i, Cubic{p0, out, in, p3});
        c.k_start.push_back(t.k_start), c.k_end.push_back(t.k_end);
        c.traits.push_back(&t);
        if (!t.within) {
          c.cost.push_back(infeasible);
          continue;
        }
        double cost = allowed > 0.0 ? 0.01 * (t.moved / allowed) * (t.moved / allowed) : 0.0;
        // A curve meeting a line tangentially meets it with κ = 0.
        if (line_before) cost += judge.g2_cost(jump(t.k_start, 0.0, flat));
        if (line_after) cost += judge.g2_cost(jump(t.k_end, 0.0, flat));
        // Where the grid allows only near zero, or a corner's handle moves, the cubic must not
        // bend the other way near its end: an inflection the unrounded cubic does not have.
        if (judge.inflections_added(i, t) > 0) cost += wrong_way;
        // Nor turn horizontal or vertical inside: an extremum without a node.
        if (t.extrema.all > ideal.extrema.all) cost += wrong_way;
        // Nor carry one that sat within half a unit of its node farther off it.
        if (t.extrema.off_node > ideal.extrema.off_node) cost += wrong_way;
        // Nor turn a corner at a line into a kink, or smooth: the kink pass then makes it smooth
        // and fairs the contour again, and the grid may give that join no G2 (Lato's S: a 4.3°
        // corner rounded straight, then κ·UPM 3.4 where its curve left the line).
        if (turned_under_limit(i, {}, out)) cost += wrong_way;
        if (turned_under_limit(j, in, {})) cost += wrong_way;
        // Nor fold back on itself past its chord.
        if (t.overreach > ideal.overreach) cost += wrong_way * (1.0 + t.overreach);
        // Nor, short, loop or cusp within it.
        if (t.turning > ideal.turning + fold_turn) cost += wrong_way;
        // Nor bend wholly the other way, gain a curvature extremum or a spike.
        cost += shape_cost(t.shape, ideal.shape, flat);
        c.cost.push_back(cost);
      }
  };
  weigh();
  // A corner to keep that every choice turns under the kink limit, or keeps only with a bend
  // the unrounded cubic lacks: the corners' handles two units either way too (Lato's Y: a 3.3°
  // corner whose line line_rounding moved 2.2 units for a shorter step; the nearly straight
  // cubic from it kept 3° only as an S, unless the far corner's handle moved two units).
  bool at_risk = !as_is, lost = false;
  for (std::size_t s = 0; s < c.states() && at_risk; ++s) {
    const Vec2 out = c.outs[s / c.ins.size()], in = c.ins[s % c.ins.size()];
    at_risk = c.cost[s] >= wrong_way;
    lost = lost || turned_under_limit(i, {}, out) || turned_under_limit(j, in, {});
  }
  if (at_risk && lost) {  // a corner's handle (no grid step) only: the others are as they were
    add(c.outs, handle_candidates(nodes[i], steps[i], true, 2));
    add(c.ins, handle_candidates(nodes[j], steps[j], false, 2));
    weigh();
  }
  // Where no choice gives an end at a smooth node within the target of its unrounded curvature,
  // the handle lengths aimed at it (handles_for_curvature), against every place of the far
  // handle: only there, as they multiply the choices.
  const bool aim_start = nodes[i].smooth && steps[i] && !line_before;
  const bool aim_end = nodes[j].smooth && steps[j] && !line_after;
  bool start_met = !aim_start, end_met = !aim_end;
  for (std::size_t s = 0; s < c.states(); ++s) {
    if (c.cost[s] == infeasible) continue;
    start_met = start_met || jump(c.k_start[s], ideal.k_start, flat) <= target_jump;
    end_met = end_met || jump(c.k_end[s], ideal.k_end, flat) <= target_jump;
  }
  if ((start_met && end_met) || as_is) return c;
  const std::size_t outs = c.outs.size(), ins = c.ins.size();
  if (!start_met)
    for (std::size_t k = 0; k < ins; ++k) add(c.outs, handles_for_curvature(p0, *steps[i], true, c.ins[k], p3, ideal.k_start));
  if (!end_met)  // against the far handles as they were, not those just aimed
    for (std::size_t k = 0; k < outs; ++k) add(c.ins, handles_for_curvature(p3, *steps[j], false, c.outs[k], p0, ideal.k_end));
  if (c.outs.size() != outs || c.ins.size() != ins) weigh();
  return c;
}

// The indices of `costs`, cheapest first; ties in index order.
std::vector<std::size_t> cheapest_first(std::span<const double> costs) {
  std::vector<std::size_t> order(costs.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return costs[a] < costs[b]; });
  return order;
}

// What the join between state s of cubic a and state t of the cubic b after it costs: its jump
// of κ and, where asked, of dκ/ds (not the turns at its node), and an inflection either side's
// end adds there.
double join_cost(const CubicJudge& judge, const CubicChoices& a, std::size_t s, const CubicChoices& b, std::size_t t,
                 double flat) {
  return judge.g2_cost(jump(a.k_end[s], b.k_start[t], flat)) + judge.slope_cost(*a.traits[s], *b.traits[t]) +
         wrong_way * judge.inflections_at_node(a.start, *a.traits[s], b.start, *b.traits[t]).added;
}

// The cheapest states of a run of cubics joined at smooth nodes; `first`, for a run that
// closes on itself, fixes the first cubic's state and adds the join from the last back to it.
struct RunChoice {
  std::vector<std::size_t> states;
  double cost = infeasible;
};

RunChoice best_run(const std::vector<CubicChoices>& run, const CubicJudge& judge, double flat,
                   std::optional<std::size_t> first) {
  const std::size_t n = run.size();
  std::vector<std::vector<std::size_t>> back(n);
  std::vector<double> cost(run[0].states(), infeasible);
  for (std::size_t s = 0; s < cost.size(); ++s)
    if (!first || *first == s) cost[s] = run[0].cost[s];
  for (std::size_t k = 1; k < n; ++k) {
    const CubicChoices &prev = run[k - 1], &cur = run[k];
    std::vector<double> next(cur.states(), infeasible);
    back[k].assign(cur.states(), 0);
    const int unrounded_turns = judge.unrounded_node_turns(prev.start, cur.start);
    // The states before, cheapest first: a join only adds to a state's cost, so once one costs
    // more than the best found, none after it can do better. Ties go to the lower state, as in
    // index order.
    const std::vector<std::size_t> order = cheapest_first(cost);
    for (std::size_t t = 0; t < cur.states(); ++t) {
      if (cur.cost[t] == infeasible) continue;
      for (const std::size_t s : order) {
        if (cost[s] == infeasible || cost[s] > next[t]) break;
        const double c = cost[s] + join_cost(judge, prev, s, cur, t, flat);
        const auto better = [&](double v) { return v < next[t] || (v == next[t] && s < back[k][t]); };
        if (!better(c)) continue;  // a node's turns only add to it
        const double with_turns = c + judge.node_turn_cost(*prev.traits[s], *cur.traits[t], unrounded_turns);
        if (better(with_turns)) next[t] = with_turns, back[k][t] = s;
      }
      next[t] += cur.cost[t];
    }
    cost = std::move(next);
  }
  RunChoice best;
  for (std::size_t s = 0; s < cost.size(); ++s) {
    double c = cost[s];
    if (first && c != infeasible)
      c += join_cost(judge, run[n - 1], s, run[0], *first, flat) +
           judge.node_turn_cost(*run[n - 1].traits[s], *run[0].traits[*first],
                                judge.unrounded_node_turns(run[n - 1].start, run[0].start));
    if (c < best.cost) best.cost = c, best.states.assign(n, 0), best.states[n - 1] = s;
  }
  if (best.cost == infeasible) return best;
  for (std::size_t k = n - 1; k > 0; --k) best.states[k - 1] = back[k][best.states[k]];
  return best;
}

// The curvatures at node k of the cubic arriving there and the one leaving it.
std::pair<double, double> curvatures_at(const std::vector<OutlineNode>& nodes, std::size_t k) {
  const std::size_t before = (k + nodes.size() - 1) % nodes.size();
  return {node_curvature(outline_cubic(nodes, before), SegmentEnd::end),
          node_curvature(outline_cubic(nodes, k), SegmentEnd::start)};
}

// The curvature jump at node k: between its two cubics, or from zero where it meets a line;
// none elsewhere.
double join_jump(const OutlineJoins& joins, std::size_t k, double flat) {
  const std::vector<OutlineNode>& nodes = joins.nodes;
  const std::size_t n = nodes.size(), before = (k + n - 1) % n;
  if (joins.joins_cubics(k)) {
    const auto [in, out] = curvatures_at(nodes, k);
    return jump(in, out, flat);
  }
  if (!joins.meets_line(k)) return 0.0;
  const double kappa = joins.is_cubic(k) ? node_curvature(outline_cubic(nodes, k), SegmentEnd::start)
                                         : node_curvature(outline_cubic(nodes, before), SegmentEnd::end);
  return jump(kappa, 0.0, flat);
}

// Where rounding or a nudge may put a node: its grid point and those `reach` units from it that
// are still within `reach` of the grid point nearest its unrounded place.
std::vector<Vec2> node_places(Vec2 at, Vec2 unrounded, int reach = 1) {
  const Vec2 nearest = nearest_grid_point(unrounded);
  std::vector<Vec2> out;
  for (int dy = -reach; dy <= reach; ++dy)
    for (int dx = -reach; dx <= reach; ++dx) {
      const Vec2 p = at + Vec2{double(dx), double(dy)};
      if (std::abs(p.x - nearest.x) <= reach && std::abs(p.y - nearest.y) <= reach) out.push_back(p);
    }
  return out;
}

// A change at node i of an outline: it changes both cubics at i (the one, where the other side
// is a line: a corner's), so the curvature jumps at i and at its two neighbours. It is allowed
// when no such cubic moves farther from its unrounded self than its allowance, nor gains an
// inflection, an H/V extremum or a handle's reach past its chord that neither its unrounded
// self nor the cubic before the change has.
class NodeChange {
 public:
  NodeChange(const std::vector<OutlineNode>& nodes, const OutlineJoins& joins, CubicJudge& judge, double flat,
             std::size_t i)
      : nodes_(nodes), joins_(joins), judge_(judge), flat_(flat), i_(i), h_((i + nodes.size() - 1) % nodes.size()),
        j_((i + 1) % nodes.size()) {
    for (const std::size_t k : {h_, i_})
      if (joins.is_cubic(k)) cubics_.push_back(k);
    for (const std::size_t k : cubics_) {
      const CubicTraits &a = judge.unrounded(k), &b = judge.traits(k, outline_cubic(nodes, k));
      most_.push_back({judge.inflections_added(k, b), std::max(a.extrema.all, b.extrema.all),
                       std::max(a.overreach, b.overreach), std::max(a.turning, b.turning)});
    }
    // The cubics beyond the neighbours stay as they are: their curvature there, once.
    const std::size_t n = nodes.size();
    for (const std::size_t k : {h_, i_, j_})
      if (judge.inflects_at(k) && !(k == j_ && j_ == h_)) inflection_nodes_.push_back(k);
    if (n >= 4) {
      if (joins.joins_cubics(h_)) beyond_h_ = node_curvature(outline_cubic(nodes, (h_ + n - 1) % n), SegmentEnd::end);
      if (joins.joins_cubics(j_)) beyond_j_ = node_curvature(outline_cubic(nodes, j_), SegmentEnd::start);
    }
  }

  /// The jump costs at node i and its neighbours, as the outline stands.
  double jump_costs() const {
    const std::array<double, 3> j = jumps_now();
    return jump_cost(j[0]) + jump_cost(j[1]) + jump_cost(j[2]);
  }
  /// What either cubic at i costs for an inflection, a bend the other way, a curvature
  /// extremum or curvature variation its unrounded self lacks, as the cubic choice weighs them
  /// (a nearly straight cubic whose rounded ends leave its chord outside their tangents can
  /// only be an S).
  double bend_cost() const { return inflections_cost() + shapes_cost(); }
  /// Both.
  double cost() const { return jump_costs() + bend_cost(); }
  /// cost() where it is under `best` and the outline as it stands is an allowed change: the
  /// jumps first, the cubics' shapes only where the jumps leave room.
  std::optional<double> cost_under(double best) const {
    const double jumps = jump_costs();
    if (jumps >= best) return std::nullopt;
    const double c = jumps + bend_cost();
    if (c >= best || !allowed()) return std::nullopt;
    return c;
  }
  /// Whether either cubic bends the wrong way, or any of those jumps is over the target.
  bool needs_change() const {
    const std::array<double, 3> j = jumps_now();
    return inflections_cost() >= wrong_way ||
           std::any_of(j.begin(), j.end(), [](double x) { return jump_cost(x) > target_jump * target_jump; });
  }

 private:
  // Whether the outline as it stands is an allowed change.
  bool allowed() const {
    for (std::size_t side = 0; side < cubics_.size(); ++side) {
      const std::size_t k = cubics_[side];
      const CubicTraits& t = judge_.traits(k, outline_cubic(nodes_, k));
      const Most& most = most_[side];
      if (!t.within || judge_.inflections_added(k, t) > most.inflections || t.extrema.all > most.extrema ||
          t.overreach > most.overreach || t.turning > most.turning + fold_turn)
        return false;
    }
    return true;
  }

  // What the inflections cost as the cubic choice weighs them: those either cubic at i adds
  // inside, and what happens at the inflection nodes among i and its neighbours.
  double inflections_cost() const {
    const std::size_t n = nodes_.size();
    const auto traits = [&](std::size_t k) -> const CubicTraits& { return judge_.traits(k, outline_cubic(nodes_, k)); };
    double cost = 0.0;
    for (const std::size_t k : cubics_) cost += judge_.inflections_added(k, traits(k)) > 0 ? wrong_way : 0.0;
    for (const std::size_t k : inflection_nodes_) {
      const std::size_t before = (k + n - 1) % n;
      cost += wrong_way * judge_.inflections_at_node(before, traits(before), k, traits(k)).added;
    }
    return cost;
  }

  // shape_cost of both cubics at i, as the cubic choice weighs them: without the variation, a
  // nudge that left every jump as it was could trade a cubic's κ·UPM of 5 at the node for a
  // spike of 667 (EB Garamond's P, where its bowl meets the stem).
  double shapes_cost() const {
    double cost = 0.0;
    for (const std::size_t k : cubics_)
      cost += shape_cost(judge_.traits(k, outline_cubic(nodes_, k)).shape, judge_.unrounded(k).shape, flat_);
    return cost;
  }

  // The jumps at the neighbour before, at node i (none at a corner) and at the neighbour after (join_jump, with
  // only the two cubics at i evaluated where the contour has room).
  std::array<double, 3> jumps_now() const {
    if (nodes_.size() < 4) return {join_jump(joins_, h_, flat_), join_jump(joins_, i_, flat_), join_jump(joins_, j_, flat_)};
    // A side that is a line (a corner's) changes nothing at its far end.
    const auto curvature = [&](std::size_t cubic, SegmentEnd end) -> std::optional<double> {
      if (!joins_.is_cubic(cubic)) return std::nullopt;
      return node_curvature(outline_cubic(nodes_, cubic), end);
    };
    const std::optional<double> ks_h = curvature(h_, SegmentEnd::start), ke_h = curvature(h_, SegmentEnd::end);
    const std::optional<double> ks_i = curvature(i_, SegmentEnd::start), ke_i = curvature(i_, SegmentEnd::end);
    const auto at_end = [&](std::size_t k, std::optional<double> beyond, std::optional<double> near) {
      if (!near) return 0.0;
      if (beyond) return jump(*beyond, *near, flat_);
      return joins_.meets_line(k) ? jump(*near, 0.0, flat_) : 0.0;
    };
    const double at_i = joins_.joins_cubics(i_) ? jump(*ke_h, *ks_i, flat_) : 0.0;  // a corner has none
    return {at_end(h_, beyond_h_, ks_h), at_i, at_end(j_, beyond_j_, ke_i)};
  }

  const std::vector<OutlineNode>& nodes_;
  const OutlineJoins& joins_;
  CubicJudge& judge_;
  double flat_;
  std::size_t i_, h_, j_;
  std::optional<double> beyond_h_, beyond_j_;
  std::vector<std::size_t> inflection_nodes_;  ///< of h, i and j, those CubicJudge::inflects_at
  std::vector<std::size_t> cubics_;  ///< the cubics at i: before it (h) and after it, where they are cubics
  // Per cubic at i, the most of each fault its unrounded self or its state before the change has.
  struct Most {
    int inflections, extrema;  ///< inflections: CubicJudge::inflections_added
    double overreach, turning;
  };
  std::vector<Most> most_;
};

// The primitive grid directions within `most` radians of `tangent`, no component over `longest`.
std::vector<Vec2> directions_near(Vec2 tangent, double most, int longest) {
  const Vec2 t = tangent / norm(tangent);
  std::vector<Vec2> out;
  for (int x = -longest; x <= longest; ++x)
    for (int y = -longest; y <= longest; ++y) {
      const Vec2 d{double(x), double(y)};
      if (!is_primitive(d) || dot(d, t) <= 0.0) continue;
      if (std::abs(turning_angle(t, d)) <= most) out.push_back(d);
    }
  return out;
}

// The directions node i may take on the grid: its own step and, where that is not horizontal or
// vertical (an extremum's must stay so), the primitive directions within `turn` of its
// unrounded tangent, only of at most `longest` units a side: whole steps of a longer one are too
// coarse to set curvature by (and each direction costs a search).
std::vector<Vec2> node_directions(Vec2 step, const OutlineNode& target, int longest = 10) {
  std::vector<Vec2> directions{step};
  if (step.x != 0.0 && step.y != 0.0)
    for (const Vec2 d : directions_near(*target.out_handle - *target.in_handle, turn, longest))
      if (d != step && d.x != 0.0 && d.y != 0.0) directions.push_back(d);
  return directions;
}

// Where whole steps alone leave a jump, the node itself may move a unit (its handles with it,
// G1 stays exact) and its two handles a step or three: the curvatures of both its cubics
// change at both their ends, so the jumps at the two neighbours count too. A node whose
// direction is not horizontal or vertical (an extremum's must stay so) may also turn to a
// primitive direction within `turn` of its unrounded tangent, its handles as long as there.
// Only the nodes `candidates` lists are tried; returns those it moved (a turn in `steps`).
std::vector<std::size_t> nudge_jumping_nodes(std::vector<OutlineNode>& nodes, const std::vector<OutlineNode>& ideal,
                                             std::vector<std::optional<Vec2>>& steps, const OutlineJoins& joins,
                                             std::span<const std::size_t> candidates, CubicJudge& judge, double flat) {
  std::vector<std::size_t> nudged;
  for (const std::size_t i : candidates) {
    if (!joins.joins_cubics(i) || !steps[i]) continue;
    const NodeChange change(nodes, joins, judge, flat, i);
    if (!change.needs_change()) continue;
    const OutlineNode kept = nodes[i];
    const OutlineNode& target = ideal[i];
    const std::vector<Vec2> directions = node_directions(*steps[i], target);
    OutlineNode best = kept;
    Vec2 best_step = *steps[i];
    double best_cost = change.cost();
    for (const Vec2 d : directions) {
      if (d != *steps[i] && best_cost <= 3.0 * target_jump * target_jump) break;  // turned only while still jumping
      const OutlineNode& from = d == *steps[i] ? kept : target;  // a turned node's handles as long as unrounded
      const double m_in = std::max(1.0, whole_steps(from.point, *from.in_handle, d, -1.0));
      const double m_out = std::max(1.0, whole_steps(from.point, *from.out_handle, d, 1.0));
      // Still on a grid point next to the nearest one, as rounding placed every node.
      for (const Vec2 p : node_places(kept.point, target.point))
        for (int a = -reach; a <= reach; ++a)
          for (int b = -reach; b <= reach; ++b) {
            if (m_in + a < 1.0 || m_out + b < 1.0) continue;
            nodes[i].point = p;
            nodes[i].in_handle = p - d * (m_in + a);
            nodes[i].out_handle = p + d * (m_out + b);
            if (const std::optional<double> c = change.cost_under(best_cost)) best_cost = *c, best = nodes[i], best_step = d;
          }
    }
    nodes[i] = best;
    steps[i] = best_step;
    if (best != kept) nudged.push_back(i);
  }
  return nudged;
}

// The handle of `node` (an out-handle when sign is +1) exactly on the line through p along d,
// on the side of p that handle faces (behind p for an out-handle of the node before it): for a
// smooth node a whole number m ≥ 1 of its steps from it, where the line crosses its handle line
// there; for a corner, the grid point of the line nearest where its handle is.
std::optional<Vec2> handle_on_line(const OutlineNode& node, std::optional<Vec2> step, double sign, Vec2 p, Vec2 d) {
  std::optional<Vec2> h;
  if (!node.smooth) {
    const Vec2 now = sign > 0.0 ? *node.out_handle : *node.in_handle;
    h = p + d * whole_steps(p, now, d, 1.0);
  } else if (step) {
    const std::optional<double> m = steps_to_line(node.point, *step, sign, p, d);
    if (m && *m >= 1.0 && *m == std::round(*m)) h = node.point + *step * (sign * *m);
  }
  if (h && -sign * dot(*h - p, d) <= 0.0) return std::nullopt;
  return h;
}

// Whether node i (joining cubics h and i) is to be flat on the grid: it was before rounding (an
// inflection), or rounding left one side of it flat (that cubic's far handle on the node's
// tangent line) and the other not. A curvature of κ·UPM 5 (UPM 1000) at a 5-unit handle wants
// its far handle a fifth of a unit off the tangent; whole units give 0 there, and the other
// side, its far handle a unit off, some multiple of it (EB Garamond a–z A–Z: 221 of its 486
// jumps were so).
// `rounded`: its two curvatures on the grid now (curvatures_at).
bool flat_node(const CubicJudge& judge, std::size_t h, std::size_t i, std::pair<double, double> rounded, double flat) {
  if (std::abs(judge.unrounded(h).k_end) < flat && std::abs(judge.unrounded(i).k_start) < flat) return true;
  return std::min(std::abs(rounded.first), std::abs(rounded.second)) < flat;
}

// A flat node (flat_node: an inflection, or a node rounding left flat on one side) keeps κ = 0
// on the grid only where both far handles lie exactly on its tangent line, and each is a
// whole number of its own node's steps from that node: the tangent line must cross both their
// handle lines at whole steps. Where the node still jumps, the grid points next to it and the
// primitive directions within `turn` of its tangent are tried for one whose line does; the far
// handles go there and the node's own handles, whose lengths set its neighbours' curvature, a
// step or three either way. Returns the nodes it moved (its direction changed in `steps`).
std::vector<std::size_t> seat_flat_nodes(std::vector<OutlineNode>& nodes, const std::vector<OutlineNode>& ideal,
                                         std::vector<std::optional<Vec2>>& steps, const OutlineJoins& joins,
                                         std::span<const std::size_t> candidates, CubicJudge& judge, double flat) {
  const std::size_t n = nodes.size();
  std::vector<std::size_t> seated;
  for (const std::size_t i : candidates) {
    const std::size_t h = (i + n - 1) % n, j = (i + 1) % n;
    if (!joins.joins_cubics(i) || !steps[i]) continue;
    const std::pair<double, double> rounded = curvatures_at(nodes, i);
    // An inflection the choices moved off the node (a flip at one side's end, no jump) is
    // seated too, weighed as a jump just over the target: its places on the grid come before
    // a hair of the other bend (each is κ = 0 from both sides).
    const CubicTraits& before = judge.traits(h, outline_cubic(nodes, h));
    const CubicTraits& after = judge.traits(i, outline_cubic(nodes, i));
    const bool moved_off = judge.inflections_at_node(h, before, i, after).moved;
    const bool jumps = jump(rounded.first, rounded.second, flat) > target_jump;
    if (!(jumps || moved_off) || !flat_node(judge, h, i, rounded, flat)) continue;
    const NodeChange change(nodes, joins, judge, flat, i);
    const OutlineNode kept = nodes[i], kept_h = nodes[h], kept_j = nodes[j];
    const OutlineNode& target = ideal[i];
    double best_cost = change.cost() + (moved_off ? moved_inflection_cost : 0.0);
    std::optional<std::array<OutlineNode, 3>> best;
    std::optional<Vec2> best_step;
    for (const Vec2 d : directions_near(*target.out_handle - *target.in_handle, turn, 16))
      for (const Vec2 p : node_places(kept.point, target.point)) {
        const std::optional<Vec2> far_in = handle_on_line(kept_h, steps[h], 1.0, p, d);
        const std::optional<Vec2> far_out = handle_on_line(kept_j, steps[j], -1.0, p, d);
        if (!far_in || !far_out) continue;
        nodes[h].out_handle = far_in, nodes[j].in_handle = far_out, nodes[i].point = p;
        const double m_in = std::max(1.0, whole_steps(target.point, *target.in_handle, d, -1.0));
        const double m_out = std::max(1.0, whole_steps(target.point, *target.out_handle, d, 1.0));
        for (int a = -reach; a <= reach; ++a)
          for (int b = -reach; b <= reach; ++b) {
            if (m_in + a < 1.0 || m_out + b < 1.0) continue;
            nodes[i].in_handle = p - d * (m_in + a);
            nodes[i].out_handle = p + d * (m_out + b);
            if (const std::optional<double> c = change.cost_under(best_cost))
              best_cost = *c, best = {nodes[h], nodes[i], nodes[j]}, best_step = d;
          }
      }
    nodes[h] = kept_h, nodes[i] = kept, nodes[j] = kept_j;
    if (!best) continue;
    nodes[h] = (*best)[0], nodes[i] = (*best)[1], nodes[j] = (*best)[2];
    steps[i] = best_step;
    seated.push_back(i);
  }
  return seated;
}

// Which neighbour of node i is a line join still jumping past the target, across a cubic from
// i: the one before (the cubic arriving at i starts on the line; that first) or the one after.
// None where neither is (a corner with a line on one side has its line join, if any, across
// that line, not across a cubic).
struct JumpingLineJoin {
  std::size_t at;  ///< the join's node
  bool before;     ///< whether it is node i's neighbour before
};
std::optional<JumpingLineJoin> jumping_line_join(const OutlineJoins& joins, std::size_t i, double flat) {
  const std::size_t n = joins.size(), h = (i + n - 1) % n, j = (i + 1) % n;
  if (joins.is_cubic(h) && joins.meets_line(h) && join_jump(joins, h, flat) > target_jump) return JumpingLineJoin{h, true};
  if (joins.is_cubic(i) && joins.meets_line(j) && join_jump(joins, j, flat) > target_jump) return JumpingLineJoin{j, false};
  return std::nullopt;
}

// A curve leaving a line keeps κ = 0 at the join on the grid only where its far handle lies
// exactly on the line, a whole number of the far node's steps from that node; along a diagonal
// line the far node's own direction seldom crosses it at one (Comic Neue's K: a 22-unit cap
// left its line with κ·UPM 18). Where such a join still jumps, its far node, one joining two
// cubics, is tried at the grid points up to two units from its own (a line of step (3, −4)
// passes a whole step of a horizontal handle every four units of height: Lato's c, whose cap
// seats two units down) and, unless it is an extremum, in the primitive
// directions within `turn` of its tangent, for one whose handle line crosses the line at a whole
// step on its side of the join; that handle goes there, the node's other handle a step or three
// either way. Returns the nodes it moved (their directions changed in `steps`).
std::vector<std::size_t> seat_line_joins(std::vector<OutlineNode>& nodes, const std::vector<OutlineNode>& ideal,
                                         std::vector<std::optional<Vec2>>& steps, const OutlineJoins& joins,
                                         std::span<const std::size_t> candidates, CubicJudge& judge, double flat) {
  std::vector<std::size_t> seated;
  for (const std::size_t i : candidates) {
    if (!joins.joins_cubics(i) || !steps[i]) continue;
    // The join on the line: before i (its cubic arrives at i) or after it; sign is i's handle's.
    const std::optional<JumpingLineJoin> line_join = jumping_line_join(joins, i, flat);
    if (!line_join) continue;
    const bool before = line_join->before;
    const OutlineNode& join = nodes[line_join->at];
    // The join's tangent, in the contour's direction (h → i → j).
    const Vec2 into = before ? *join.out_handle - join.point : join.point - *join.in_handle;
    const double sign = before ? -1.0 : 1.0;
    const NodeChange change(nodes, joins, judge, flat, i);
    const OutlineNode kept = nodes[i];
    const OutlineNode& target = ideal[i];
    // The far handle of the cubic on i's other side, a step or three either way along its own
    // node's direction (a corner's stays): moved across its tangent, node i changes that cubic's
    // curvature at i as much as the line join's (Lato's c: its cap's top two units down).
    const std::size_t far = before ? (i + 1) % nodes.size() : (i + nodes.size() - 1) % nodes.size();
    std::optional<Vec2>& far_handle = before ? nodes[far].in_handle : nodes[far].out_handle;
    const Vec2 kept_far = *far_handle;
    const std::vector<Vec2> fars =
        steps[far] ? handle_candidates(nodes[far], steps[far], !before) : std::vector<Vec2>{kept_far};
    double best_cost = change.cost();
    std::optional<std::pair<OutlineNode, Vec2>> best;
    std::optional<Vec2> best_step;
    // Sides up to 16: only a step that lands on the line is taken, not one set by curvature.
    for (const Vec2 d : node_directions(*steps[i], target, 16))
      for (const Vec2 p : node_places(kept.point, target.point, 2)) {
        const std::optional<double> m = steps_to_line(p, d, sign, join.point, into);
        if (!m || *m < 1.0 || *m != std::round(*m)) continue;
        const Vec2 on_line = p + d * (sign * *m);
        if (sign * dot(on_line - join.point, into) >= 0.0) continue;  // on i's side of the join
        const Vec2 other = before ? *target.out_handle : *target.in_handle;
        const double m_other = std::max(1.0, whole_steps(target.point, other, d, -sign));
        nodes[i].point = p;
        (before ? nodes[i].in_handle : nodes[i].out_handle) = on_line;
        for (int b = -reach; b <= reach; ++b) {
          if (m_other + b < 1.0) continue;
          (before ? nodes[i].out_handle : nodes[i].in_handle) = p - d * (sign * (m_other + b));
          for (const Vec2 f : fars) {
            far_handle = f;
            if (const std::optional<double> c = change.cost_under(best_cost))
              best_cost = *c, best = {nodes[i], f}, best_step = d;
          }
        }
      }
    nodes[i] = best ? best->first : kept;
    far_handle = best ? best->second : kept_far;
    if (!best) continue;
    steps[i] = best_step;
    seated.push_back(i);
  }
  return seated;
}

// A curve whose far handle misses its line leaves the line with κ = (2/3)·d/h² (d the far
// handle's offset from the line, h the near handle's length), and on a slanted line the grid
// sets d in multiples of 1/|step|: Lato's A, whose feet leave the legs' lines of step (−9, 23)
// with κ·UPM 0.066 on two-step handles; Pagella's serifs, stepping (16, 1), with 0.16 on one.
// Where such a join still jumps, its node slides back along the line by one to three of the
// line's steps, the near handle's tip kept: the curve leaves the line where it did, straight,
// only sooner, and its handle grows by as many steps. Pass after pass, a join stays within
// twice its cubic's chord of where the passes found it (`entry`): unbounded, Comic Neue's u had
// a step of (1, 56) slide a short cap 56 units down its stem, which strayed and cost the
// contour eight roundings more, and Gentium's M a bracket of 89 units crawl 600 units up its
// stem; within one chord, Lato's M stopped a step short of where its cap's curve leaves the leg
// flat enough (slide_reach). The line keeps half its length at least. Returns the first node of
// each cubic it changed.
std::vector<std::size_t> slide_line_joins(std::vector<OutlineNode>& nodes, std::span<const OutlineNode> entry,
                                          std::span<const std::optional<Vec2>> steps, const OutlineJoins& joins,
                                          CubicJudge& judge, double flat) {
  const std::size_t n = nodes.size();
  std::vector<std::size_t> slid;
  if (n < 4) return slid;
  for (std::size_t at = 0; at < n; ++at) {
    if (!joins.meets_line(at) || !steps[at] || join_jump(joins, at, flat) <= target_jump) continue;
    const bool leaves = joins.is_cubic(at);  // the cubic leaves the join, the line arrives
    const std::size_t far = leaves ? (at + 1) % n : (at + n - 1) % n;  // the cubic's other node
    const std::size_t first = leaves ? at : far;                        // the cubic's first node
    const NodeChange change(nodes, joins, judge, flat, far);
    const Vec2 line_end = nodes[leaves ? (at + n - 1) % n : (at + 1) % n].point;
    const Vec2 kept = nodes[at].point, back = *steps[at] * (leaves ? -1.0 : 1.0);
    const double line_length = distance(kept, line_end);
    const Vec2 start = entry[at].point;
    const double chord = distance(start, entry[far].point);
    double best_cost = change.cost();
    std::optional<Vec2> best;
    for (int k = 1; k <= 3; ++k) {
      const Vec2 p = kept + back * static_cast<double>(k);
      if (distance(p, start) > slide_reach * chord || distance(p, line_end) < 0.5 * line_length ||
          dot(p - line_end, kept - line_end) <= 0.0)
        break;
      nodes[at].point = p;
      if (const std::optional<double> c = change.cost_under(best_cost)) best_cost = *c, best = p;
    }
    nodes[at].point = best ? *best : kept;
    if (best) slid.push_back(first);
  }
  return slid;
}

// A corner whose cubic meets a line at the far end keeps no grid direction: its handle may go
// to any grid point, and cubic_choices offers the line's whole step nearest it, where κ = 0 at
// the join. Where that moves the cubic too far (DejaVu Serif's R: the leg's corner 1.81 units
// against an allowance of 1.71), the corner is tried at the grid points up to two units from
// its own, its handle at the line's whole steps up to two either side, its other handle where
// it is; it must still turn by the kink limit (or as little as it did). `corners`: interior
// corners at a cubic (choose_handle_steps lists them); since stop 65 also those with a line on
// the other side (Caladea's v, x and y: a serif's curve from its stroke's line to the serif's
// end kept κ·UPM 0.5–0.9 at the join), such a corner moving only where that line's other end
// is a corner too. Each corner is tried
// once: a tried one leaves `corners` (again every pass, it cost Because We Learn's a–z A–Z 3 %
// more time for nothing). Returns the corners moved.
std::vector<std::size_t> seat_line_joins_at_corners(std::vector<OutlineNode>& nodes, const std::vector<OutlineNode>& ideal,
                                                    std::span<const std::optional<Vec2>> steps, const OutlineJoins& joins,
                                                    std::vector<std::size_t>& corners, CubicJudge& judge, double flat) {
  const std::size_t n = nodes.size();
  std::vector<std::size_t> seated;
  if (n < 3) return seated;
  std::vector<std::size_t> untried;
  for (const std::size_t i : corners) {
    const std::size_t h = (i + n - 1) % n, j = (i + 1) % n;
    // The join on the line: at the start of the cubic arriving at i, or at the end of the one leaving it.
    const std::optional<JumpingLineJoin> line_join = jumping_line_join(joins, i, flat);
    if (!line_join || !steps[line_join->at]) {
      untried.push_back(i);
      continue;
    }
    const bool before = line_join->before;
    const std::size_t at = line_join->at;
    const Vec2 join = nodes[at].point, line_far = nodes[before ? (h + n - 1) % n : (j + 1) % n].point;
    const double least_turn = std::min(kink_limit, turn_at(ideal, joins.closed, i));
    const NodeChange change(nodes, joins, judge, flat, i);
    const OutlineNode kept = nodes[i];
    double best_cost = change.cost();
    std::optional<OutlineNode> best;
    std::optional<Vec2>& handle = before ? nodes[i].in_handle : nodes[i].out_handle;
    const double nearest = whole_steps(join, before ? *kept.in_handle : *kept.out_handle, *steps[at], 1.0);
    // A corner at a line is that line's end too: it stays where the line's other end is smooth,
    // whose G1 a turned line would break.
    const bool line_before = !joins.is_cubic(h), line_after = !joins.is_cubic(i);
    const bool held = (line_before && nodes[h].smooth) || (line_after && nodes[j].smooth);
    for (const Vec2 p : held ? std::vector<Vec2>{kept.point} : node_places(kept.point, ideal[i].point, 2))
      for (double m = nearest - 2.0; m <= nearest + 2.0; ++m) {
        const Vec2 on_line = join + *steps[at] * m;
        if (dot(on_line - join, line_far - join) >= 0.0) continue;  // on the cubic's side of the join
        nodes[i].point = p;
        handle = on_line;
        if (turn_at(nodes, joins.closed, i) < least_turn) continue;
        if (const std::optional<double> c = change.cost_under(best_cost)) best_cost = *c, best = nodes[i];
      }
    nodes[i] = best ? *best : kept;
    if (best) seated.push_back(i);
  }
  corners = std::move(untried);
  return seated;
}

// The whole steps of one run of cubics joined at smooth nodes (the nodes starting them, in
// order), chosen together (Viterbi; a run that closes on itself with each state of its first
// cubic in turn): the choices and the cheapest states.
struct RunSteps {
  std::vector<CubicChoices> run;
  RunChoice best;
};

// For a run that closes on itself, the least each state of its first cubic can cost: its own
// cost, the cheapest path from it through the last cubic and the cheapest join back to it from
// any state of the last, the turns at the nodes left out (they cost nothing or more).
std::vector<double> first_state_bounds(const std::vector<CubicChoices>& run, const CubicJudge& judge, double flat) {
  std::vector<double> after = run.back().cost;  // the cheapest path from each state to the end
  for (std::size_t k = run.size() - 1; k > 0; --k) {
    const CubicChoices &prev = run[k - 1], &cur = run[k];
    const std::vector<std::size_t> order = cheapest_first(after);
    std::vector<double> here(prev.states(), infeasible);
    for (std::size_t s = 0; s < prev.states(); ++s) {
      if (prev.cost[s] == infeasible) continue;
      double least = infeasible;
      for (const std::size_t t : order) {
        if (after[t] >= least) break;  // a join only adds
        least = std::min(least, after[t] + join_cost(judge, prev, s, cur, t, flat));
      }
      here[s] = prev.cost[s] + least;
    }
    after = std::move(here);
  }
  // And the cheapest join back from the last cubic, whatever its state.
  const CubicChoices &first = run.front(), &last = run.back();
  for (std::size_t s = 0; s < first.states(); ++s) {
    if (after[s] == infeasible) continue;
    double least = infeasible;
    for (std::size_t t = 0; t < last.states(); ++t)
      if (last.cost[t] != infeasible)
        least = std::min(least, join_cost(judge, last, t, first, s, flat));
    after[s] += least;
  }
  return after;
}

// The cheapest states of a run that closes on itself: each first state in turn, in the order of
// the least its run can cost, until that is past the cheapest run found (no later one can win);
// a tie goes to the lower first state, as in index order. Every first state, in index order,
// took 60 % of the time of DejaVu Sans's a–z A–Z under G3; in this order 5.6 of 85 are solved,
// and the whole takes 43 % less.
RunChoice best_cycle(const std::vector<CubicChoices>& run, const CubicJudge& judge, double flat) {
  RunChoice best;
  const std::vector<double> bound = first_state_bounds(run, judge, flat);
  std::size_t best_first = 0;
  for (const std::size_t first : cheapest_first(bound)) {
    // The bound adds the run's terms in another order: a margin for the last bits.
    if (bound[first] == infeasible || (best.cost != infeasible && bound[first] > best.cost * (1.0 + 1e-9) + 1e-9))
      break;
    RunChoice c = best_run(run, judge, flat, first);
    if (c.cost < best.cost || (c.cost == best.cost && c.cost != infeasible && first < best_first))
      best = std::move(c), best_first = first;
  }
  return best;
}

RunSteps best_run_steps(const std::vector<OutlineNode>& nodes, std::span<const std::optional<Vec2>> steps,
                        const OutlineJoins& joins, std::span<const std::size_t> cubics, bool cycle, CubicJudge& judge,
                        double flat) {
  const std::size_t n = nodes.size();
  std::vector<CubicChoices> run;
  for (const std::size_t i : cubics) {
    const std::size_t j = (i + 1) % n;
    run.push_back(cubic_choices(nodes, steps, i, j, judge, flat, joins.meets_line(i), joins.meets_line(j)));
  }
  RunChoice best = cycle ? best_cycle(run, judge, flat) : best_run(run, judge, flat, std::nullopt);
  return {std::move(run), std::move(best)};
}

// The handles set to the cheapest states (none where every state is infeasible). Returns
// whether any handle moved.
bool apply_steps(std::vector<OutlineNode>& nodes, const RunSteps& chosen) {
  if (chosen.best.cost == infeasible) return false;
  bool moved = false;
  for (std::size_t k = 0; k < chosen.run.size(); ++k) {
    const CubicChoices& c = chosen.run[k];
    const std::size_t state = chosen.best.states[k];
    const Vec2 out = c.outs[state / c.ins.size()], in = c.ins[state % c.ins.size()];
    moved = moved || nodes[c.start].out_handle != out || nodes[c.end].in_handle != in;
    nodes[c.start].out_handle = out;
    nodes[c.end].in_handle = in;
  }
  return moved;
}

// The run's handles set to the cheapest states. Returns whether any handle moved.
bool choose_run_steps(std::vector<OutlineNode>& nodes, std::span<const std::optional<Vec2>> steps,
                      const OutlineJoins& joins, std::span<const std::size_t> cubics, bool cycle, CubicJudge& judge,
                      double flat) {
  return apply_steps(nodes, best_run_steps(nodes, steps, joins, cubics, cycle, judge, flat));
}

// The cubics of a run around one node, re-chosen while that node is tried in other places:
// three cubics either side of it, between the fixed cubics next to them (whose curvature at the
// window's ends still counts); the whole run where it is that short. Three against two: dkg's
// a–z A–Z g2-jumps 1.97 → 1.62 % for 0.6 % more instructions; one: 2.44 %.
struct RunWindow {
  std::vector<std::size_t> cubics;  ///< node indices starting the cubics re-chosen
  std::optional<std::size_t> before, after;  ///< the fixed cubics at its ends
  bool whole_cycle = false;                  ///< the whole of a run that closes on itself
};

RunWindow window_around(std::span<const std::size_t> run, bool cycle, std::size_t position) {
  constexpr std::size_t side = 3;
  const std::size_t m = run.size();
  RunWindow w;
  if (cycle && m <= 2 * side + 2) {
    w.cubics.assign(run.begin(), run.end());
    w.whole_cycle = true;
    return w;
  }
  const std::ptrdiff_t size = static_cast<std::ptrdiff_t>(m);
  const auto at = [&](std::ptrdiff_t k) -> std::optional<std::size_t> {
    if (cycle) return run[static_cast<std::size_t>((k % size + size) % size)];
    if (k < 0 || k >= size) return std::nullopt;
    return run[static_cast<std::size_t>(k)];
  };
  const std::ptrdiff_t q = static_cast<std::ptrdiff_t>(position), s = static_cast<std::ptrdiff_t>(side);
  for (std::ptrdiff_t k = q - s; k < q + s; ++k)
    if (const auto c = at(k)) w.cubics.push_back(*c);
  w.before = at(q - s - 1), w.after = at(q + s);
  return w;
}

// The cheapest handles of the window's cubics with its nodes where they are now (the fixed end
// cubics first and last in `run`, one state each); the choices of cubics not touching node
// `moving` reused from `known` (the same window with that node elsewhere) when given.
RunSteps choose_window(const std::vector<OutlineNode>& nodes, std::span<const std::optional<Vec2>> steps,
                       const OutlineJoins& joins, const RunWindow& w, CubicJudge& judge, double flat,
                       std::size_t moving, const RunSteps* known = nullptr) {
  const std::size_t n = nodes.size();
  std::vector<std::pair<std::size_t, bool>> cubics;  // each cubic, and whether it stays as it is
  if (w.before) cubics.emplace_back(*w.before, true);
  for (const std::size_t i : w.cubics) cubics.emplace_back(i, false);
  if (w.after) cubics.emplace_back(*w.after, true);
  RunSteps out;
  for (const auto& [i, as_is] : cubics) {
    const std::size_t j = (i + 1) % n;
    const bool touches = i == moving || j == moving;
    out.run.push_back(known && !touches ? known->run[out.run.size()]
                                        : cubic_choices(nodes, steps, i, j, judge, flat, joins.meets_line(i),
                                                        joins.meets_line(j), as_is));
  }
  out.best = w.whole_cycle ? best_cycle(out.run, judge, flat) : best_run(out.run, judge, flat, std::nullopt);
  return out;
}

// CubicJudge::turns_too_often at node i of the outline as it stands.
bool turns_too_often(const std::vector<OutlineNode>& nodes, const OutlineJoins& joins, CubicJudge& judge, std::size_t i) {
  if (!judge.node_turns() || !joins.joins_cubics(i)) return false;
  const std::size_t h = (i + nodes.size() - 1) % nodes.size();
  return judge.turns_too_often(h, judge.traits(h, outline_cubic(nodes, h)), i, judge.traits(i, outline_cubic(nodes, i)));
}

// Whether dκ/ds jumps at node i of the outline as it stands by more than the target (under
// HandleStepLimits::slope_jump_weight; never otherwise).
bool slope_jumps(const std::vector<OutlineNode>& nodes, const OutlineJoins& joins, CubicJudge& judge, std::size_t i) {
  if (!judge.match_slopes() || !joins.joins_cubics(i)) return false;
  const std::size_t h = (i + nodes.size() - 1) % nodes.size();
  return judge.slope_cost(judge.traits(h, outline_cubic(nodes, h)), judge.traits(i, outline_cubic(nodes, i))) > 0.0;
}

// Whether node + sign·m·d (sign +1 towards a join after the node, −1 before it) lies exactly on
// the line through `join` along `line_dir` for some whole m ≥ 1.
bool lands_on_line(Vec2 node, Vec2 d, bool join_after, Vec2 join, Vec2 line_dir) {
  const std::optional<double> m = steps_to_line(node, d, join_after ? 1.0 : -1.0, join, line_dir);
  return m && *m >= 1.0 && *m == std::round(*m);
}

// Where a run still jumps once the passes end, or turns where it should not (turns_too_often):
// each node at a jump, or next to one (unless `only_at_jumps`: then only the far node of a
// line join that jumps, and only where its handle lands on the line), or turning so, moved to
// the grid points next to it and turned to the primitive directions near its tangent (its
// handles as many steps long as they were), with the handles of the cubics around it chosen
// again for each place (choose_window), so that a move which needs its neighbours' handles to
// follow is seen at its worth. The cheapest stands. Returns whether any node moved.
bool polish_jumping_run(std::vector<OutlineNode>& nodes, const std::vector<OutlineNode>& ideal,
                        std::vector<std::optional<Vec2>>& steps, const OutlineJoins& joins,
                        std::span<const std::size_t> cubics, bool cycle, CubicJudge& judge, double flat,
                        bool only_at_jumps) {
  bool moved = false;
  const std::size_t n = nodes.size();
  for (std::size_t q = 0; q < cubics.size(); ++q) {
    const std::size_t i = cubics[q];
    if (!joins.joins_cubics(i) || !steps[i]) continue;
    // Beside a jump; when `only_at_jumps`, only beside a line join that jumps, and then only to
    // where its handle lands on the line (the join itself, κ = 0 wanted where the curve leaves
    // the line, is no node to move: its far node is).
    const std::size_t next = (i + 1) % n, prev = (i + n - 1) % n;
    const bool next_jumps = join_jump(joins, next, flat) > target_jump, prev_jumps = join_jump(joins, prev, flat) > target_jump;
    const bool beside = !only_at_jumps && (next_jumps || prev_jumps);
    std::optional<std::size_t> line_join;
    if (only_at_jumps && next_jumps && joins.meets_line(next) && steps[next]) line_join = next;
    if (only_at_jumps && prev_jumps && joins.meets_line(prev) && steps[prev]) line_join = prev;
    const bool own = join_jump(joins, i, flat) > target_jump || turns_too_often(nodes, joins, judge, i) ||
                     slope_jumps(nodes, joins, judge, i);
    if (!own && !beside && !line_join) continue;
    const bool only_on_line = !own && !beside;
    const RunWindow window = window_around(cubics, cycle, q);
    const RunSteps now = choose_window(nodes, steps, joins, window, judge, flat, i);
    double best_cost = now.best.cost;
    const OutlineNode kept = nodes[i];
    const Vec2 kept_step = *steps[i];
    OutlineNode best = kept;
    Vec2 best_step = kept_step;
    std::optional<RunSteps> best_window;
    for (const Vec2 d : node_directions(kept_step, ideal[i])) {
      // Turned only while its own direction leaves a jump in the window (each costs at least 1).
      if (d != kept_step && best_cost < 1.0) break;
      const OutlineNode& from = d == kept_step ? kept : ideal[i];
      const double m_in = std::max(1.0, whole_steps(from.point, *from.in_handle, d, -1.0));
      const double m_out = std::max(1.0, whole_steps(from.point, *from.out_handle, d, 1.0));
      // Under G3, two units: dκ/ds at a cubic's end moves by tens of per cent a unit, and the
      // places a unit off left DejaVu Sans's median jump at 0.076 (0.049 with two, for 2.3 times
      // the time of a–z A–Z).
      std::vector<Vec2> places = node_places(kept.point, ideal[i].point, judge.match_slopes() ? 2 : 1);
      // Along its own direction by a step longer than a unit: both handles' tips can stay, and
      // with them a far handle seated on a line (TeX Gyre Heros's S).
      if (d == kept_step && std::max(std::abs(d.x), std::abs(d.y)) > 1.0)
        for (const double sign : {-1.0, 1.0}) places.push_back(kept.point + d * sign);
      for (const Vec2 p : places) {
        if (p == kept.point && d == kept_step) continue;
        if (only_on_line && !lands_on_line(p, d, *line_join == next, nodes[*line_join].point, *steps[*line_join])) continue;
        nodes[i].point = p;
        nodes[i].in_handle = p - d * m_in;
        nodes[i].out_handle = p + d * m_out;
        steps[i] = d;
        RunSteps tried = choose_window(nodes, steps, joins, window, judge, flat, i, &now);
        if (tried.best.cost < best_cost)
          best_cost = tried.best.cost, best = nodes[i], best_step = d, best_window = std::move(tried);
      }
    }
    nodes[i] = best;
    steps[i] = best_step;
    if (!best_window) continue;
    moved = true;
    apply_steps(nodes, *best_window);
  }
  return moved;
}

// The most placements of a bracket judged (nearest the unrounded bracket first): the Pagella
// serifs that take one take it among the first few.
constexpr std::size_t bracket_tries = 48;

// Two cubics of a run, from node h through node i to node j, of which h or j is a line join,
// that still jump once the passes end (a serif's bracket; in a longer run, the two next to its
// line; a curve from a line to a corner), placed as one piece (fair/bracket_placements.hpp):
// each line turned about its far corner or slid, an end inside the run kept with κ there to
// match the cubic beyond, a corner kept with its handle's direction, the node moved and turned,
// all handles set together; the cheapest allowed placement stands, where it costs less than the
// run as it is. Returns whether it moved.
bool place_bracket(std::vector<OutlineNode>& nodes, const std::vector<OutlineNode>& ideal,
                   std::vector<std::optional<Vec2>>& steps, const OutlineJoins& joins, std::size_t h, CubicJudge& judge,
                   double flat) {
  const std::size_t n = nodes.size(), i = (h + 1) % n, j = (i + 1) % n, before = (h + n - 1) % n, after = (j + 1) % n;
  // Each end's direction along the contour: a line's or node's step, a corner's handle's.
  const auto end_step = [&](std::size_t k) -> std::optional<Vec2> {
    if (nodes[k].smooth) return steps[k];
    return primitive_step(k == h ? *nodes[k].out_handle - nodes[k].point : nodes[k].point - *nodes[k].in_handle);
  };
  const std::optional<Vec2> step_h = end_step(h), step_j = end_step(j);
  if (n < 5 || !step_h || !steps[i] || !step_j) return false;
  // A line may turn about a far end that is a corner, where it is not horizontal or vertical;
  // that corner may go back to its nearest grid point where the line beyond it is horizontal or
  // vertical and stays so. A node inside the run stays, with the curvature beyond it.
  const auto end = [&](std::size_t join, std::size_t far, std::size_t beyond) -> std::variant<BracketLine, BracketNode> {
    const Vec2 step = join == h ? *step_h : *step_j;
    if (!joins.meets_line(join)) {
      if (!nodes[join].smooth) return BracketNode{nodes[join].point, step, std::nullopt};
      const double kappa = far == before ? curvatures_at(nodes, join).first : curvatures_at(nodes, join).second;
      return BracketNode{nodes[join].point, step, kappa};
    }
    const Vec2 d = ideal[far].point - ideal[join].point;
    BracketLine l{nodes[far].point, std::nullopt, nodes[join].point, step, ideal[far].point, ideal[join].point,
                  !nodes[far].smooth && d.x != 0.0 && d.y != 0.0};
    const Vec2 nearest = nearest_grid_point(ideal[far].point), other = nodes[beyond].point;
    const bool beyond_is_line = !(far == before ? joins.is_cubic(beyond) : joins.is_cubic(far));
    const bool stays_upright = (l.far.x == other.x && nearest.x == other.x) || (l.far.y == other.y && nearest.y == other.y);
    if (l.may_turn && beyond_is_line && stays_upright && nearest != l.far) l.far_alternative = nearest;
    return l;
  };
  const Bracket bracket{end(h, before, (before + n - 1) % n), end(j, after, (after + 1) % n),
                        {ideal[h].point, *ideal[h].out_handle, *ideal[i].in_handle, ideal[i].point,
                         *ideal[i].out_handle, *ideal[j].in_handle, ideal[j].point}};
  const std::vector<BracketPlacement> placements =
      bracket_placements(bracket, node_places(nodes[i].point, ideal[i].point, 2), node_directions(*steps[i], ideal[i]),
                         flat, target_jump, turn, bracket_tries);
  if (placements.empty()) return false;
  const NodeChange change(nodes, joins, judge, flat, i);
  // The far corners of lines turn no less than the kink limit, or than they did.
  const bool line_before = joins.meets_line(h), line_after = joins.meets_line(j);
  const double least_before = std::min(kink_limit, turn_at(ideal, joins.closed, before));
  const double least_after = std::min(kink_limit, turn_at(ideal, joins.closed, after));
  const std::array<OutlineNode, 5> kept{nodes[before], nodes[h], nodes[i], nodes[j], nodes[after]};
  double best_cost = change.cost();
  const BracketPlacement* best = nullptr;
  const auto place = [&](const BracketPlacement& p) {
    if (line_before) nodes[before].point = p.far1, nodes[h].point = p.join1;
    if (line_after) nodes[after].point = p.far2, nodes[j].point = p.join2;
    nodes[h].out_handle = p.handle1;
    nodes[i].point = p.node, nodes[i].in_handle = p.handle2, nodes[i].out_handle = p.handle3;
    nodes[j].in_handle = p.handle4;
  };
  for (const BracketPlacement& p : placements) {
    place(p);
    if ((line_before && turn_at(nodes, joins.closed, before) < least_before) ||
        (line_after && turn_at(nodes, joins.closed, after) < least_after))
      continue;
    if (const std::optional<double> c = change.cost_under(best_cost)) best_cost = *c, best = &p;
  }
  nodes[before] = kept[0], nodes[h] = kept[1], nodes[i] = kept[2], nodes[j] = kept[3], nodes[after] = kept[4];
  if (!best) return false;
  place(*best);
  if (line_before) steps[h] = best->step1;
  if (line_after) steps[j] = best->step2;
  steps[i] = best->node_step;
  return true;
}

}  // namespace

std::vector<Vec2> handles_near_line(Vec2 node, Vec2 step, double sign, Vec2 line_point, Vec2 line_dir) {
  const std::optional<double> m = steps_to_line(node, step, sign, line_point, line_dir);
  return m ? whole_steps_around(node, step, sign, *m) : std::vector<Vec2>{};
}

std::vector<Vec2> handles_for_curvature(Vec2 node, Vec2 step, bool out, Vec2 far, Vec2 other_end, double target) {
  const double length = norm(step);
  const Vec2 t = step / length;
  const double d = out ? cross(t, far - node) : cross(node - far, t);
  if (d * target <= 0.0) return {};
  const double m = std::sqrt(2.0 * d / (3.0 * target)) / length;
  if (m * length > 2.0 * distance(node, other_end)) return {};
  return whole_steps_around(node, step, out ? 1.0 : -1.0, m);
}

void choose_handle_steps(std::vector<OutlineNode>& nodes, const std::vector<OutlineNode>& ideal,
                         std::span<const std::optional<Vec2>> grid_steps, bool closed, const HandleStepLimits& limits) {
  // The grid steps as rounding left them; a node turned or seated here takes a new one.
  const std::size_t n = nodes.size();
  if (n < 2) return;
  const OutlineJoins joins{nodes, closed};

  // The runs of cubics joined at smooth nodes, each by the nodes starting its cubics.
  std::vector<std::vector<std::size_t>> runs;
  for (std::size_t i = 0; i < n; ++i)
    if (joins.is_cubic(i) && !joins.joins_cubics(i)) runs.push_back({i});
  const bool cycle = runs.empty();
  if (cycle && joins.is_cubic(0)) runs.push_back({0});
  if (runs.empty()) return;
  std::vector<std::size_t> run_of(n, runs.size());  // the run each node inside one belongs to
  if (cycle) run_of[0] = 0;                          // a run that closes on itself: its seam too
  std::vector<std::size_t> run_starting_at(n, runs.size());
  for (std::size_t r = 0; r < runs.size(); ++r) {
    run_starting_at[runs[r].front()] = r;
    for (std::size_t j = (runs[r].back() + 1) % n; joins.joins_cubics(j) && j != runs[r].front(); j = (j + 1) % n) {
      runs[r].push_back(j);
      run_of[j] = r;
    }
  }
  // The corners at a cubic, where a run starts or ends (seat_line_joins_at_corners).
  std::vector<std::size_t> corners;
  for (std::size_t i = 0; i < n; ++i)
    if (!nodes[i].smooth && joins.interior(i) && (joins.is_cubic(i) || joins.is_cubic((i + n - 1) % n))) corners.push_back(i);

  // A nudged node changes the curvature its neighbours' handles give (its handles are their
  // far handles), and the steps chosen are the centre of the next choice's reach: a run is
  // chosen again while it or a nudge changes it and a join of it still jumps.
  // The joins of a run (the one after its last cubic too) that jump.
  const auto jumps_in = [&](std::span<const std::size_t> run) {
    int count = join_jump(joins, (run.back() + 1) % n, limits.flat_curvature) > target_jump;
    for (const std::size_t k : run) count += join_jump(joins, k, limits.flat_curvature) > target_jump;
    return count;
  };
  const auto still_jumps = [&](std::span<const std::size_t> run) { return jumps_in(run) > 0; };
  CubicJudge judge(nodes, ideal, joins, limits);
  auto turns_too_often_in = [&](std::span<const std::size_t> run) {
    return std::any_of(run.begin(), run.end(), [&](std::size_t k) { return turns_too_often(nodes, joins, judge, k); });
  };
  std::vector<std::optional<Vec2>> steps(grid_steps.begin(), grid_steps.end());
  std::vector<bool> again(runs.size(), true);
  const std::vector<OutlineNode> entry = nodes;  // as the passes find them (slide_line_joins)
  for (int pass = 0; pass < max_passes; ++pass) {
    std::vector<std::size_t> inside;
    for (std::size_t r = 0; r < runs.size(); ++r) {
      if (!again[r]) continue;
      again[r] = choose_run_steps(nodes, steps, joins, runs[r], cycle, judge, limits.flat_curvature);
      inside.insert(inside.end(), runs[r].begin() + 1, runs[r].end());
      if (cycle) inside.push_back(runs[r].front());
    }
    std::sort(inside.begin(), inside.end());
    for (const std::size_t i : nudge_jumping_nodes(nodes, ideal, steps, joins, inside, judge, limits.flat_curvature))
      again[run_of[i]] = true;
    for (const std::size_t i : seat_flat_nodes(nodes, ideal, steps, joins, inside, judge, limits.flat_curvature))
      again[run_of[i]] = true;
    for (const std::size_t i : seat_line_joins(nodes, ideal, steps, joins, inside, judge, limits.flat_curvature))
      again[run_of[i]] = true;
    for (const std::size_t i : slide_line_joins(nodes, entry, steps, joins, judge, limits.flat_curvature))
      for (const std::size_t r : {run_of[i], run_starting_at[i]})
        if (r < runs.size()) again[r] = true;
    for (const std::size_t i : seat_line_joins_at_corners(nodes, ideal, steps, joins, corners, judge, limits.flat_curvature))
      for (const std::size_t r : {run_starting_at[i], run_of[(i + n - 1) % n], run_starting_at[(i + n - 1) % n]})
        if (r < runs.size()) again[r] = true;
    for (std::size_t r = 0; r < runs.size(); ++r) again[r] = again[r] && still_jumps(runs[r]);
    if (std::none_of(again.begin(), again.end(), [](bool b) { return b; })) break;
  }
  // A run is polished while it jumps or turns so.
  const auto wants_polish = [&](std::span<const std::size_t> run) {
    return jumps_in(run) > 0 || turns_too_often_in(run) ||
           std::any_of(run.begin(), run.end(), [&](std::size_t k) { return slope_jumps(nodes, joins, judge, k); });
  };
  for (std::size_t r = 0; r < runs.size(); ++r)
    for (int k = 0; k < limits.polish_rounds && wants_polish(runs[r]); ++k)
      if (!polish_jumping_run(nodes, ideal, steps, joins, runs[r], cycle, judge, limits.flat_curvature,
                              limits.polish_only_at_jumps))
        break;
  // Brackets: the two cubics next to each line a run meets, where a join of theirs jumps (a
  // run of two between a line and a corner too).
  const auto jumps_at = [&](std::size_t h) {
    const std::array<std::size_t, 3> at{h, (h + 1) % n, (h + 2) % n};
    return std::any_of(at.begin(), at.end(), [&](std::size_t k) { return join_jump(joins, k, limits.flat_curvature) > target_jump; });
  };
  for (const std::vector<std::size_t>& run : runs) {
    if (cycle || run.size() < 2) continue;
    const std::size_t last = (run.back() + 1) % n;
    const bool from_line = joins.meets_line(run.front()), to_line = joins.meets_line(last);
    // A run of two is one bracket from whichever end is a line; a longer run has one at each.
    const bool pair = run.size() == 2;
    if ((from_line || (pair && to_line)) && jumps_at(run.front()))
      place_bracket(nodes, ideal, steps, joins, run.front(), judge, limits.flat_curvature);
    if (!pair && to_line && jumps_at(run[run.size() - 2]))
      place_bracket(nodes, ideal, steps, joins, run[run.size() - 2], judge, limits.flat_curvature);
  }
}

}  // namespace gf
