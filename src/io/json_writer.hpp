// JSON output: the outline and its analysis (docs/json-format.md documents the schema).
#pragma once

#include <filesystem>
#include <span>
#include <string>

#include "geom/contour.hpp"

namespace gf {

inline constexpr int json_format_version = 1;

std::string outline_json(const GlyphSet& glyphs);

/// Writes atomically; never over one of `inputs`. Throws OutputError.
void write_json(const GlyphSet& glyphs, const std::filesystem::path& target,
                std::span<const std::filesystem::path> inputs = {});

}  // namespace gf
