// What the fairing issue's check counts against one faired contour: curvature jumps at smooth
// joins (CurvatureJumpRule), kinks (joins turning by more than a smooth join may and less than
// a corner does), inflections beyond the source's, and the source's corners that have no
// corner near them. Two faired versions of a contour are compared by it (fair_contour's
// fairings again).
#pragma once

#include <span>
#include <vector>

#include "geom/contour.hpp"
#include "geom/join.hpp"

namespace gf {

/// The check's rule less a hair, by which the fairing counts a jump: a jump of exactly the
/// limit, which whole grid steps can make (κ·UPM 4.43 against 4.66 over handles of one length,
/// 5 % to the last bit: Junicode's e), comes out a hair over it or under it depending on how
/// a checker rounds, so the fairing mends it as one.
inline constexpr CurvatureJumpRule fairing_jump_rule{0.05 * (1.0 - 1e-9), 0.05 * (1.0 - 1e-9), 0.5};

struct OutlineFaults {
  /// `inflections`: how many more the faired contour has than its source (the check's bar:
  /// inflections not increased).
  int jumps = 0, kinks = 0, inflections = 0, corners_lost = 0;
  /// The jumps and kinks the check counts at smooth joins.
  int at_smooth_joins() const { return jumps + kinks; }
  /// What a fairing again is for: jumps or kinks at smooth joins, or inflections beyond the
  /// source's.
  bool mendable() const { return at_smooth_joins() > 0 || inflections > 0; }
  bool operator==(const OutlineFaults&) const = default;
};

/// The faults of each faired version of one source contour, on an em of `units_per_em`. A
/// source corner is kept where the faired contour has a corner (or a join without a direction)
/// within a quarter per cent of the em of it, as the check has it; the source's corners are
/// found once, however many versions are counted.
class FaultCounter {
 public:
  FaultCounter(const Contour& source, double units_per_em);
  OutlineFaults count(const Contour& faired) const;

 private:
  std::vector<Vec2> source_corners_;
  double units_per_em_;
  int source_inflections_ = 0;
};

/// What the check makes of a join: a corner (turning past `thresholds.kink_max_deg`, or without
/// a direction), a kink, a smooth join whose curvature jumps (an unbounded side counts), or a
/// smooth join that holds.
enum class JoinFault { corner, kink, jump, none };
JoinFault join_fault(const Join& j, const JoinThresholds& thresholds, double units_per_em);

/// Where `faired` has a join the check counts as `fault` (a jump: a smooth join whose curvature
/// jumps, an unbounded side counting), on an em of `units_per_em`.
std::vector<Vec2> joins_at_fault(const Contour& faired, JoinFault fault, double units_per_em);

/// The sign changes of κ along each stretch of `c` between corners (of its `joins`, joins_of(c),
/// those turning by more than `kink_max_deg` or without a direction; kinks belong to the
/// stretch), as the check counts them: |κ|·UPM under 1e-6 is no sign, so κ changing sign across
/// a node where it is 0 on both sides counts. A closed contour without a corner is one stretch
/// round.
int inflections_along(const Contour& c, std::span<const Join> joins, double units_per_em, double kink_max_deg);

/// Whether `a` has fewer faults than `b`. Either none more of any kind (jumps and kinks
/// together, kinks, inflections beyond the source's, lost corners) and fewer jumps and kinks
/// together, inflections or lost corners; or fewer jumps and kinks together at the cost of at
/// most two inflections for each: a jump is not traded for a broken tangent or a corner
/// rounded off, and an inflection only for a jump, whose bar allows none while the check's
/// inflection bar is the font's total (Vollkorn's R: a jump mended by a fairing again with two
/// more inflections than the source's contour, the font's inflections still 0.98× the
/// source's).
bool fewer_faults(const OutlineFaults& a, const OutlineFaults& b);

}  // namespace gf
