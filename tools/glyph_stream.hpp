// Whole fonts through a command: glyphs are read in order (FreeType faces are not
// thread-safe), worked on in parallel a chunk at a time, and handed on in order, so memory
// stays flat however large the font.
#pragma once

#include <algorithm>
#include <optional>
#include <vector>

#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include "io/source.hpp"
#include "progress.hpp"

namespace gf {

/// At most `jobs` threads while the returned object lives (0: every core).
inline std::optional<tbb::global_control> limit_parallelism(int jobs) {
  std::optional<tbb::global_control> limit;
  if (jobs > 0) limit.emplace(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(jobs));
  return limit;
}

/// `work(const Glyph&) -> Result` in parallel, then `take(Glyph&, Result&)` in the source's order.
template <typename Result, typename Work, typename Take>
void stream_glyphs(const GlyphSource& source, std::size_t chunk_size, const Progress& progress, const std::string& label,
                   Work&& work, Take&& take) {
  std::vector<Glyph> glyphs;
  std::vector<Result> results;
  for (std::size_t first = 0; first < source.size(); first += chunk_size) {
    const std::size_t last = std::min(source.size(), first + chunk_size);
    glyphs.clear();
    for (std::size_t i = first; i < last; ++i)
      if (auto g = source.load(i)) glyphs.push_back(std::move(*g));
    results.assign(glyphs.size(), Result{});
    tbb::parallel_for(std::size_t{0}, glyphs.size(), [&](std::size_t k) { results[k] = work(glyphs[k]); });
    for (std::size_t k = 0; k < glyphs.size(); ++k) take(glyphs[k], results[k]);
    progress.show(label, last, source.size());
  }
  progress.clear();
}

}  // namespace gf
