// SVG output: one <path> per glyph, side by side along a baseline, each drawn in font units
// through matrix(1 0 0 -1 x 0) so its `d` keeps the font's own coordinates; a viewBox from
// the metrics. data-glyph-name, data-advance and data-origin-x let glyphfair read it back exactly.
#pragma once

#include <filesystem>
#include <span>
#include <string>

#include "geom/contour.hpp"

namespace gf {

std::string svg_document(const GlyphSet& glyphs);

/// Writes atomically; never over one of `inputs`. Throws OutputError.
void write_svg(const GlyphSet& glyphs, const std::filesystem::path& target,
               std::span<const std::filesystem::path> inputs = {});

}  // namespace gf
