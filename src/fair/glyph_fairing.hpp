// A glyph faired contour by contour; name, unicodes, advance width, contour order and
// direction are the source's.
#pragma once

#include <string>
#include <vector>

#include "fair/contour_fairing.hpp"

namespace gf {

struct GlyphFairing {
  Glyph glyph;
  int contours_faired = 0;
  /// Contours kept as the source had them, with the reason (index: reason).
  std::vector<std::string> kept;
  double deviation = 0.0;  ///< largest over the faired contours, font units
  double max_curvature_mismatch = 0.0;
  int g1_nodes = 0;  ///< smooth nodes with G1 only
  int guide_stretches = 0;  ///< spans written from the smoothing guide
};

GlyphFairing fair_glyph(const Glyph& source, const FairSettings& settings);

}  // namespace gf
