// One glyph in the glyph panel: metric lines, outline, points and handles, curvature combs,
// and marks at inflections, curvature extrema and H/V extrema.
#pragma once

#include <span>

#include <cairo.h>

#include "geom/contour.hpp"
#include "geom/curvature_profile.hpp"
#include "render/colours.hpp"
#include "render/proof_layout.hpp"

namespace gf {

/// Font units of comb tooth per unit of curvature: one per page, so every comb on it compares.
double comb_gain(std::span<const CurvatureProfile> profiles, double units_per_em);

void paint_metrics(cairo_t* cr, const PanelMap& map, const FontInfo& font, double advance_width, const Box& panel);
void paint_combs(cairo_t* cr, const PanelMap& map, std::span<const CurvatureProfile> profiles, double gain,
                 double max_tooth_units);
void paint_outline(cairo_t* cr, const PanelMap& map, const Outline& outline, colour::Rgba stroke, bool filled);
void paint_points(cairo_t* cr, const PanelMap& map, const Outline& outline, colour::Rgba tint, bool detailed);
void paint_marks(cairo_t* cr, const PanelMap& map, const Outline& outline);

}  // namespace gf
