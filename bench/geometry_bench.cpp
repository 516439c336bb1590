// The analysis every check and every fairing runs per segment.
#include <benchmark/benchmark.h>

#include "geom/arc_length.hpp"
#include "geom/critical_points.hpp"
#include "geom/curvature.hpp"
#include "geom/join.hpp"
#include "geom/tolerance_band.hpp"

#include <cmath>
#include <numbers>
#include <vector>

namespace gf {
namespace {

const Cubic bowl{{1069, 639}, {1069, 952}, {874, 1147}, {589, 1147}};
const Cubic s_curve{{0, 0}, {310, 420}, {520, -380}, {900, 60}};

void critical_points_of_cubic(benchmark::State& state) {
  const Segment s = state.range(0) ? Segment(s_curve) : Segment(bowl);
  for (auto _ : state) benchmark::DoNotOptimize(critical_points(s));
}
BENCHMARK(critical_points_of_cubic)->Arg(0)->Arg(1)->ArgName("s_curve");

void arc_length_of_cubic(benchmark::State& state) {
  const Segment s = s_curve;
  for (auto _ : state) benchmark::DoNotOptimize(arc_length(s));
}
BENCHMARK(arc_length_of_cubic);

void curvature_at(benchmark::State& state) {
  const Segment s = s_curve;
  double t = 0.0;
  for (auto _ : state) {
    t = t > 1.0 ? 0.0 : t + 0.01;
    benchmark::DoNotOptimize(curvature(derivatives_at(s, t)));
  }
}
BENCHMARK(curvature_at);

void joins_of_contour(benchmark::State& state) {
  Contour c;
  c.segments = {bowl, Line{{589, 1147}, {200, 1147}}, Cubic{{200, 1147}, {0, 1000}, {0, 639}, {1069, 639}}};
  c.nodes.assign(3, NodeFlags{});
  for (auto _ : state) benchmark::DoNotOptimize(joins_of(c));
}
BENCHMARK(joins_of_contour);

// A circle of radius 300 in the band of 2.4 units around it, in 8 pieces: a quarter of its
// source sampled every 3 units answers to each, and a candidate replacement (an arc of 96
// chords, `range(0)` hundredths of a unit out) is measured against them, as rounding measures
// a cubic moved past its allowance. Held (1, 2) and refused (3: 3 units out).
void tolerance_band_holds(benchmark::State& state) {
  const double r = 300.0, gap = 0.01 * double(state.range(0));
  auto circle = [&](double radius, double a0, double a1, int n) {
    std::vector<Vec2> out;
    for (int k = 0; k <= n; ++k) {
      const double a = a0 + (a1 - a0) * k / n;
      out.push_back({radius * std::cos(a), radius * std::sin(a)});
    }
    return out;
  };
  const double tau = 2.0 * std::numbers::pi;
  const std::vector<Vec2> source = circle(r, 0.0, tau, 628), faired = circle(r, 0.0, tau, 256);
  std::vector<std::size_t> piece_of;
  for (std::size_t k = 0; k < faired.size(); ++k) piece_of.push_back(std::min<std::size_t>(k / 32, 7));
  const ToleranceBand band(source, nearest_pieces(PolylineGrid(faired, 8.0), piece_of, source), 2.4);
  const std::vector<Vec2> replacement = circle(r + gap, 0.0, tau / 8.0, 96);
  for (auto _ : state) benchmark::DoNotOptimize(band.holds(0, replacement));
}
BENCHMARK(tolerance_band_holds)->Arg(100)->Arg(200)->Arg(300)->ArgName("hundredths_out");

}  // namespace
}  // namespace gf
