// UFO 3 output: glyph names, unicodes, advance widths, smooth flags, contour order, direction
// and start points as in the model; quadratic runs with implied on-curve points as `qcurve`.
#pragma once

#include <filesystem>
#include <span>

#include "geom/contour.hpp"

namespace gf {

/// Writes atomically (a staging directory renamed into place); never over one of `inputs`.
/// Throws OutputError.
void write_ufo(const GlyphSet& glyphs, const std::filesystem::path& target,
               std::span<const std::filesystem::path> inputs = {});

}  // namespace gf
