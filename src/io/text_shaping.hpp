// The glyphs a text really uses in a font, shaped with HarfBuzz: ligatures, contextual and
// positional forms included.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "io/variation_location.hpp"

namespace gf {

/// Glyph indices in order of first use, each once. `location` applies feature variations.
/// Throws InputError when the text is not valid UTF-8.
std::vector<std::uint32_t> glyphs_for_text(std::span<const std::uint8_t> font_bytes,
                                           std::span<const AxisValue> location, std::string_view text);

}  // namespace gf
