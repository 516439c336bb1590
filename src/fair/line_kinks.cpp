#include "fair/line_kinks.hpp"

#include <algorithm>
#include <optional>
#include <vector>

#include "fair/contour_plan.hpp"
#include "fair/kink_fillet.hpp"
#include "fair/sampled_contour.hpp"
#include "geom/join.hpp"

namespace gf {

namespace {

// The kinks the check would count in c.
std::size_t kinks_in(const Contour& c) {
  const std::vector<Join> joins = joins_of(c);
  return static_cast<std::size_t>(
      std::count_if(joins.begin(), joins.end(), [](const Join& j) { return j.kind == JoinKind::kink; }));
}

// The source sampled where a pass first changed a contour: most contours have no line kink.
class LazilySampled {
 public:
  explicit LazilySampled(const Contour& source) : source_(source) {}
  const SampledContour& get() {
    if (!sampled_) sampled_.emplace(source_);
    return *sampled_;
  }

 private:
  const Contour& source_;
  std::optional<SampledContour> sampled_;
};

// The passes, merging every kink that may go first or only those no fillet may take.
LineKinksTaken taken(const Contour& faired, double deviation, LazilySampled& sampled_source, double tolerance_units,
                     bool integer_grid, bool merging_only_against_neighbours) {
  const double t = tolerance_units;
  LineKinksTaken out{with_straight_segments_as_lines(faired), deviation, false};
  const auto take = [&](const Contour& filleted) {
    // Unchanged: no kink taken (a fillet that takes a whole line leaves as many segments).
    if (filleted.segments == out.contour.segments) return;
    const double d = distance_between(SampledContour(filleted), sampled_source.get());
    if (d > t) return;
    out.contour = filleted, out.changed = true;
    out.deviation = std::max(out.deviation, d);
  };
  take(merge_line_kinks(out.contour, t, merging_only_against_neighbours));
  const double left = 0.95 * (t - out.deviation);
  if (integer_grid)
    for (const double allowance : {left, 0.9 * t})
      take(fillet_legless_kinks_at_moved_vertices(out.contour, left, allowance));
  take(fillet_line_kinks(out.contour, left, integer_grid));
  if (integer_grid) take(fillet_kinks_at_moved_vertices(out.contour, 0.9 * t));
  if (!out.changed) out.contour = faired;
  return out;
}

}  // namespace

LineKinksTaken without_line_kinks(const Contour& faired, double deviation, const Contour& source,
                                  double tolerance_units, bool integer_grid) {
  LazilySampled sampled_source(source);
  LineKinksTaken merged = taken(faired, deviation, sampled_source, tolerance_units, integer_grid, false);
  const std::size_t kinks_left = kinks_in(merged.contour);
  if (kinks_left == 0) return merged;
  LineKinksTaken filleted = taken(faired, deviation, sampled_source, tolerance_units, integer_grid, true);
  return kinks_in(filleted.contour) < kinks_left ? filleted : merged;
}

}  // namespace gf
