// Every cubic of a rounded outline against its unrounded self: what the choice of whole-step
// handles (fair/handle_steps) weighs of a candidate cubic, measured once however many passes
// weigh it.
#pragma once

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <unordered_map>
#include <vector>

#include "fair/cubic_change.hpp"
#include "fair/handle_steps.hpp"
#include "fair/inflection_count.hpp"
#include "fair/outline_joins.hpp"
#include "fair/step_costs.hpp"

namespace gf {

/// What the choices weigh of a candidate cubic.
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

/// The turns of κ a node adds, counted as the check counts them over the second half of the
/// cubic before it and the first half of the one after, beyond what that first half counts
/// alone (the halves' own turns are their cubics').
int turns_at_node(const CubicTraits& before, const CubicTraits& after, double hysteresis);

/// Every cubic of the outline against its unrounded self. How far each may move to gain G2 is
/// set once: its allowance, or as far as rounding alone already put it. Each candidate is
/// measured once, however many passes weigh it.
class CubicJudge {
 public:
  CubicJudge(const std::vector<OutlineNode>& rounded, const std::vector<OutlineNode>& ideal,
             const OutlineJoins& joins, const HandleStepLimits& limits);

  bool closed() const { return closed_; }
  /// Whether node k of `nodes` is a corner that rounding must leave turning by the kink limit
  /// (corner_to_keep) and turns under it, its handles `in` and `out` where given (turn_at).
  bool turned_under_limit(const std::vector<OutlineNode>& nodes, std::size_t k, std::optional<Vec2> in = {},
                          std::optional<Vec2> out = {}) const {
    return keeps_corner_[k] && turn_at(nodes, closed_, k, in, out) < kink_limit;
  }

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
    return node_turn_weight * std::max(0, turns_at_node(before, after, node_hysteresis()) - unrounded_turns);
  }
  /// What a curvature jump j at a node costs, one the check counts the more
  /// (HandleStepLimits::counted_jump_cost).
  double g2_cost(double j) const { return jump_cost(j) + (j > checked_jump ? counted_jump_cost_ : 0.0); }
  /// What the jump of dκ/ds at a node costs (HandleStepLimits::slope_jump_weight), else nothing.
  double slope_cost(const CubicTraits& before, const CubicTraits& after) const {
    return match_slopes() ? slope_jump_cost(before.slope_end, after.slope_start, slope_jump_weight_) : 0.0;
  }
  int unrounded_node_turns(std::size_t h, std::size_t i) const {
    return node_turns_ ? turns_at_node(ideal_[h], ideal_[i], node_hysteresis()) : 0;
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
    Measured& m = measured(i, c);
    if (!m.shaped) shape(m.traits, c), m.shaped = true;
    return m.traits;
  }
  /// What a choice of handles weighs of `c` in the place of cubic i: its traits where it is
  /// within, else only its ends' curvature and how far it moved (a state not within is never
  /// joined to another, and most candidates of a tight turn are not: the choices of DejaVu
  /// Sans's U+2765 measured three in four only so far).
  const CubicTraits& weighed(std::size_t i, const Cubic& c) {
    Measured& m = measured(i, c);
    if (!m.shaped && m.traits.within) shape(m.traits, c), m.shaped = true;
    return m.traits;
  }

 private:
  // How far `c`, in the place of cubic i, lies from the unrounded outline where its node slid
  // along it: its points from the unrounded cubic and those it joins smoothly, and the points of
  // those between where c's ends lie nearest from c. A node moved along its own tangent shortens
  // one cubic and lengthens the other; each measured against its unrounded self alone, the
  // shortened one "moves" by the whole slide, its end no longer reaching the old node. Past
  // `within`, only that it is past.
  double slid_distance(std::size_t i, const Cubic& c, double within);

  // Cubic i's unrounded self with the unrounded cubics it joins smoothly, along the outline:
  // `points`, of which [own_first, own_last] are its own. A lone cubic between two lines has
  // the lines' stretches near its joins instead: where it meets them with κ = 0 on the grid
  // may be a stretch of line away from where it did unrounded (Noto Sans's W: its curve
  // reaches 8 units farther up the line to the apex, its handles then long enough). Built
  // when first asked for (most cubics stay within their allowance).
  struct Stretch {
    BoxedPolyline points;  ///< with their boxes, for the searches against them
    std::size_t own_first = 0, own_last = 0;
  };
  const Stretch& along_outline(std::size_t i);

  // Whether `c`, in the place of cubic i, keeps within the band around the source, the source
  // points its unrounded self answered for covered by it or by the unrounded cubics it joins
  // smoothly, spliced on either side of it in place of its unrounded self (a node slid along
  // the outline hands them over; what c itself covers, the splice covers too).
  bool band_holds(std::size_t i, const Cubic& c);

  // A candidate's traits, those of its shape only once asked for.
  struct Measured {
    CubicTraits traits;
    bool shaped = false;
  };
  Measured& measured(std::size_t i, const Cubic& c) {
    const auto [it, fresh] = seen_[i].try_emplace(std::array{c.p[0].x, c.p[0].y, c.p[1].x, c.p[1].y,
                                                             c.p[2].x, c.p[2].y, c.p[3].x, c.p[3].y});
    if (fresh) it->second.traits = measure(i, c);
    return it->second;
  }
  // Its ends' curvature and how far it moved.
  CubicTraits measure(std::size_t i, const Cubic& c);
  // The rest: its shape, extrema, overreach and turning.
  void shape(CubicTraits& t, const Cubic& c) const;
  /// The hysteresis the turns at nodes count from (turn_peak_margin below hysteresis_).
  double node_hysteresis() const;

  std::vector<SampledCubic> unrounded_;
  std::vector<double> allowed_;
  double hysteresis_ = 0.0;
  std::vector<CubicTraits> ideal_;
  // A candidate by its control points; a hash map keeps its entries in place as it grows.
  struct ControlPointsHash {
    std::size_t operator()(const std::array<double, 8>& key) const {
      std::uint64_t h = 0;
      for (const double v : key) h = (h ^ std::bit_cast<std::uint64_t>(v + 0.0)) * 0x9E3779B97F4A7C15ull;  // −0 as +0
      return static_cast<std::size_t>(h ^ (h >> 29));
    }
  };
  std::vector<std::unordered_map<std::array<double, 8>, Measured, ControlPointsHash>> seen_;
  bool inflection_handles_, node_turns_;
  double slope_jump_weight_, counted_jump_cost_;
  const ToleranceBand* band_;
  std::vector<std::size_t> band_pieces_;  ///< the band's piece for each cubic
  std::vector<bool> keeps_corner_;
  bool closed_;
  std::vector<bool> joins_before_;                 ///< whether node i joins two cubics smoothly
  /// For a cubic between two lines it meets smoothly, the lines' unrounded far ends.
  std::vector<std::optional<std::array<Vec2, 2>>> lone_lines_;
  std::vector<Stretch> along_outline_;             ///< along_outline(i), once asked for
};

}  // namespace gf
