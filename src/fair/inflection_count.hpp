// The inflections a rounded outline adds to its unrounded self, counted as the check counts
// them: sign changes of κ along the run, inside each cubic and across each smooth node. An
// inflection at a node may move across it: the cubic on one side then ends with the other
// side's sign (a far handle a fifth of a unit past the tangent line), and the run has as many
// sign changes as before so long as the cubic on the other side does not flip too. Counted
// per cubic alone, that move is an added inflection, and the rounding kept a curvature jump
// instead (Lato's g, where its bowl's flat node meets the ear).
#pragma once

#include <algorithm>

#include "fair/cubic_change.hpp"

namespace gf {

/// Whether each end of a rounded cubic has κ of the other sign than its unrounded self there.
struct EndFlips {
  bool start = false, end = false;
};
inline EndFlips end_flips(const CurvatureShape& rounded, const CurvatureShape& unrounded) {
  return {rounded.first_sign * unrounded.first_sign < 0, rounded.last_sign * unrounded.last_sign < 0};
}

/// Whether κ changes sign across the node from unrounded cubic a to unrounded cubic b: the
/// only nodes where a flip at a cubic's end can leave the count as it was.
inline bool inflection_between(const CurvatureShape& a, const CurvatureShape& b) {
  return a.last_sign * b.first_sign < 0;
}

/// The sign changes a rounded cubic adds inside, less a flip at an end that is an inflection
/// node between two cubics (`start_inflects`, `end_inflects`): that node counts it
/// (inflections_at).
inline int inflections_added_within(const CurvatureShape& rounded, const CurvatureShape& unrounded,
                                    bool start_inflects, bool end_inflects) {
  const EndFlips f = end_flips(rounded, unrounded);
  const int at_nodes = (f.start && start_inflects) + (f.end && end_inflects);
  return std::max(0, rounded.sign_changes - unrounded.sign_changes - at_nodes);
}

/// What a rounded run does at the node from cubic a to cubic b (each rounded, beside its
/// unrounded self u): the sign changes it adds there, a flip at either side's end counted with
/// the change across the node against the one change there was (0 where one side flips, 2
/// where both do; 0 at nodes κ did not change sign across, whose flips the cubics count
/// inside), and whether the inflection moved off the node (one side flipped: κ no longer 0
/// there from both sides).
struct NodeInflections {
  int added = 0;
  bool moved = false;
};
inline NodeInflections inflections_at(const CurvatureShape& a, const CurvatureShape& ua, const CurvatureShape& b,
                                      const CurvatureShape& ub) {
  if (!inflection_between(ua, ub)) return {};
  const bool fa = end_flips(a, ua).end, fb = end_flips(b, ub).start;
  const int across = a.last_sign * b.first_sign < 0;
  const int added = std::max(0, int{fa} + int{fb} + across - 1);
  return {added, (fa || fb) && added == 0};
}

}  // namespace gf
