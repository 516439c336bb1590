// Whole-step handle lengths on the grid: G1 stays exact (integer cross products zero), and
// curvature matches across smooth nodes by the check's rule (relative jump at most 5 %),
// κ = 0 exactly where a curve meets a line, while no cubic moves farther than allowed.
#include "fair/handle_steps.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <random>

#include "fair/grid_rounding.hpp"
#include "geom/curvature.hpp"
#include "geom/g2_hermite.hpp"

namespace gf {
namespace {

double kappa(const Cubic& c, SegmentEnd end) { return end_curvature(c, end).curvature.value_or(0.0); }

Cubic cubic_from(const std::vector<OutlineNode>& nodes, std::size_t i) {
  const OutlineNode &a = nodes[i], &b = nodes[(i + 1) % nodes.size()];
  return {a.point, *a.out_handle, *b.in_handle, b.point};
}

// An ellipse x = a cos t, y = b sin t through the points where its tangent runs along the
// given primitive grid directions (in order round it), as G2 Hermite cubics with the exact
// curvature ab / (a² sin² t + b² cos² t)^{3/2} at the ends, off the grid.
std::vector<OutlineNode> ellipse(double a, double b, Vec2 centre, const std::vector<Vec2>& directions) {
  const std::size_t n = directions.size();
  std::vector<HermiteEnd> ends;
  for (const Vec2 d : directions) {
    const double t = std::atan2(-b * d.x, a * d.y);
    const double s = std::sin(t), c = std::cos(t);
    ends.push_back({centre + Vec2{a * c, b * s}, d / norm(d), a * b / std::pow(a * a * s * s + b * b * c * c, 1.5)});
  }
  std::vector<OutlineNode> nodes(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::vector<Cubic> cubics = g2_hermite_cubics(ends[i], ends[(i + 1) % n]);
    EXPECT_FALSE(cubics.empty());
    // The solution with the most even handles: the one an ellipse arc looks like.
    auto unevenness = [](const Cubic& c) {
      return std::abs(std::log(distance(c.p[1], c.p[0]) / distance(c.p[3], c.p[2])));
    };
    const Cubic* best = &cubics.front();
    for (const Cubic& c : cubics)
      if (unevenness(c) < unevenness(*best)) best = &c;
    nodes[i].point = best->p[0];
    nodes[i].out_handle = best->p[1];
    nodes[(i + 1) % n].in_handle = best->p[2];
    nodes[i].grid_step = directions[i];
  }
  return nodes;
}

Vec2 primitive(Vec2 v) {
  const double g = static_cast<double>(std::gcd(static_cast<long long>(std::abs(v.x)), static_cast<long long>(std::abs(v.y))));
  return v / g;
}

double parametric_distance(const Cubic& a, const Cubic& b) {
  double d = 0.0;
  for (int k = 0; k <= 16; ++k) d = std::max(d, distance(a.point_at(k / 16.0), b.point_at(k / 16.0)));
  return d;
}

TEST(HandleSteps, EllipsesKeepG2OnTheGrid) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int nodes = 0, within = 0;
  for (int trial = 0; trial < 100; ++trial) {
    const double a = 150 + 300 * u(rng), b = 100 + 200 * u(rng);
    // Extrema and the diagonals between them, where the writeback cuts long arcs.
    const std::vector<OutlineNode> ideal =
        ellipse(a, b, {500.3 + u(rng), 400.7 + u(rng)}, {{0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}, {1, 0}, {1, 1}});
    const std::size_t n = ideal.size();
    // Rounded with no room to move, then given a unit to gain G2 in.
    const std::vector<OutlineNode> plain = round_to_grid(ideal, true, {5e-4, 0.0});
    std::vector<std::optional<Vec2>> steps;
    for (const OutlineNode& node : plain) steps.push_back(primitive(*node.out_handle - node.point));
    std::vector<OutlineNode> r = plain;
    choose_handle_steps(r, ideal, steps, true, {5e-4, 1.0});
    for (std::size_t i = 0; i < n; ++i) {
      const OutlineNode& node = r[i];
      EXPECT_EQ(cross(node.point - *node.in_handle, *node.out_handle - node.point), 0.0);
      const double k_in = kappa(cubic_from(r, (i + n - 1) % n), SegmentEnd::end);
      const double k_out = kappa(cubic_from(r, i), SegmentEnd::start);
      ++nodes;
      within += std::abs(k_in - k_out) / std::max(std::abs(k_in), std::abs(k_out)) <= 0.05;
      // No cubic farther from its unrounded self than the allowance, or than rounding alone
      // put it (2 % for sampling).
      const Cubic c0 = cubic_from(ideal, i);
      EXPECT_LE(parametric_distance(cubic_from(r, i), c0),
                1.02 * std::max(1.0, parametric_distance(cubic_from(plain, i), c0)));
    }
  }
  // Whole steps cannot always meet 5 % on a short handle within a unit; nearly always they do
  // (rounding alone misses it at about one node in seven).
  EXPECT_GE(within, 0.98 * nodes);
}

TEST(HandleSteps, ACurveLeavingALineStartsWithZeroCurvature) {
  // A line along y = 0.3 into node 1, then a cubic with κ = 0 there (its second handle on the
  // line) up to a vertical tangent at node 2, then a corner back.
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 50; ++trial) {
    const double y = 0.3 + u(rng), x = 200.4 + 100 * u(rng), top = 150 + 100 * u(rng);
    std::vector<OutlineNode> nodes(3);
    nodes[0].point = {0.2, y};
    nodes[0].smooth = false;
    nodes[1].point = {x, y};
    nodes[1].out_handle = Vec2{x + 60 + 20 * u(rng), y};
    nodes[2].point = {x + 150, y + top};
    nodes[2].in_handle = Vec2{x + 150, y};  // on the line: κ = 0 at node 1
    nodes[2].out_handle = Vec2{x + 150, y + top + 40};
    nodes[2].grid_step = Vec2{0, 1};
    nodes[0].in_handle = Vec2{0.2, y + top + 40};
    const std::vector<OutlineNode> r = round_to_grid(nodes, true, {5e-4, 1.0});
    const Cubic c = cubic_from(r, 1);
    EXPECT_EQ(cross(c.p[1] - c.p[0], c.p[2] - c.p[1]), 0.0) << "trial " << trial;
    EXPECT_EQ(cross(r[1].point - r[0].point, c.p[1] - c.p[0]), 0.0);  // G1 with the line
  }
}

}  // namespace
}  // namespace gf
