#include "fair/node_change.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "fair/step_costs.hpp"

namespace gf {

std::vector<Vec2> node_places(Vec2 at, Vec2 unrounded, int reach) {
  const Vec2 nearest = nearest_grid_point(unrounded);
  std::vector<Vec2> out;
  for (int dy = -reach; dy <= reach; ++dy)
    for (int dx = -reach; dx <= reach; ++dx) {
      const Vec2 p = at + Vec2{double(dx), double(dy)};
      if (std::abs(p.x - nearest.x) <= reach && std::abs(p.y - nearest.y) <= reach) out.push_back(p);
    }
  return out;
}

std::vector<Vec2> directions_near(Vec2 tangent, double most, int longest) {
  const Vec2 t = tangent / norm(tangent);
  // Within `most` of t (under a quarter turn) ⟺ |t × d| ≤ tan(most)·(t · d) ahead of it: a test
  // without atan2 or gcd (a hair wide, for rounding) that leaves the exact ones a few dozen of
  // the (2·longest + 1)² grid points. The joins' mends ask for these at every grid point along
  // a curve (2.7 % of whole DejaVu Sans's time, most of it spent outside the wedge).
  const double slope =
      most < 0.5 * std::numbers::pi ? std::tan(most) * (1.0 + 1e-9) : std::numeric_limits<double>::infinity();
  std::vector<Vec2> out;
  for (int x = -longest; x <= longest; ++x)
    for (int y = -longest; y <= longest; ++y) {
      const Vec2 d{double(x), double(y)};
      const double along = dot(d, t);
      if (along <= 0.0 || std::abs(cross(t, d)) > slope * along + 1e-12) continue;
      if (is_primitive(d) && std::abs(turning_angle(t, d)) <= most) out.push_back(d);
    }
  return out;
}

std::vector<Vec2> node_directions(Vec2 step, const OutlineNode& target, int longest) {
  std::vector<Vec2> directions{step};
  if (step.x == 0.0 || step.y == 0.0) return directions;
  const Vec2 tangent = *target.out_handle - *target.in_handle;
  for (const Vec2 d : directions_near(tangent, grid_turn, longest)) {
    // An axis only along the tangent, to float noise (a G3 solve leaves 1e-13 rad).
    const bool axis = d.x == 0.0 || d.y == 0.0;
    if (d != step && (!axis || std::abs(cross(tangent, d)) <= 1e-9 * norm(tangent))) directions.push_back(d);
  }
  return directions;
}

FaultCeiling FaultCeiling::of(CubicJudge& judge, std::size_t k, const CubicTraits& before) {
  const CubicTraits& unrounded = judge.unrounded(k);
  return {judge.inflections_added(k, before), std::max(unrounded.extrema.all, before.extrema.all),
          std::max(unrounded.overreach, before.overreach), std::max(unrounded.turning, before.turning)};
}

bool FaultCeiling::admits(CubicJudge& judge, std::size_t k, const CubicTraits& t) const {
  return t.within && judge.inflections_added(k, t) <= inflections && t.extrema.all <= extrema &&
         t.overreach <= overreach && t.turning <= turning + fold_turn;
}

NodeChange::NodeChange(const std::vector<OutlineNode>& nodes, const OutlineJoins& joins, CubicJudge& judge, double flat,
                       std::size_t i)
    : nodes_(nodes), joins_(joins), judge_(judge), flat_(flat), i_(i), h_((i + nodes.size() - 1) % nodes.size()),
      j_((i + 1) % nodes.size()) {
  for (const std::size_t k : {h_, i_})
    if (joins.is_cubic(k)) cubics_.push_back(k);
  for (const std::size_t k : cubics_)
    ceilings_.push_back(FaultCeiling::of(judge, k, judge.traits(k, outline_cubic(nodes, k))));
  // The cubics beyond the neighbours stay as they are: their curvature there, once.
  const std::size_t n = nodes.size();
  for (const std::size_t k : {h_, i_, j_})
    if (judge.inflects_at(k) && !(k == j_ && j_ == h_)) inflection_nodes_.push_back(k);
  if (n >= 4) {
    if (joins.joins_cubics(h_)) beyond_h_ = node_curvature(outline_cubic(nodes, (h_ + n - 1) % n), SegmentEnd::end);
    if (joins.joins_cubics(j_)) beyond_j_ = node_curvature(outline_cubic(nodes, j_), SegmentEnd::start);
  }
}

double NodeChange::jump_costs() const {
  const std::array<double, 3> j = jumps_now();
  return jump_cost(j[0]) + jump_cost(j[1]) + jump_cost(j[2]);
}

std::optional<double> NodeChange::cost_under(double best) const {
  const double jumps = jump_costs();
  if (jumps >= best) return std::nullopt;
  const double c = jumps + bend_cost();
  if (c >= best || !allowed()) return std::nullopt;
  return c;
}

bool NodeChange::needs_change() const {
  const std::array<double, 3> j = jumps_now();
  return inflections_cost() >= wrong_way ||
         std::any_of(j.begin(), j.end(), [](double x) { return jump_cost(x) > target_jump * target_jump; });
}

bool NodeChange::allowed() const {
  for (std::size_t side = 0; side < cubics_.size(); ++side) {
    const std::size_t k = cubics_[side];
    if (!ceilings_[side].admits(judge_, k, judge_.traits(k, outline_cubic(nodes_, k)))) return false;
  }
  return true;
}

double NodeChange::inflections_cost() const {
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

double NodeChange::shapes_cost() const {
  double cost = 0.0;
  for (const std::size_t k : cubics_)
    cost += shape_cost(judge_.traits(k, outline_cubic(nodes_, k)).shape, judge_.unrounded(k).shape, flat_);
  return cost;
}

std::array<double, 3> NodeChange::jumps_now() const {
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
    if (beyond) return relative_jump(*beyond, *near, flat_);
    return joins_.meets_line(k) ? relative_jump(*near, 0.0, flat_) : 0.0;
  };
  const double at_i = joins_.joins_cubics(i_) ? relative_jump(*ke_h, *ks_i, flat_) : 0.0;  // a corner has none
  return {at_end(h_, beyond_h_, ks_h), at_i, at_end(j_, beyond_j_, ke_i)};
}

}  // namespace gf
