// Which glyphs a command works on: by name, by code point, by shaped text, combinable.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "io/unicode_ranges.hpp"

namespace gf {

struct GlyphSelection {
  std::vector<std::string> names;
  std::vector<CodepointRange> unicodes;
  std::optional<std::string> text;

  bool empty() const { return names.empty() && unicodes.empty() && !text; }
};

/// What selection needs to know of a source.
struct GlyphCatalog {
  std::function<std::optional<std::uint32_t>(std::string_view)> by_name;
  /// Every mapped code point with its glyph, ascending.
  std::span<const std::pair<char32_t, std::uint32_t>> character_map;
  /// The glyphs `text` uses (shaped, for fonts; character by character, for UFO and SVG).
  std::function<std::vector<std::uint32_t>(std::string_view)> glyphs_for_text;
};

/// Glyph indices in the order the selection names them (names, then code points, then text),
/// each once. Throws InputError naming `file` and the glyph for an unknown name or a single
/// code point the source does not map, and when the whole selection is empty.
std::vector<std::uint32_t> resolve_selection(const GlyphSelection& selection, const GlyphCatalog& catalog,
                                             const std::string& file);

/// Split "a,b,c" (commas, optional spaces) into names.
std::vector<std::string> split_glyph_names(std::string_view list);

}  // namespace gf
