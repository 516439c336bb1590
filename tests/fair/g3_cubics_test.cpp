// G3 carried into the written cubics: closed forms (a circle's quarter with dκ/ds = 0 at both
// ends has handles (8 − √10)/9 of the radius), invariants (a run already G3 stays; nothing
// moves without an allowance), and the joins of runs drawn from an ellipse and from a curve
// leaving a line, which come out G3 with κ continuous, κ = 0 kept at the line and each corner's
// κ held.
#include "fair/g3_cubics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>

#include "geom/g2_hermite.hpp"

namespace gf {
namespace {

constexpr double pi = std::numbers::pi;

// Nodes of the cubics `cubics` joined end to start (closed: the last returns to the first).
std::vector<OutlineNode> nodes_of(const std::vector<Cubic>& cubics, bool closed) {
  std::vector<OutlineNode> nodes(closed ? cubics.size() : cubics.size() + 1);
  for (std::size_t k = 0; k < cubics.size(); ++k) {
    nodes[k].point = cubics[k].p[0], nodes[k].out_handle = cubics[k].p[1];
    nodes[(k + 1) % nodes.size()].in_handle = cubics[k].p[2];
  }
  if (!closed) nodes.back().point = cubics.back().p[3];
  return nodes;
}

std::vector<Cubic> cubics_of(const std::vector<OutlineNode>& nodes, bool closed) {
  std::vector<Cubic> out;
  for (std::size_t i = 0; i < (closed ? nodes.size() : nodes.size() - 1); ++i) out.push_back(outline_cubic(nodes, i));
  return out;
}

double relative_jump(double a, double b) {
  const double big = std::max(std::abs(a), std::abs(b));
  return big > 0.0 ? std::abs(a - b) / big : 0.0;
}

// The largest relative jumps of κ and of dκ/ds over the inner nodes.
struct Jumps {
  double curvature = 0.0, slope = 0.0;
};
Jumps inner_jumps(const std::vector<Cubic>& cubics, bool closed) {
  Jumps j;
  for (std::size_t k = closed ? 0 : 1; k < cubics.size(); ++k) {
    const Cubic& into = cubics[(k + cubics.size() - 1) % cubics.size()];
    const EndCurvature a = end_curvature(Segment(into), SegmentEnd::end);
    const EndCurvature b = end_curvature(Segment(cubics[k]), SegmentEnd::start);
    j.curvature = std::max(j.curvature, relative_jump(*a.curvature, *b.curvature));
    j.slope = std::max(j.slope, relative_jump(*a.curvature_derivative, *b.curvature_derivative));
  }
  return j;
}

// The largest distance from samples of `now` to the cubic `was` (dense samples of it).
double moved(const Cubic& now, const Cubic& was) {
  double worst = 0.0;
  for (int s = 0; s <= 64; ++s) {
    double nearest = INFINITY;
    for (int u = 0; u <= 4000; ++u) nearest = std::min(nearest, distance(now.point_at(s / 64.0), was.point_at(u / 4000.0)));
    worst = std::max(worst, nearest);
  }
  return worst;
}

// G2 Hermite cubics through a smooth curve's frames at the parameters `at` (the solution whose
// handles are nearest a third of the chord).
struct Frame {
  Vec2 point, tangent;
  double curvature;
};
std::vector<Cubic> hermite_run(const std::function<Frame(double)>& curve, const std::vector<double>& at) {
  std::vector<Cubic> out;
  for (std::size_t k = 0; k + 1 < at.size(); ++k) {
    const Frame a = curve(at[k]), b = curve(at[k + 1]);
    const std::vector<Cubic> all = g2_hermite_cubics({a.point, a.tangent, a.curvature}, {b.point, b.tangent, b.curvature});
    EXPECT_FALSE(all.empty()) << "span " << k;
    if (all.empty()) return {};
    const double third = distance(a.point, b.point) / 3.0;
    const auto off = [&](const Cubic& c) {
      return std::abs(distance(c.p[0], c.p[1]) - third) + std::abs(distance(c.p[3], c.p[2]) - third);
    };
    out.push_back(*std::min_element(all.begin(), all.end(), [&](const Cubic& x, const Cubic& y) { return off(x) < off(y); }));
  }
  return out;
}

Frame ellipse(double a, double b, double theta) {
  const Vec2 d{-a * std::sin(theta), b * std::cos(theta)};
  const double speed = norm(d);
  return {{a * std::cos(theta), b * std::sin(theta)}, d / speed, a * b / (speed * speed * speed)};
}

TEST(G3Cubics, TheNodeBudgetKeepsTheFairingBar) {
  // 12 % of the cubics, rounded to the nearest: 25 cubics give 3.
  EXPECT_EQ(g3_node_budget(25, 25, 100, 0.12, 1.3), 3);
  // Held within 1.3 times the source's nodes: a contour of 20 nodes from a source of 16 may
  // reach 20 (floor 20.8), and no more.
  EXPECT_EQ(g3_node_budget(20, 20, 16, 0.12, 1.3), 0);
  EXPECT_EQ(g3_node_budget(30, 19, 16, 0.12, 1.3), 1);
  // Past the bar already: none (never a negative budget).
  EXPECT_EQ(g3_node_budget(30, 30, 16, 0.12, 1.3), 0);
}

TEST(G3Cubics, ACircleInFourCubicsTakesTheHandlesWhoseEndsHaveNoSlope) {
  const double r = 500.0, k = 0.5523;
  std::vector<Cubic> quarters;
  for (int q = 0; q < 4; ++q) {
    const Vec2 a = direction_of(q * pi / 2) * r, b = direction_of((q + 1) * pi / 2) * r;
    quarters.push_back({a, a + perpendicular(a) * k, b - perpendicular(b) * k, b});
  }
  std::vector<OutlineNode> nodes = nodes_of(quarters, true);
  for (OutlineNode& n : nodes) n.grid_step = perpendicular(n.point / r);
  const std::vector<double> allowance(4, 0.01 * r);
  const G3CubicReport report = make_cubics_g3(nodes, true, allowance, {5e-4, 0});
  EXPECT_EQ(report.runs, 1);
  EXPECT_EQ(report.runs_g3, 1);
  EXPECT_EQ(report.nodes_added, 0);
  ASSERT_EQ(nodes.size(), 4u);
  const double closed_form = (8.0 - std::sqrt(10.0)) / 9.0;  // 9h² − 16h + 6 = 0
  for (const OutlineNode& n : nodes) {
    const double radius = norm(n.point);
    EXPECT_NEAR(distance(*n.out_handle, n.point) / radius, closed_form, 1e-6);
    EXPECT_NEAR(distance(*n.in_handle, n.point) / radius, closed_form, 1e-6);
  }
  for (const Cubic& c : cubics_of(nodes, true)) {
    const double kappa = *end_curvature(Segment(c), SegmentEnd::start).curvature;
    EXPECT_NEAR(*end_curvature(Segment(c), SegmentEnd::start).curvature_derivative * r / kappa, 0.0, 1e-6);
    EXPECT_NEAR(*end_curvature(Segment(c), SegmentEnd::end).curvature_derivative * r / kappa, 0.0, 1e-6);
  }
}

TEST(G3Cubics, AnEllipseArcBetweenTwoCornersComesOutG3WithinItsAllowance) {
  const auto curve = [](double t) { return ellipse(600.0, 300.0, t); };
  const std::vector<Cubic> source = hermite_run(curve, {0.0, 0.5, 1.3, 2.1, pi});
  ASSERT_EQ(source.size(), 4u);
  std::vector<OutlineNode> nodes = nodes_of(source, false);
  nodes.front().smooth = nodes.back().smooth = false;  // corners
  EXPECT_GT(inner_jumps(source, false).slope, 0.01);  // the G2 Hermite cubics are not G3
  const double allowance = 2.0;
  const G3CubicReport report = make_cubics_g3(nodes, false, std::vector<double>(4, allowance), {5e-4, 0});
  EXPECT_EQ(report.runs, 1);
  EXPECT_EQ(report.runs_g3, 1);
  const std::vector<Cubic> faired = cubics_of(nodes, false);
  const Jumps j = inner_jumps(faired, false);
  EXPECT_LE(j.curvature, 1e-6);
  EXPECT_LE(j.slope, 1e-4);
  // The corners keep point, tangent and κ.
  for (const auto& [now, was, end] : {std::tuple{faired.front(), source.front(), SegmentEnd::start},
                                      std::tuple{faired.back(), source.back(), SegmentEnd::end}}) {
    EXPECT_EQ(end == SegmentEnd::start ? now.p[0] : now.p[3], end == SegmentEnd::start ? was.p[0] : was.p[3]);
    EXPECT_NEAR(cross(*end_tangent(Segment(now), end), *end_tangent(Segment(was), end)), 0.0, 1e-12);
    EXPECT_LE(relative_jump(*end_curvature(Segment(now), end).curvature, *end_curvature(Segment(was), end).curvature), 1e-6);
  }
  for (std::size_t k = 0; k < faired.size(); ++k) EXPECT_LE(moved(faired[k], source[k]), allowance * 1.01) << k;
}

TEST(G3Cubics, RunsMeetingAtCornersBetweenCurvesKeepBothTangentsThere) {
  // A lens: an ellipse's upper arc, then its mirror image in the chord back, closed. The
  // corners have a handle on either side, so each run must take its last tangent from the
  // handle it arrives by (DejaVu's corners mostly meet lines; a handwriting font's meet curves).
  const double a = 600.0, b = 300.0, start = 0.3, end = pi - 0.3, chord_y = b * std::sin(start);
  const std::vector<Cubic> upper = hermite_run([&](double t) { return ellipse(a, b, t); }, {start, 0.8, 1.4, 2.1, end});
  ASSERT_EQ(upper.size(), 4u);
  std::vector<Cubic> source = upper;
  for (auto it = upper.rbegin(); it != upper.rend(); ++it) {
    Cubic mirrored;
    for (int i = 0; i < 4; ++i) mirrored.p[static_cast<std::size_t>(3 - i)] = {it->p[static_cast<std::size_t>(i)].x, 2 * chord_y - it->p[static_cast<std::size_t>(i)].y};
    source.push_back(mirrored);
  }
  std::vector<OutlineNode> nodes = nodes_of(source, true);
  nodes[0].smooth = nodes[4].smooth = false;  // the corners
  const double allowance = 2.0;
  const G3CubicReport report = make_cubics_g3(nodes, true, std::vector<double>(8, allowance), {5e-4, 0});
  EXPECT_EQ(report.runs, 2);
  EXPECT_EQ(report.runs_g3, 2);
  ASSERT_EQ(nodes.size(), 8u);
  const std::vector<Cubic> faired = cubics_of(nodes, true);
  for (const std::size_t first : {0u, 4u}) {
    const std::vector<Cubic> run(faired.begin() + first, faired.begin() + first + 4);
    const Jumps j = inner_jumps(run, false);
    EXPECT_LE(j.curvature, 1e-6) << first;
    EXPECT_LE(j.slope, 1e-4) << first;
  }
  // Each corner keeps its point, and both tangents and curvatures it had.
  for (const std::size_t k : {0u, 3u, 4u, 7u})
    for (const SegmentEnd end : {SegmentEnd::start, SegmentEnd::end}) {
      const Segment now(faired[k]), was(source[k]);
      if ((end == SegmentEnd::start) != (k % 4 == 0)) continue;
      EXPECT_NEAR(cross(*end_tangent(now, end), *end_tangent(was, end)), 0.0, 1e-12) << k;
      EXPECT_GT(dot(*end_tangent(now, end), *end_tangent(was, end)), 0.0) << k;
      EXPECT_LE(relative_jump(*end_curvature(now, end).curvature, *end_curvature(was, end).curvature), 1e-6) << k;
    }
  EXPECT_EQ(nodes[0].point, source[0].p[0]);
  EXPECT_EQ(nodes[4].point, source[4].p[0]);
  for (std::size_t k = 0; k < faired.size(); ++k) EXPECT_LE(moved(faired[k], source[k]), allowance * 1.01) << k;
}

TEST(G3Cubics, ACurveLeavingALineKeepsNoCurvatureThere) {
  // y = c·x³ leaves the x axis with κ = 0; its G2 Hermite cubics from x = 0 to 300.
  const double c = 5e-6;
  const auto curve = [&](double x) {
    const double slope = 3 * c * x * x, bend = 6 * c * x, speed = std::sqrt(1 + slope * slope);
    return Frame{{x, c * x * x * x}, Vec2{1.0, slope} / speed, bend / (speed * speed * speed)};
  };
  const std::vector<Cubic> source = hermite_run(curve, {0.0, 90.0, 170.0, 240.0, 300.0});
  ASSERT_EQ(source.size(), 4u);
  std::vector<OutlineNode> nodes = nodes_of(source, false);
  nodes.back().smooth = false;  // a corner at the far end; the first node meets a line (no in-handle)
  const G3CubicReport report = make_cubics_g3(nodes, false, std::vector<double>(4, 1.0), {5e-4, 0});
  EXPECT_EQ(report.runs_g3, 1);
  const std::vector<Cubic> faired = cubics_of(nodes, false);
  EXPECT_EQ(faired.front().p[0], source.front().p[0]);
  EXPECT_NEAR(*end_curvature(Segment(faired.front()), SegmentEnd::start).curvature, 0.0, 1e-15);
  const Jumps j = inner_jumps(faired, false);
  EXPECT_LE(j.curvature, 1e-6);
  EXPECT_LE(j.slope, 1e-4);
}

TEST(G3Cubics, ARunAlreadyG3StaysAsItIs) {
  // One cubic cut in three: joined C∞, so G3 already.
  const Cubic whole{{0, 0}, {200, 300}, {500, 320}, {700, 100}};
  const std::array<Cubic, 2> a = whole.split(1.0 / 3.0);
  const std::array<Cubic, 2> b = a[1].split(0.5);
  std::vector<OutlineNode> nodes = nodes_of({a[0], b[0], b[1]}, false);
  nodes.front().smooth = nodes.back().smooth = false;
  const std::vector<OutlineNode> before = nodes;
  const G3CubicReport report = make_cubics_g3(nodes, false, std::vector<double>(3, 1.0), {5e-4, 0});
  EXPECT_EQ(report.runs_g3, 1);
  ASSERT_EQ(nodes.size(), before.size());
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    EXPECT_LE(distance(nodes[i].point, before[i].point), 1e-9) << i;
    if (nodes[i].out_handle) {
      EXPECT_LE(distance(*nodes[i].out_handle, *before[i].out_handle), 1e-9) << i;
    }
    if (nodes[i].in_handle) {
      EXPECT_LE(distance(*nodes[i].in_handle, *before[i].in_handle), 1e-9) << i;
    }
  }
}

TEST(G3Cubics, WithoutAnAllowanceNothingMoves) {
  const auto curve = [](double t) { return ellipse(600.0, 300.0, t); };
  std::vector<OutlineNode> nodes = nodes_of(hermite_run(curve, {0.0, 0.5, 1.3, 2.1, pi}), false);
  nodes.front().smooth = nodes.back().smooth = false;
  const std::vector<OutlineNode> before = nodes;
  const G3CubicReport report = make_cubics_g3(nodes, false, std::vector<double>(4, 0.0), {5e-4, 3});
  EXPECT_EQ(report.runs, 1);
  EXPECT_EQ(report.runs_moved, 0);
  EXPECT_EQ(report.nodes_added, 0);
  EXPECT_EQ(nodes, before);
}

}  // namespace
}  // namespace gf
