// glyphfair fair's cost per glyph and per stage (the whole-font figures come from the command
// itself: see the closing notes).
#include <benchmark/benchmark.h>

#include "fair/cubic_change.hpp"
#include "fair/g3_run.hpp"
#include "fair/glyph_fairing.hpp"
#include "fair/initial_tangents.hpp"
#include "geom/g2_hermite.hpp"
#include "geom/smoothing_spline.hpp"
#include "io/source.hpp"

namespace gf {
namespace {

void fair_every_glyph(benchmark::State& state, const std::string& font, FairProfile profile,
                      Continuity continuity = Continuity::g2) {
  const GlyphSet set = GlyphSource::open(font).load_all();
  FairOptions options;
  options.profile = profile;
  options.continuity = continuity;
  const FairSettings settings = resolve_settings(options, set.font.units_per_em);
  for (auto _ : state)
    for (const Glyph& g : set.glyphs) benchmark::DoNotOptimize(fair_glyph(g, settings));
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * set.glyphs.size()));
}

// As `glyphfair fair` does it: a contour that a composite repeats is faired once (the subset's
// adieresis, eacute, fi, fl …).
void fair_font_sharing_contours(benchmark::State& state, const std::string& font) {
  const GlyphSet set = GlyphSource::open(font).load_all();
  const FairSettings settings = resolve_settings({}, set.font.units_per_em);
  for (auto _ : state) {
    FairedContours faired;
    for (const Glyph& g : set.glyphs) benchmark::DoNotOptimize(fair_glyph(g, settings, faired));
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * set.glyphs.size()));
}
BENCHMARK_CAPTURE(fair_font_sharing_contours, dejavu_text,
                  std::string(GLYPHFAIR_FONTS) + "/DejaVuSans/DejaVuSans-subset.ttf")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(fair_every_glyph, dejavu_text, std::string(GLYPHFAIR_FONTS) + "/DejaVuSans/DejaVuSans-subset.ttf",
                  FairProfile::text)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(fair_every_glyph, dejavu_text_g3, std::string(GLYPHFAIR_FONTS) + "/DejaVuSans/DejaVuSans-subset.ttf",
                  FairProfile::text, Continuity::g3)
    ->Unit(benchmark::kMillisecond);
// EB Garamond's d, G, I, W and K: serifs whose joins the grid matches only after fairings again
// (K's one contour alone was faired 33 times, 57 s, until stop 109).
BENCHMARK_CAPTURE(fair_every_glyph, eb_garamond_text,
                  std::string(GLYPHFAIR_FONTS) + "/EBGaramond/EBGaramond12-Regular-subset.otf", FairProfile::text)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(fair_every_glyph, because_we_learn_handwriting,
                  std::string(GLYPHFAIR_FONTS) + "/BecauseWeLearn/BecauseWeLearn-Regular-subset.otf",
                  FairProfile::handwriting)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(fair_every_glyph, because_we_learn_handwriting_g3,
                  std::string(GLYPHFAIR_FONTS) + "/BecauseWeLearn/BecauseWeLearn-Regular-subset.otf",
                  FairProfile::handwriting, Continuity::g3)
    ->Unit(benchmark::kMillisecond);

// One G3 solve of a closed run of n junctions around a 300 × 180 ellipse (3n unknowns; past 150
// the Newton steps factor sparse): what a handwriting run cut many times over costs.
void g3_run_ellipse(benchmark::State& state) {
  const auto n = static_cast<int>(state.range(0));
  std::vector<G3Node> nodes;
  std::vector<double> lengths;
  double angle = 0.0;
  for (int k = 0; k < n; ++k) {
    const double t = 6.283185307179586 * k / n, dt = 6.283185307179586 / n;
    const Vec2 d{-300 * std::sin(t), 180 * std::cos(t)};
    if (k > 0) angle += wrapped_angle(std::atan2(d.y, d.x) - angle);
    else angle = std::atan2(d.y, d.x);
    nodes.push_back({{300 * std::cos(t), 180 * std::sin(t)}, angle, 300 * 180 / std::pow(norm(d), 3), G3NodeKind::smooth});
    lengths.push_back(norm(Vec2{-300 * std::sin(t + dt / 2), 180 * std::cos(t + dt / 2)}) * dt);
  }
  for (auto _ : state) benchmark::DoNotOptimize(make_g3(nodes, lengths, true));
}
BENCHMARK(g3_run_ellipse)->Arg(8)->Arg(96)->Arg(384)->Unit(benchmark::kMillisecond);

void g2_hermite_quarter(benchmark::State& state) {
  const HermiteEnd s{{300.0, 0.0}, {0.0, 1.0}, 1.0 / 300.0};
  const HermiteEnd e{{0.0, 300.0}, {-1.0, 0.0}, 1.0 / 250.0};
  for (auto _ : state) benchmark::DoNotOptimize(g2_hermite_cubics(s, e));
}
BENCHMARK(g2_hermite_quarter);

// A candidate cubic against the unrounded one it would replace, sampled once, as rounding
// weighs every candidate: its handle moved `range(0)` tenths of a unit across the curve, within
// an allowance of a unit (5: its control points are within; 20: the curves are within, though
// not the handle; 80: past it at the middle).
void moved_distance_of_candidate(benchmark::State& state) {
  const Cubic unrounded{{{1069, 639}, {1069, 952}, {874, 1147}, {589, 1147}}};
  const SampledCubic sampled(unrounded);
  Cubic candidate = unrounded;
  candidate.p[1].x -= 0.1 * double(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(moved_distance(candidate, sampled, 1.0));
}
BENCHMARK(moved_distance_of_candidate)->Arg(5)->Arg(20)->Arg(80)->ArgName("tenths_moved");

void balanced_tangents_closed(benchmark::State& state) {
  std::vector<Vec2> pts;
  for (int i = 0; i < state.range(0); ++i) {
    const double t = 6.283185307179586 * i / static_cast<double>(state.range(0));
    pts.push_back({300 * std::cos(t), 200 * std::sin(t)});
  }
  for (auto _ : state) benchmark::DoNotOptimize(balanced_tangents(pts, true, std::nullopt, std::nullopt));
}
BENCHMARK(balanced_tangents_closed)->Arg(8)->Arg(32);

// The handwriting guide of one closed run: 600 points with 3-unit wobbles, within 5 units.
void smoothing_spline_closed(benchmark::State& state) {
  std::vector<Vec2> pts;
  for (int i = 0; i < 600; ++i) {
    const double t = 6.283185307179586 * i / 600.0;
    const double r = 200.0 + 3.0 * std::sin(37.0 * t) * std::cos(11.0 * t);
    pts.push_back({r * std::cos(t), r * std::sin(t)});
  }
  for (auto _ : state)
    benchmark::DoNotOptimize(fit_smoothing_spline(pts, 5.0, static_cast<int>(state.range(0)), true));
}
BENCHMARK(smoothing_spline_closed)->Arg(20)->Arg(80)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace gf
