// What the fairing issue's check counts against one faired contour: curvature jumps at smooth
// joins (CurvatureJumpRule), kinks (joins turning by more than a smooth join may and less than
// a corner does), inflections, and the source's corners that have no corner near them. Two
// faired versions of a contour are compared by it (fair_contour's fairings again).
#pragma once

#include <vector>

#include "geom/contour.hpp"

namespace gf {

struct OutlineFaults {
  int jumps = 0, kinks = 0, inflections = 0, corners_lost = 0;
  /// What a fairing again is for: the jumps and kinks the check counts at smooth joins.
  int at_smooth_joins() const { return jumps + kinks; }
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
};

/// Whether `a` has fewer jumps and kinks together than `b`, and no more kinks, inflections or
/// lost corners: a curvature jump is not traded for a broken tangent, a new inflection or a
/// corner rounded off.
bool fewer_faults(const OutlineFaults& a, const OutlineFaults& b);

}  // namespace gf
