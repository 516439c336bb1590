// The run-wide G3 solve: junction frames from exact curves (a circle, an ellipse, a sine wave,
// a clothoid leaving a line), each checked for what G3 promises — every spiral meets the next
// junction in point, tangent, κ and κ′, κ(s) monotone on every piece — and the circle, whose
// answer is known, for that answer.
#include "fair/g3_run.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "aesthetic/clothoid_g1.hpp"

namespace gf {
namespace {

constexpr double pi = std::numbers::pi;

// Every spiral's far end is the next one's start, to the solve's tolerance; κ and κ′ exactly.
void expect_g3(const G3Result& r, bool closed) {
  ASSERT_TRUE(r.ok()) << r.reason;
  const std::size_t m = r.spirals.size();
  for (std::size_t i = 0; i < m; ++i) {
    const PolynomialSpiral& a = r.spirals[i];
    EXPECT_TRUE(a.curvature_monotone()) << "segment " << i;
    if (!closed && i + 1 == m) break;
    const PolynomialSpiral& b = r.spirals[(i + 1) % m];
    const LacPoint e = a.end(), s = b.start();
    const double scale = a.length();
    EXPECT_NEAR(distance(e.point, s.point) / scale, 0.0, 1e-10) << "junction " << i + 1;
    EXPECT_NEAR(cross(e.tangent, s.tangent), 0.0, 1e-10);
    EXPECT_GT(dot(e.tangent, s.tangent), 0.0);
    EXPECT_NEAR(e.curvature, s.curvature, 1e-12 / scale);
    const double ka = *e.curvature_derivative, kb = *s.curvature_derivative;
    // Relative, or absolute where κ′ is 0 (rounding in the spirals' polynomials: 1e-21).
    EXPECT_LE(std::abs(ka - kb), std::max(1e-9 * std::max(std::abs(ka), std::abs(kb)), 1e-12 * std::abs(e.curvature) / scale))
        << "junction " << i + 1;
  }
}

TEST(G3Run, ACircleStaysTheCircle) {
  // Four quarter arcs, lengths started 10 % off: the answer is the circle, κ′ = 0 everywhere.
  const double r = 250.0;
  std::vector<G3Node> nodes;
  for (int k = 0; k < 4; ++k) {
    const double t = k * pi / 2;
    nodes.push_back({{r * std::cos(t), r * std::sin(t)}, t + pi / 2, 1.0 / r, G3NodeKind::smooth});
  }
  const std::vector<double> lengths(4, 1.1 * r * pi / 2);
  const G3Result g = make_g3(nodes, lengths, true);
  expect_g3(g, true);
  for (const PolynomialSpiral& s : g.spirals) {
    EXPECT_NEAR(s.length(), r * pi / 2, 1e-8 * r);
    for (const LacPoint& p : s.sample(16)) {
      EXPECT_NEAR(p.curvature, 1.0 / r, 1e-12);
      EXPECT_NEAR(norm(p.point), r, 1e-8 * r);
    }
  }
}

// The ellipse x = a cos t, y = b sin t with `count` junctions evenly in t (a multiple of 4: its
// four extrema of curvature among them); κ from the ellipse, the lengths by the midpoint rule.
struct EllipseRun {
  static constexpr double a = 300.0, b = 180.0;
  std::vector<G3Node> nodes;
  std::vector<double> lengths;
};

EllipseRun ellipse_run(int count) {
  const double a = EllipseRun::a, b = EllipseRun::b, step = 2.0 * pi / count;
  EllipseRun e;
  for (int k = 0; k < count; ++k) {
    const double t = k * step;
    const double speed = std::hypot(a * std::sin(t), b * std::cos(t));
    e.nodes.push_back({{a * std::cos(t), b * std::sin(t)}, std::atan2(b * std::cos(t), -a * std::sin(t)),
                       a * b / (speed * speed * speed), G3NodeKind::smooth});
    double len = 0.0;
    for (int q = 0; q < 2000; ++q) {
      const double u = t + (q + 0.5) * step / 2000;
      len += std::hypot(a * std::sin(u), b * std::cos(u)) * step / 2000;
    }
    e.lengths.push_back(len);
  }
  for (std::size_t k = 1; k < e.nodes.size(); ++k)  // unwrap along the run
    e.nodes[k].tangent_angle =
        e.nodes[k - 1].tangent_angle + wrapped_angle(e.nodes[k].tangent_angle - e.nodes[k - 1].tangent_angle);
  return e;
}

// G3 on every junction, κ′ = 0 at the ellipse's extrema of curvature (junctions whose secants
// differ in sign), every spiral near the ellipse.
void expect_g3_ellipse(int count) {
  const double a = EllipseRun::a, b = EllipseRun::b;
  const EllipseRun e = ellipse_run(count);
  const G3Result g = make_g3(e.nodes, e.lengths, true);
  expect_g3(g, true);
  for (int k = 0; k < count; k += count / 4) EXPECT_EQ(g.ends[static_cast<std::size_t>(k)].curvature_slope, 0.0);
  double far = 0.0;
  for (const PolynomialSpiral& s : g.spirals)
    for (const LacPoint& p : s.sample(32)) {
      // Distance to the ellipse, near enough: |F(p)| / |∇F| for F = (x/a)² + (y/b)² − 1.
      const double f = (p.point.x / a) * (p.point.x / a) + (p.point.y / b) * (p.point.y / b) - 1.0;
      const double grad = 2.0 * std::hypot(p.point.x / (a * a), p.point.y / (b * b));
      far = std::max(far, std::abs(f) / grad);
    }
  EXPECT_LT(far, 0.005 * a);
}

TEST(G3Run, AnEllipseComesOutG3NearTheEllipse) { expect_g3_ellipse(8); }

// 96 junctions, 288 unknowns: the Newton steps by sparse QR (geom/damped_newton.hpp), as for a
// run cut many times over.
TEST(G3Run, AnEllipseOfManyJunctionsComesOutG3Too) { expect_g3_ellipse(96); }

// y = A sin(x / B) from one crest to the next trough: corners at the ends, the inflection in
// the middle, smooth junctions halfway; the lengths by the midpoint rule.
struct SineWave {
  static constexpr int count = 5;
  std::vector<G3Node> nodes;
  std::vector<double> lengths;
};

SineWave sine_wave() {
  const double A = 60.0, B = 80.0;
  SineWave w;
  for (int k = 0; k < SineWave::count; ++k) {
    const double x = B * (pi / 2 + k * pi / 4);
    const double d1 = A / B * std::cos(x / B), d2 = -A / (B * B) * std::sin(x / B);
    const bool end = k == 0 || k == SineWave::count - 1;
    const G3NodeKind kind = end ? G3NodeKind::corner : (k == 2 ? G3NodeKind::inflection : G3NodeKind::smooth);
    w.nodes.push_back({{x, A * std::sin(x / B)}, std::atan(d1), d2 / std::pow(1 + d1 * d1, 1.5), kind});
    if (k + 1 < SineWave::count) {
      double len = 0.0;
      for (int q = 0; q < 2000; ++q) {
        const double u = x + (q + 0.5) * (B * pi / 4) / 2000;
        len += std::hypot(1.0, A / B * std::cos(u / B)) * (B * pi / 4) / 2000;
      }
      w.lengths.push_back(len);
    }
  }
  return w;
}

TEST(G3Run, ASineWaveBetweenCornersKeepsItsInflectionAtZeroCurvature) {
  const SineWave w = sine_wave();
  const G3Result g = make_g3(w.nodes, w.lengths, false);
  expect_g3(g, false);
  EXPECT_EQ(g.ends[2].curvature, 0.0);
  EXPECT_NE(g.ends[2].curvature_slope, 0.0);  // an inflection, not a flat stretch
  // The corners keep their points and tangents.
  for (const std::size_t k : {std::size_t{0}, std::size_t{SineWave::count - 1}}) {
    EXPECT_EQ(g.ends[k].point, w.nodes[k].point);
    EXPECT_EQ(g.ends[k].tangent_angle, w.nodes[k].tangent_angle);
  }
}

TEST(G3Run, HeldNodesKeepTheirCurvatureAndTheRunStaysG3) {
  // The sine wave, its first corner and the smooth node after it held at the sine's κ (what
  // g3_reexpression does to nodes the solve would carry across 0): each keeps its κ exactly, the
  // corner its point, and every junction is G3.
  SineWave w = sine_wave();
  w.nodes[0].kind = G3NodeKind::corner_held;
  w.nodes[1].kind = G3NodeKind::held;
  const G3Result g = make_g3(w.nodes, w.lengths, false);
  expect_g3(g, false);
  EXPECT_EQ(g.ends[0].curvature, w.nodes[0].curvature);
  EXPECT_EQ(g.ends[1].curvature, w.nodes[1].curvature);
  EXPECT_EQ(g.ends[0].point, w.nodes[0].point);
  EXPECT_EQ(g.ends[2].curvature, 0.0);
  // Free to turn, the held corner's tangent stays near the sine's: κ is what the sine has there.
  EXPECT_NEAR(g.ends[0].tangent_angle, w.nodes[0].tangent_angle, 0.05);
  EXPECT_EQ(g.ends[SineWave::count - 1].tangent_angle, w.nodes[SineWave::count - 1].tangent_angle);
}

TEST(G3Run, ACurveLeavingALineSlidesAlongItToMeetItG3) {
  // A clothoid (κ = s / 100) leaves the x axis at the origin, κ′ ≠ 0 there; G3 with the line
  // needs κ′ = 0, which the line end gets by sliding along the line.
  const double c = 0.01;
  std::vector<G3Node> nodes;
  std::vector<double> lengths;
  for (int k = 0; k <= 3; ++k) {
    const double s = 40.0 * k;
    Vec2 p{0.0, 0.0};
    for (int q = 0; q < 4000; ++q) {
      const double u = (q + 0.5) * s / 4000;
      p += direction_of(0.5 * c * u * u) * (s / 4000);
    }
    nodes.push_back({p, 0.5 * c * s * s, c * s, k == 0 ? G3NodeKind::line : (k == 3 ? G3NodeKind::corner : G3NodeKind::smooth),
                     k == 0 ? 1000.0 : 0.0});
    if (k < 3) lengths.push_back(40.0);
  }
  const G3Result g = make_g3(nodes, lengths, false);
  expect_g3(g, false);
  EXPECT_EQ(g.ends[0].curvature, 0.0);
  EXPECT_EQ(g.ends[0].curvature_slope, 0.0);
  EXPECT_EQ(g.ends[0].tangent_angle, 0.0);
  EXPECT_EQ(g.ends[0].point.y, 0.0);  // still on the line
  const double slide = -g.ends[0].point.x;
  EXPECT_GT(slide, 1.0);  // back into the line: the curve must start turning earlier, and slower
  // A line shorter than that slide has no room for it: no G3, and a reason.
  nodes[0].slide_room = 0.5 * slide;
  const G3Result short_line = make_g3(nodes, lengths, false);
  EXPECT_FALSE(short_line.ok());
  EXPECT_NE(short_line.reason.find("stalled"), std::string::npos) << short_line.reason;
}

// κ′ at every inner junction of `g` is the smooth mean of its secants (g3_run.hpp's
// SlopeRule): 4a²b² / ((a + b)(a² + b²)), 0 where they differ in sign, never past 1.11 times the
// smaller one.
void expect_smooth_mean_slopes(const G3Result& g, bool closed) {
  const std::size_t m = g.spirals.size();
  for (std::size_t j = closed ? 0 : 1; j < (closed ? m : m); ++j) {
    const PolynomialSpiral &before = g.spirals[(j + m - 1) % m], &after = g.spirals[j];
    const double a = (before.end().curvature - before.start().curvature) / before.length();
    const double b = (after.end().curvature - after.start().curvature) / after.length();
    const double slope = g.ends[j].curvature_slope;
    if (a * b <= 0.0) {
      EXPECT_EQ(slope, 0.0) << "junction " << j;
      continue;
    }
    EXPECT_NEAR(slope, 4 * a * a * b * b / ((a + b) * (a * a + b * b)), 1e-12 * std::abs(a + b)) << "junction " << j;
    EXPECT_LE(std::abs(slope), 1.11 * std::min(std::abs(a), std::abs(b))) << "junction " << j;
  }
}

TEST(G3Run, TheSmoothMeanOfTheSecantsGivesG3Too) {
  // The same runs with κ′ the smooth mean: every spiral meets the next junction in point,
  // tangent, κ and κ′ and keeps κ monotone, κ′ = 0 at the ellipse's extrema, κ = 0 kept at the
  // sine's inflection.
  for (const int count : {8, 96}) {
    const EllipseRun e = ellipse_run(count);
    const G3Result g = make_g3(e.nodes, e.lengths, true, SlopeRule::smooth_mean);
    expect_g3(g, true);
    expect_smooth_mean_slopes(g, true);
    for (int k = 0; k < count; k += count / 4) EXPECT_EQ(g.ends[static_cast<std::size_t>(k)].curvature_slope, 0.0);
  }
  const SineWave w = sine_wave();
  const G3Result g = make_g3(w.nodes, w.lengths, false, SlopeRule::smooth_mean);
  expect_g3(g, false);
  expect_smooth_mean_slopes(g, false);
  EXPECT_EQ(g.ends[2].curvature, 0.0);
}

// A piece of length 100 whose κ is 0 up to s = 90 and rises by 1 over the last 10: only
// curvature is read (cut_places).
PathPiece flat_then_steep() {
  const auto at = [](double s) {
    LacPoint p;
    p.curvature = std::max(0.0, (s - 90.0) / 10.0);
    return p;
  };
  const auto sample = [at](int n) {
    std::vector<LacPoint> out;
    for (int k = 0; k <= n; ++k) out.push_back(at(100.0 * k / n));
    return out;
  };
  return {100.0, at, sample};
}

TEST(G3Run, CutsCrowdWhereCurvatureChangesFast) {
  const PathPiece piece = flat_then_steep();
  // By length: 0, 25, 50, 75, 100.
  const std::vector<double> even = cut_places(piece, 4, CutPlacement::by_length);
  ASSERT_EQ(even.size(), 5u);
  for (int k = 0; k <= 4; ++k) EXPECT_DOUBLE_EQ(even[static_cast<std::size_t>(k)], 25.0 * k);
  // By length and curvature, (s / 100 + w(s)) / 2 at 1/4, 1/2, 3/4 with w = max(0, (s − 90) / 10):
  // s = 50, then s / 100 + s / 10 − 9 = 1 and 1.5, so s = 10 / 0.11 and 10.5 / 0.11.
  const std::vector<double> crowded = cut_places(piece, 4, CutPlacement::by_length_and_curvature);
  ASSERT_EQ(crowded.size(), 5u);
  EXPECT_EQ(crowded.front(), 0.0);
  EXPECT_EQ(crowded.back(), 100.0);
  EXPECT_NEAR(crowded[1], 50.0, 1e-9);
  // Linear between samples 1.5625 apart, across the kink at s = 90: within a tenth.
  EXPECT_NEAR(crowded[2], 10.0 / 0.11, 0.1);
  EXPECT_NEAR(crowded[3], 10.5 / 0.11, 0.1);
  // One piece: its ends only; constant κ: equal lengths.
  EXPECT_EQ(cut_places(piece, 1, CutPlacement::by_length_and_curvature), (std::vector<double>{0.0, 100.0}));
  PathPiece arc = piece;
  arc.sample = [](int n) { return std::vector<LacPoint>(static_cast<std::size_t>(n + 1), LacPoint{{0, 0}, {1, 0}, 0.01, std::nullopt}); };
  const std::vector<double> on_arc = cut_places(arc, 4, CutPlacement::by_length_and_curvature);
  for (int k = 0; k <= 4; ++k) EXPECT_NEAR(on_arc[static_cast<std::size_t>(k)], 25.0 * k, 1e-12);
}

TEST(G3Run, ARunWithoutChainsHasNoProblem) {
  const SmoothRun run;
  EXPECT_FALSE(g3_problem({}, run).has_value());
}

TEST(G3Run, SaysWhyWhenTheNodesDoNotFitTheSegments) {
  const G3Node n{{0, 0}, 0, 0, G3NodeKind::corner};
  const std::vector<G3Node> nodes{n, n, n};
  const std::vector<double> lengths{1.0};
  const G3Result g = make_g3(nodes, lengths, false);
  EXPECT_FALSE(g.ok());
  EXPECT_FALSE(g.reason.empty());
}

}  // namespace
}  // namespace gf
