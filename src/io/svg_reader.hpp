// SVG input: every <path> is one glyph, named by its data-glyph-name or id. Its coordinates
// are mapped through the transforms on it and its ancestors and then flipped (font y = −SVG y),
// so an SVG drawn y-down with the baseline at y = 0 reads upright. glyphfair's own SVG output
// carries data-origin-x (subtracted again) and data-advance, so it reads back exactly.
#pragma once

#include <filesystem>

#include "geom/contour.hpp"

namespace gf {

/// Throws InputError naming the file (and path) for anything malformed.
GlyphSet read_svg(const std::filesystem::path& svg);

}  // namespace gf
