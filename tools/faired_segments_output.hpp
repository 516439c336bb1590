// `glyphfair fair --segments FILE.json`: the faired curve before the cubic writeback, glyph by
// glyph and piece by piece, with each piece's end frames (κ and κ′), so the continuity the
// fairing claims can be checked outside it (docs/json-format.md, "Faired segments").
#pragma once

#include <filesystem>
#include <span>
#include <string>

#include <nlohmann/json.hpp>

#include "fair/fair_options.hpp"
#include "fair/glyph_fairing.hpp"

namespace gf {

class FairedSegmentsOutput {
 public:
  FairedSegmentsOutput(std::string source, const FairSettings& settings, double units_per_em);
  void add(const GlyphFairing& glyph);
  /// Written atomically, never over one of `inputs`.
  void write(const std::filesystem::path& target, std::span<const std::filesystem::path> inputs) const;

 private:
  nlohmann::ordered_json document_;
};

}  // namespace gf
