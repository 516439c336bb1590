// Small drawing helpers over a cairo context in page coordinates.
#pragma once

#include <string>

#include <cairo.h>

#include "geom/vec2.hpp"
#include "render/colours.hpp"

namespace gf::draw {

inline void set(cairo_t* cr, colour::Rgba c) { cairo_set_source_rgba(cr, c.r, c.g, c.b, c.a); }
inline void line(cairo_t* cr, Vec2 a, Vec2 b) {
  cairo_move_to(cr, a.x, a.y);
  cairo_line_to(cr, b.x, b.y);
}
inline void circle(cairo_t* cr, Vec2 c, double r) {
  cairo_new_sub_path(cr);
  cairo_arc(cr, c.x, c.y, r, 0, 6.283185307179586);
}
inline void square(cairo_t* cr, Vec2 c, double half) { cairo_rectangle(cr, c.x - half, c.y - half, 2 * half, 2 * half); }
inline void diamond(cairo_t* cr, Vec2 c, double r) {
  cairo_move_to(cr, c.x, c.y - r);
  cairo_line_to(cr, c.x + r, c.y);
  cairo_line_to(cr, c.x, c.y + r);
  cairo_line_to(cr, c.x - r, c.y);
  cairo_close_path(cr);
}
inline void text(cairo_t* cr, Vec2 at, const std::string& s, double size, bool bold = false) {
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL,
                         bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size);
  cairo_move_to(cr, at.x, at.y);
  cairo_show_text(cr, s.c_str());
}
inline double text_width(cairo_t* cr, const std::string& s, double size) {
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size);
  cairo_text_extents_t e;
  cairo_text_extents(cr, s.c_str(), &e);
  return e.x_advance;
}

}  // namespace gf::draw
