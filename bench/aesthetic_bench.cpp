// The aesthetic engine's hot paths: the 3-point construction (issue bar: ≤ 10 µs median at
// 1e-12 accuracy) and dense sampling.
#include <benchmark/benchmark.h>

#include "aesthetic/clothoid_g1.hpp"
#include "aesthetic/curvature_profile_segment.hpp"
#include "aesthetic/lcg_slope.hpp"
#include "aesthetic/polynomial_spiral.hpp"
#include "aesthetic/profile_interpolation.hpp"
#include "aesthetic/segment_fit.hpp"

namespace gf {
namespace {

void three_point_construction(benchmark::State& state) {
  const double alpha = static_cast<double>(state.range(0)) / 2.0;
  for (auto _ : state) benchmark::DoNotOptimize(fit_three_point({0, 0}, {1, 0}, {2, 0.8}, alpha));
}
BENCHMARK(three_point_construction)->DenseRange(-4, 6, 2)->ArgName("alpha_x2");

void three_point_glyph_like(benchmark::State& state) {
  // A bowl quarter of a 1000-unit glyph, α = 1 (a log spiral), no closed form for the fit.
  for (auto _ : state) benchmark::DoNotOptimize(fit_three_point({589, 1147}, {874, 1147}, {1069, 639}, 0.7));
}
BENCHMARK(three_point_glyph_like);

void inflection_start_construction(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(fit_inflection_start({0, 0}, {1.8, 0}, {2.414, 1}));
}
BENCHMARK(inflection_start_construction);

void clothoid_g1_fit(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(fit_clothoid_g1({0, 0}, 0.3, {2, 1}, -0.4));
}
BENCHMARK(clothoid_g1_fit);

// The G3 segments on check_07's reference problem (lac-math.md §7.1), to 1e-12.
const CurvatureEnd g3_start{{0, 0}, 0.0, 1.0, 0.5};
const CurvatureEnd g3_end{{0.751193112803, 0.733640070028}, 1.766325, 2.0, 0.8};

void curvature_profile_fit(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(fit_curvature_profile(g3_start, g3_end));
}
BENCHMARK(curvature_profile_fit);

void polynomial_spiral_fit(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(fit_polynomial_spiral(g3_start, g3_end));
}
BENCHMARK(polynomial_spiral_fit);

// Five points of the clothoid κ = 0.2 + 0.5 s with their curvatures only: tangents settled by
// least squares, κ′ from the secants, four seed-004 segments.
void profile_interpolation(benchmark::State& state) {
  const CurvatureProfileSegment c({{0, 0}, 0.3, 0.2, 0.5}, 2.4, 0.8, 0.8, 1.4, 0.5);
  std::vector<InterpolationPoint> pts;
  for (int k = 0; k <= 4; ++k) pts.push_back({c.at_parameter(k / 4.0).point, c.at_parameter(k / 4.0).curvature, {}, {}});
  for (auto _ : state) benchmark::DoNotOptimize(interpolate_curvature_profiles(pts));
}
BENCHMARK(profile_interpolation);

void sampling(benchmark::State& state) {
  const LogAestheticSegment s = *fit_three_point({0, 0}, {1, 0}, {2, 0.8}, 1.5).segment;
  const int n = static_cast<int>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(s.sample(n));
  state.SetItemsProcessed(state.iterations() * n);
}
BENCHMARK(sampling)->Arg(16)->Arg(256)->Arg(4096);

void evaluate_at_arc_length(benchmark::State& state) {
  const LogAestheticSegment s = *fit_three_point({0, 0}, {1, 0}, {2, 0.8}, -1.0).segment;
  double sigma = 0.0;
  for (auto _ : state) {
    sigma = sigma > s.length() ? 0.0 : sigma + 0.01;
    benchmark::DoNotOptimize(s.at(sigma));
  }
}
BENCHMARK(evaluate_at_arc_length);

}  // namespace
}  // namespace gf
