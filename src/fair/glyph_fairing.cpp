#include "fair/glyph_fairing.hpp"

#include <algorithm>

#include "geom/straight_segments.hpp"

namespace gf {

GlyphFairing fair_glyph(const Glyph& source, const FairSettings& requested, FairedContours& faired) {
  FairSettings settings = requested;
  settings.rounding = resolve_rounding(requested.rounding, source.outline.contours);
  GlyphFairing out;
  out.glyph = source;
  out.glyph.outline.contours.clear();
  for (std::size_t i = 0; i < source.outline.contours.size(); ++i) {
    ContourFairing c = faired.fair(source.outline.contours[i], settings);
    const std::string contour = "contour " + std::to_string(i) + ": ";
    if (c.faired) {
      // The writeback and rounding may leave a straight stretch in several cubics on one line
      // (a guide's stem, its tangent crossing the vertical at each node, all rounded onto it):
      // one cubic draws it, no point moved. Only now, once every fairing of the contour has
      // been weighed and mended as it was.
      c.contour = with_straight_runs_joined(c.contour);
      ++out.contours_faired;
      out.deviation = std::max(out.deviation, c.deviation);
      out.max_curvature_mismatch = std::max(out.max_curvature_mismatch, c.max_curvature_mismatch);
      out.g1_nodes += c.g1_nodes;
      out.guide_stretches += c.guide_stretches;
      out.g3_runs += c.g3_runs;
      out.g2_line_joins += c.g2_line_joins;
      out.g3_cubics += c.g3_cubics;
      if (settings.continuity == Continuity::g3) out.g3_joins += g3_joins_of(c.contour);
      for (const std::string& why : c.g3_shortfalls) out.g3_shortfalls.push_back(contour + why);
      for (const std::string& why : c.runs_as_drawn) out.runs_as_drawn.push_back(contour + why);
    } else {
      out.kept.push_back(contour + c.reason);
    }
    out.glyph.outline.contours.push_back(std::move(c.contour));
    out.pieces.push_back(std::move(c.pieces));
  }
  return out;
}

GlyphFairing fair_glyph(const Glyph& source, const FairSettings& settings) {
  FairedContours none(0);
  return fair_glyph(source, settings, none);
}

}  // namespace gf
