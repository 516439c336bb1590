#include "fair/cubic_judge.hpp"

#include <algorithm>
#include <limits>
#include <span>
#include <utility>
#include <vector>

#include "geom/curvature.hpp"
#include "geom/polyline_distance.hpp"

namespace gf {

namespace {

constexpr int slide_samples = 24;      // points per cubic where a node's slide is measured
// Units of a line that a lone cubic's stretch takes in from its join, a point a unit. Taken in
// for every cubic meeting a line, the passes slid more joins along their lines and left more
// jumps elsewhere (a–z A–Z: TeX Gyre Pagella 10 → 15, EB Garamond 55 → 60, Lato 0 → 1).
constexpr double line_stretch = 48.0;
// The share of the outline's largest |κ| rounding may take off it, so that the turns at nodes
// the choices weigh are those the check will count (Because We Learn's L: a peak of κ·UPM 25.8
// rounded to 24.0, and a tooth of 0.24 at a node counted against 0.240 but weighed against
// 0.258). Not in the cubics' shapes: on text, Comic Neue a–z A–Z g2-jumps 22 → 29.
constexpr double turn_peak_margin = 0.1;

// A line from a join towards its far end: a point a unit for line_stretch units, then the far end.
std::vector<Vec2> line_from(Vec2 join, Vec2 far) {
  const double length = distance(join, far);
  const int units = static_cast<int>(std::min(length, line_stretch));
  std::vector<Vec2> run{join};
  for (int k = 1; k <= units; ++k) run.push_back(join + (far - join) * (k / length));
  if (length > units) run.push_back(far);
  return run;
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

}  // namespace

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

double CubicJudge::node_hysteresis() const { return (1.0 - turn_peak_margin) * hysteresis_; }

CubicJudge::CubicJudge(const std::vector<OutlineNode>& rounded, const std::vector<OutlineNode>& ideal,
                       const OutlineJoins& joins, const HandleStepLimits& limits)
    : unrounded_(rounded.size()), allowed_(rounded.size(), 0.0), ideal_(rounded.size()), seen_(rounded.size()),
      inflection_handles_(limits.inflection_handles), node_turns_(limits.node_turns), slope_jump_weight_(limits.slope_jump_weight),
      counted_jump_cost_(limits.counted_jump_cost), band_(limits.band), band_pieces_(rounded.size()),
      keeps_corner_(rounded.size(), false), closed_(joins.closed), joins_before_(rounded.size(), false),
      lone_lines_(rounded.size()), along_outline_(rounded.size()) {
  const std::size_t n = rounded.size();
  for (std::size_t i = 0; i < n; ++i) band_pieces_[i] = limits.band_piece(i);
  for (std::size_t i = 0; i < n; ++i) {
    if (!joins.is_cubic(i)) continue;
    unrounded_[i] = SampledCubic(along_lines(outline_cubic(ideal, i), rounded, i, joins));
    const double allowance = limits.allowance_at(i);
    allowed_[i] = std::max(allowance, moved_distance(outline_cubic(rounded, i), unrounded_[i], allowance));
    // κ turns count from 1 % of the outline's largest unrounded |κ|, as the check counts them.
    hysteresis_ = std::max(hysteresis_, 0.01 * curvature_shape(unrounded_[i].cubic, 0.0).largest);
  }
  for (std::size_t i = 0; i < n; ++i) joins_before_[i] = joins.joins_cubics(i);
  for (std::size_t i = 0; i < n; ++i)
    if (joins.is_cubic(i) && joins.meets_line(i) && joins.meets_line((i + 1) % n))
      lone_lines_[i] = std::array{ideal[(i + n - 1) % n].point, ideal[(i + 2) % n].point};
  for (std::size_t i = 0; i < n; ++i) {
    if (!joins.is_cubic(i)) continue;
    ideal_[i] = measure(i, unrounded_[i].cubic);
    shape(ideal_[i], unrounded_[i].cubic);
  }
  for (std::size_t k = 0; k < n; ++k) keeps_corner_[k] = corner_to_keep(ideal, closed_, k);
}

double CubicJudge::slid_distance(std::size_t i, const Cubic& c, double within) {
  const Stretch& stretch = along_outline(i);
  const std::span<const Vec2> along = stretch.points.points();
  std::array<Vec2, slide_samples + 1> pc;
  for (int t = 0; t <= slide_samples; ++t) pc[t] = c.point_at(double(t) / slide_samples);
  const double there = directed_hausdorff(pc, stretch.points, within, stretch.own_first);
  if (there > within) return there;
  const auto nearest = [&](Vec2 p) {
    std::size_t best = 0;
    for (std::size_t k = 1; k < along.size(); ++k)
      if (distance(along[k], p) < distance(along[best], p)) best = k;
    return best;
  };
  const std::size_t a = nearest(c.p[0]), b = nearest(c.p[3]);
  if (a >= b) return std::numeric_limits<double>::infinity();
  const std::span<const Vec2> covered = along.subspan(a, b - a + 1);
  return std::max(there, directed_hausdorff(covered, pc, within));
}

const CubicJudge::Stretch& CubicJudge::along_outline(std::size_t i) {
  Stretch& along = along_outline_[i];
  if (!along.points.points().empty()) return along;
  const std::size_t n = unrounded_.size();
  std::vector<Vec2> points;
  const auto add = [&](const Cubic& c) {
    for (int t = points.empty() ? 0 : 1; t <= slide_samples; ++t) points.push_back(c.point_at(double(t) / slide_samples));
  };
  const Cubic& own = unrounded_[i].cubic;
  if (joins_before_[i]) add(unrounded_[(i + n - 1) % n].cubic);
  else if (lone_lines_[i]) {
    const std::vector<Vec2> run = line_from(own.p[0], (*lone_lines_[i])[0]);
    points.assign(run.rbegin(), run.rend());
  }
  along.own_first = points.empty() ? 0 : points.size() - 1;
  add(own);
  along.own_last = points.size() - 1;
  if (joins_before_[(i + 1) % n]) add(unrounded_[(i + 1) % n].cubic);
  else if (lone_lines_[i]) {
    const std::vector<Vec2> run = line_from(own.p[3], (*lone_lines_[i])[1]);
    points.insert(points.end(), run.begin() + 1, run.end());
  }
  along.points = BoxedPolyline(std::move(points));
  return along;
}

bool CubicJudge::band_holds(std::size_t i, const Cubic& c) {
  const std::vector<Vec2> pc = band_samples(c);
  const Stretch& along = along_outline(i);
  const std::span<const Vec2> points = along.points.points();
  if (along.own_first == 0 && along.own_last + 1 == points.size()) return band_->holds(band_pieces_[i], pc);
  std::vector<Vec2> spliced(points.begin(), points.begin() + static_cast<std::ptrdiff_t>(along.own_first));
  spliced.insert(spliced.end(), pc.begin(), pc.end());
  spliced.insert(spliced.end(), points.begin() + static_cast<std::ptrdiff_t>(along.own_last + 1), points.end());
  return band_->holds_along(band_pieces_[i], pc, spliced);
}

CubicTraits CubicJudge::measure(std::size_t i, const Cubic& c) {
  const EndCurvature start = end_curvature(c, SegmentEnd::start), end = end_curvature(c, SegmentEnd::end);
  double moved = moved_distance(c, unrounded_[i], allowed_[i]);
  if (moved > allowed_[i]) moved = std::min(moved, slid_distance(i, c, allowed_[i]));
  CubicTraits t;
  t.k_start = start.curvature.value_or(0.0), t.k_end = end.curvature.value_or(0.0);
  t.slope_start = start.curvature_derivative.value_or(0.0), t.slope_end = end.curvature_derivative.value_or(0.0);
  t.moved = moved;
  t.within = moved <= allowed_[i] || (band_ && band_holds(i, c));
  return t;
}

void CubicJudge::shape(CubicTraits& t, const Cubic& c) const {
  t.shape = curvature_shape(c, hysteresis_);
  t.extrema = inner_axis_extrema_of(c);
  t.overreach = overreach_length(c);
  t.turning = distance(c.p[0], c.p[3]) < fold_chord ? cubic_turning(c) : 0.0;
}

}  // namespace gf
