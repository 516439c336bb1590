// glyphfair proof SRC [selection] [--compare OTHER] -o FILE.pdf|.png|.svg
#include <filesystem>
#include <unordered_map>

#include "commands.hpp"
#include "exit_codes.hpp"
#include "io/input_error.hpp"
#include "render/proof_document.hpp"

namespace fs = std::filesystem;

namespace gf {

void ProofCommand::add_to(CLI::App& app) {
  add(app, "proof", "Draw proofs: outlines, points, curvature combs, marks and κ(s) plots",
      "FILE.pdf (a page per glyph), FILE.png or FILE.svg")
      .add_option("--compare", compare_, "Overlay the same glyphs (by name) from this second source");
}

int ProofCommand::run() const {
  if (!proof_format_for(output_)) throw InputError(output_ + ": unknown proof format (use .pdf, .png or .svg)");
  const SourceOptions options = selection_.parse();
  const GlyphSource source = GlyphSource::open(source_, options);
  const GlyphSet glyphs = source.load_all();

  std::vector<ProofGlyph> pages;
  ProofOptions proof;
  const FontInfo& f = glyphs.font;
  proof.title = fs::path(source_).filename().string() + "  " + f.family_name + " " + f.style_name;
  if (compare_.empty()) {
    for (const Glyph& g : glyphs.glyphs) pages.push_back({g, std::nullopt});
  } else {
    // The other version is looked up by glyph name; location options apply to both.
    SourceOptions other = options;
    other.selection = {};
    for (const Glyph& g : glyphs.glyphs) other.selection.names.push_back(g.name);
    GlyphSource compare = GlyphSource::open(compare_, other);
    const GlyphSet versions = compare.load_all();
    std::unordered_map<std::string, const Glyph*> by_name;
    for (const Glyph& g : versions.glyphs) by_name.emplace(g.name, &g);
    for (const Glyph& g : glyphs.glyphs) {
      const auto it = by_name.find(g.name);
      pages.push_back({g, it == by_name.end() ? std::nullopt : std::optional<Glyph>(*it->second)});
    }
    proof.has_compare = true;
    proof.compare_label = fs::path(compare_).filename().string();
  }
  const fs::path inputs[] = {source_, compare_.empty() ? fs::path() : fs::path(compare_)};
  write_proof(pages, f, proof, output_, inputs);
  return exit_code::ok;
}

}  // namespace gf
