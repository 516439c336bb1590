// Whole fonts through a command: glyphs are read in order (FreeType faces are not
// thread-safe), worked on in parallel, and handed on in order, at most a set number in memory
// at a time, so memory stays flat however large the font.
#pragma once

#include <algorithm>
#include <memory>
#include <optional>

#include <tbb/global_control.h>
#include <tbb/parallel_pipeline.h>

#include "io/source.hpp"
#include "progress.hpp"

namespace gf {

/// At most `jobs` threads while the returned object lives (0: every core).
inline std::optional<tbb::global_control> limit_parallelism(int jobs) {
  std::optional<tbb::global_control> limit;
  if (jobs > 0) limit.emplace(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(jobs));
  return limit;
}

/// `work(const Glyph&) -> Result` in parallel, then `take(Glyph&, Result&)` in the source's
/// order, with at most `in_flight` glyphs read and not yet taken. A pipeline rather than
/// chunks with a barrier after each: glyph times run long-tailed (whole DejaVu Sans: 14 ms a
/// glyph on average, one glyph 4.6 s), and at each barrier one thread idled while the other
/// finished.
template <typename Result, typename Work, typename Take>
void stream_glyphs(const GlyphSource& source, std::size_t in_flight, const Progress& progress, const std::string& label,
                   Work&& work, Take&& take) {
  struct Item {
    std::size_t index = 0;
    std::optional<Glyph> glyph;  // none where the source has no glyph to load
    Result result{};
  };
  using Carried = std::shared_ptr<Item>;  // pipeline tokens must be copyable
  const std::size_t every = std::max<std::size_t>(1, in_flight / 4);  // glyphs between progress updates
  std::size_t next = 0;
  const auto read = [&](tbb::flow_control& control) -> Carried {
    if (next == source.size()) {
      control.stop();
      return nullptr;
    }
    auto item = std::make_shared<Item>();
    item->index = next;
    item->glyph = source.load(next++);
    return item;
  };
  const auto run = [&](Carried item) {
    if (item->glyph) item->result = work(*item->glyph);
    return item;
  };
  const auto hand_on = [&](Carried item) {
    if (item->glyph) take(*item->glyph, item->result);
    const std::size_t done = item->index + 1;
    if (done % every == 0 || done == source.size()) progress.show(label, done, source.size());
  };
  tbb::parallel_pipeline(in_flight, tbb::make_filter<void, Carried>(tbb::filter_mode::serial_in_order, read) &
                                        tbb::make_filter<Carried, Carried>(tbb::filter_mode::parallel, run) &
                                        tbb::make_filter<Carried, void>(tbb::filter_mode::serial_in_order, hand_on));
  progress.clear();
}

}  // namespace gf
