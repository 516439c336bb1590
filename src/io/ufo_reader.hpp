// UFO 2/3 input: the default layer's glyphs with their contours (point types move, line,
// curve, qcurve, offcurve; smooth flags), components decomposed, metrics from fontinfo.plist.
#pragma once

#include <filesystem>

#include "geom/contour.hpp"

namespace gf {

/// Glyphs in public.glyphOrder order, then the rest by name. Throws InputError naming the
/// UFO and glyph for anything malformed.
GlyphSet read_ufo(const std::filesystem::path& ufo);

}  // namespace gf
