// The checks on one glyph's outline and its fairness figures (issue "batch contour
// checking"): curve continuity (kink, g2-jump, wobble, inflections), extrema, and the
// structural checks of fontbakery and FontForge's Validate (peers.md §2.2).
#pragma once

#include <vector>

#include "check/check_profile.hpp"
#include "check/finding.hpp"
#include "geom/contour.hpp"

namespace gf {

/// How smoothly curvature flows through a glyph.
struct FairnessFigures {
  /// Curvature total variation × UPM: ∫|dκ/ds| ds over every segment plus Σ|κ jumps| at
  /// smooth joins (exact: |κ| summed between the segments' curvature extrema).
  double total_variation = 0.0;
  int curvature_extrema = 0;  ///< inside segments, and at smooth nodes where dκ/ds turns
  int inflections = 0;
  int curve_segments = 0;
  /// Of the curve segments, the fraction whose |κ| is monotone (no inflection or curvature
  /// extremum inside); 1 when there are none.
  double monotone_fraction = 1.0;
};

struct GlyphReport {
  std::string glyph;
  std::vector<Finding> findings;  ///< in contour, then place order
  FairnessFigures fairness;
};

GlyphReport check_glyph(const Glyph& glyph, const FontInfo& font, const CheckProfile& profile);

}  // namespace gf
