// `glyphfair curve --format svg`: a constructed curve with its curvature comb and the points it
// was built from, y up, in a 600-pixel-wide picture.
#pragma once

#include <span>
#include <string>

#include "aesthetic/log_aesthetic_segment.hpp"

namespace gf {

/// `curve`: points along the curve, in order; `guide`: the control triangle or the points
/// interpolated, drawn dashed.
std::string curve_svg(std::span<const LacPoint> curve, std::span<const Vec2> guide);

}  // namespace gf
