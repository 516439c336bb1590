// Glyph outlines from TrueType, CFF and CFF2 OpenType fonts (static or variable) through
// FreeType, in font units, y up, with the source's structure kept: TrueType quadratics stay
// quadratics and their implied on-curve points are marked as implied.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "geom/contour.hpp"
#include "io/variation_location.hpp"

namespace gf {

struct FontLoadOptions {
  /// Design coordinates for a variable font; unset axes stay at the instance or default value.
  std::vector<AxisValue> location;
  /// A named instance by its name ("Bold") or 1-based number.
  std::optional<std::string> named_instance;
};

struct VariationAxis {
  std::string tag;
  double minimum = 0.0, default_value = 0.0, maximum = 0.0;
};

class FreetypeFont {
 public:
  /// Throws InputError (one line naming the file) for a missing, unreadable, truncated or
  /// non-font file, and for a location or instance the font does not have.
  static FreetypeFont open(const std::filesystem::path& path, const FontLoadOptions& options = {});
  FreetypeFont(FreetypeFont&&) noexcept;
  FreetypeFont& operator=(FreetypeFont&&) noexcept;
  ~FreetypeFont();

  const FontInfo& info() const;
  std::uint32_t glyph_count() const;
  const std::string& glyph_name(std::uint32_t gid) const;
  std::optional<std::uint32_t> glyph_by_name(std::string_view name) const;
  std::optional<std::uint32_t> glyph_by_codepoint(char32_t c) const;
  /// Every mapped code point with its glyph, ascending.
  std::span<const std::pair<char32_t, std::uint32_t>> character_map() const;
  std::vector<VariationAxis> axes() const;
  /// The design location in force, every axis listed (empty for a static font).
  const std::vector<AxisValue>& location() const;
  std::span<const std::uint8_t> bytes() const;

  /// Throws InputError naming the file and glyph when FreeType cannot load it.
  Glyph load_glyph(std::uint32_t gid) const;

 private:
  struct Impl;
  explicit FreetypeFont(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace gf
