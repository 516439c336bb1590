// SVG path data (the `d` attribute) to contours and back. Parsing covers the whole grammar:
// M L H V C S Q T A Z, absolute and relative; elliptical arcs become cubics (at most 90° each,
// the standard approximation, within 3e-4 of the radius). Coordinates stay as written
// (SVG user space); the reader and writer do the y flip.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "geom/contour.hpp"

namespace gf {

/// Throws InputError (prefixed with `where`) on malformed data.
std::vector<Contour> parse_svg_path_data(std::string_view d, const std::string& where);

/// Absolute M L Q C Z commands with shortest round-trip numbers. A closed contour's last
/// segment is left to Z when it is a line; open contours have no Z.
std::string format_svg_path_data(const std::vector<Contour>& contours);

}  // namespace gf
