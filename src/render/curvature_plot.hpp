// The κ(s) panel: signed curvature (times UPM) against arc length along each contour, the
// contours side by side, joins marked so that curvature jumps show.
#pragma once

#include <span>
#include <vector>

#include <cairo.h>

#include "geom/curvature_profile.hpp"
#include "render/colours.hpp"
#include "render/proof_layout.hpp"

namespace gf {

struct PlotSeries {
  std::span<const CurvatureProfile> contours;
  colour::Rgba colour;
};

void paint_curvature_plot(cairo_t* cr, const Box& panel, std::span<const PlotSeries> series, double units_per_em);

}  // namespace gf
