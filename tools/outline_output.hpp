// The outline outputs of convert and fair, chosen by the output's extension.
#pragma once

#include <filesystem>
#include <span>

#include "geom/contour.hpp"

namespace gf {

enum class OutlineFormat { ufo, svg, json };

/// From OUT's extension (any case); InputError for anything else.
OutlineFormat outline_format_for(const std::filesystem::path& output);

/// Written atomically, never over one of `inputs`.
void write_outlines(const GlyphSet& glyphs, const std::filesystem::path& target, OutlineFormat format,
                    std::span<const std::filesystem::path> inputs);

}  // namespace gf
