// The proof a type designer prints: per glyph a page with the outline, its points and handles,
// signed curvature combs, marks at inflections, curvature extrema and H/V extrema, and below
// it κ(s) along each contour with the joins marked. Optionally a second version of the same
// glyphs overlaid in another colour, with both κ(s) plotted.
#pragma once

#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "geom/contour.hpp"

namespace gf {

struct ProofGlyph {
  Glyph glyph;
  std::optional<Glyph> compare;  ///< the other version, when --compare found it
};

struct ProofOptions {
  std::string title;          ///< e.g. the source file and font name
  std::string compare_label;  ///< what the overlay is, e.g. its file name
  bool has_compare = false;
};

enum class ProofFormat { pdf, png, svg };

/// From the target's extension; nullopt for anything else.
std::optional<ProofFormat> proof_format_for(const std::filesystem::path& target);

/// PDF: one page per glyph. PNG and SVG: the pages stacked in one image. Written atomically,
/// never over one of `inputs`. Throws OutputError.
void write_proof(std::span<const ProofGlyph> glyphs, const FontInfo& font, const ProofOptions& options,
                 const std::filesystem::path& target, std::span<const std::filesystem::path> inputs = {});

}  // namespace gf
