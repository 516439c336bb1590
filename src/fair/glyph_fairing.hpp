// A glyph faired contour by contour; name, unicodes, advance width, contour order and
// direction are the source's.
#pragma once

#include <string>
#include <vector>

#include "fair/contour_fairing.hpp"
#include "fair/faired_contours.hpp"
#include "fair/g3_joins.hpp"

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
  int g3_runs = 0;          ///< --continuity g3: smooth runs that came out G3
  int g2_line_joins = 0;    ///< and their line joins held to G2
  std::vector<std::string> g3_shortfalls;  ///< "contour i: why", for each run that stayed G2
  G3CubicReport g3_cubics;                 ///< --continuity g3: the written cubics' runs, summed
  G3JoinCount g3_joins;  ///< --continuity g3: the faired contours' joins between curves as written
  std::vector<std::string> runs_as_drawn;  ///< "contour i: where and why", for each run kept as drawn
  std::vector<FairedPieces> pieces;        ///< per contour, the faired curve before the writeback
};

/// `settings.rounding` as_source resolved on the whole glyph: rounded to integers only when
/// every point of every contour is a whole unit. A contour `faired` already holds (another
/// glyph's component) takes the result it holds.
GlyphFairing fair_glyph(const Glyph& source, const FairSettings& settings, FairedContours& faired);

/// Each contour faired afresh.
GlyphFairing fair_glyph(const Glyph& source, const FairSettings& settings);

}  // namespace gf
