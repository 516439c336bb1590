#include "faired_segments_output.hpp"

#include "io/atomic_output.hpp"
#include "lac_point_json.hpp"

namespace gf {

using json = nlohmann::ordered_json;

FairedSegmentsOutput::FairedSegmentsOutput(std::string source, const FairSettings& settings, double units_per_em) {
  document_["format"] = "glyphfair-faired-segments";
  document_["version"] = 1;
  document_["source"] = std::move(source);
  document_["units_per_em"] = units_per_em;
  document_["continuity"] = to_string(settings.continuity);
  document_["tolerance_units"] = settings.tolerance_units;
  document_["glyphs"] = json::array();
}

void FairedSegmentsOutput::add(const GlyphFairing& glyph) {
  json contours = json::array();
  for (std::size_t i = 0; i < glyph.pieces.size(); ++i) {
    const FairedPieces& pieces = glyph.pieces[i];
    json list = json::array();
    for (const FairedPiece& p : pieces) {
      json j{{"kind", to_string(p.kind)}, {"length", p.length}, {"smooth_start", p.smooth_start}};
      if (p.alpha) j["alpha"] = *p.alpha;
      if (p.bumps) j["symmetric_bump"] = p.bumps->first, j["odd_bump"] = p.bumps->second;
      j["start"] = lac_point_json(p.start);
      j["end"] = lac_point_json(p.end);
      list.push_back(std::move(j));
    }
    const bool closed = i < glyph.glyph.outline.contours.size() && glyph.glyph.outline.contours[i].closed;
    contours.push_back({{"closed", closed}, {"faired", !pieces.empty()}, {"pieces", std::move(list)}});
  }
  document_["glyphs"].push_back({{"name", glyph.glyph.name}, {"contours", std::move(contours)}});
}

void FairedSegmentsOutput::write(const std::filesystem::path& target, std::span<const std::filesystem::path> inputs) const {
  write_file_atomically(target, document_.dump(1) + "\n", inputs);
}

}  // namespace gf
