// Reading glyphs from fonts and writing them out: the per-glyph cost of the I/O edges.
#include <benchmark/benchmark.h>

#include <filesystem>

#include "io/freetype_reader.hpp"
#include "io/json_writer.hpp"
#include "io/source.hpp"
#include "io/ufo_writer.hpp"

namespace gf {
namespace {

const std::string fonts = GLYPHFAIR_FONTS;

void load_every_glyph(benchmark::State& state, const std::string& font) {
  const FreetypeFont f = FreetypeFont::open(font);
  for (auto _ : state)
    for (std::uint32_t g = 0; g < f.glyph_count(); ++g) benchmark::DoNotOptimize(f.load_glyph(g));
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * f.glyph_count());
}
BENCHMARK_CAPTURE(load_every_glyph, truetype_dejavu, fonts + "/DejaVuSans/DejaVuSans-subset.ttf");
BENCHMARK_CAPTURE(load_every_glyph, cff_because_we_learn, fonts + "/BecauseWeLearn/BecauseWeLearn-Regular-subset.otf");
BENCHMARK_CAPTURE(load_every_glyph, cff2_at_a_location_via_harfbuzz, fonts + "/Inter/GlyphfairProbe-CFF2.var.otf");

void write_ufo_of_font(benchmark::State& state) {
  const GlyphSet set = GlyphSource::open(fonts + "/DejaVuSans/DejaVuSans-subset.ttf").load_all();
  const auto target = std::filesystem::temp_directory_path() / "glyphfair-bench.ufo";
  for (auto _ : state) write_ufo(set, target);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * set.glyphs.size()));
  std::filesystem::remove_all(target);
}
BENCHMARK(write_ufo_of_font)->Unit(benchmark::kMillisecond);

void json_with_analysis(benchmark::State& state) {
  const GlyphSet set = GlyphSource::open(fonts + "/DejaVuSans/DejaVuSans-subset.ttf").load_all();
  for (auto _ : state) benchmark::DoNotOptimize(outline_json(set));
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * set.glyphs.size()));
}
BENCHMARK(json_with_analysis)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace gf
