// Any glyph source by its path: a font file (TrueType, CFF, CFF2, variable) through FreeType,
// a UFO directory, or an SVG file; with the selection applied.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>

#include "geom/contour.hpp"
#include "io/freetype_reader.hpp"
#include "io/glyph_selection.hpp"

namespace gf {

struct SourceOptions {
  FontLoadOptions font;
  GlyphSelection selection;
};

/// What kind of file a source is: its outlines are a designer's own (font, UFO), traced paths
/// (SVG) or fitted to handwritten points (JSON).
enum class SourceKind { font, ufo, svg, points };

class GlyphSource {
 public:
  /// Throws InputError (one line naming the file and problem).
  static GlyphSource open(const std::filesystem::path& path, const SourceOptions& options = {});
  GlyphSource(GlyphSource&&) noexcept;
  GlyphSource& operator=(GlyphSource&&) noexcept;
  ~GlyphSource();

  const FontInfo& font() const;
  const std::filesystem::path& path() const;
  SourceKind kind() const;
  /// Number of selected glyphs.
  std::size_t size() const;
  /// The i-th selected glyph. With no selection (the whole source), glyphs without an outline
  /// are skipped: nullopt. Throws InputError naming the glyph when it cannot be read.
  std::optional<Glyph> load(std::size_t i) const;
  /// All selected glyphs that load(i) returns.
  GlyphSet load_all() const;

 private:
  struct Impl;
  explicit GlyphSource(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace gf
