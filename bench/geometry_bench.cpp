// The analysis every check and every fairing runs per segment.
#include <benchmark/benchmark.h>

#include "geom/arc_length.hpp"
#include "geom/critical_points.hpp"
#include "geom/curvature.hpp"
#include "geom/join.hpp"

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

}  // namespace
}  // namespace gf
