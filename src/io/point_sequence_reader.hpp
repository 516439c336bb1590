// Handwritten point sequences (seed 000 [0038]–[0045]) as glyphs: each stroke is fitted with a
// least-squares cubic B-spline, its span count raised until every point is within the fit
// tolerance, and becomes a contour the fairing takes like any other. The format is in
// docs/points-format.md:
//   {"unitsPerEm": 1000, "fitTolerance": 2.5,
//    "glyphs": [{"name": "a", "unicodes": [97], "advanceWidth": 560,
//                "strokes": [{"closed": true, "points": [[x, y], ...]}]}]}
#pragma once

#include <filesystem>

#include "geom/contour.hpp"

namespace gf {

/// Throws InputError naming the file, the glyph and the problem.
GlyphSet read_point_sequences(const std::filesystem::path& json);

}  // namespace gf
