// glyphfair check's cost per glyph (the whole-font figures come from the command itself:
// see the closing notes).
#include <benchmark/benchmark.h>

#include "check/contour_checks.hpp"
#include "io/source.hpp"

namespace gf {
namespace {

void check_every_glyph(benchmark::State& state, const std::string& font) {
  const GlyphSet set = GlyphSource::open(font).load_all();
  const CheckProfile profile = *check_profile("text");
  for (auto _ : state)
    for (const Glyph& g : set.glyphs) benchmark::DoNotOptimize(check_glyph(g, set.font, profile));
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * set.glyphs.size()));
}
BENCHMARK_CAPTURE(check_every_glyph, dejavu_truetype, std::string(GLYPHFAIR_FONTS) + "/DejaVuSans/DejaVuSans-subset.ttf")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(check_every_glyph, because_we_learn_cff,
                  std::string(GLYPHFAIR_FONTS) + "/BecauseWeLearn/BecauseWeLearn-Regular-subset.otf")
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace gf
