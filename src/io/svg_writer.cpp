#include "io/svg_writer.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <pugixml.hpp>

#include "io/atomic_output.hpp"
#include "io/number_format.hpp"
#include "io/svg_path_data.hpp"

namespace gf {

std::string svg_document(const GlyphSet& glyphs) {
  const FontInfo& f = glyphs.font;
  // Whole-unit pen positions keep (x + pen) − pen == x, so the file reads back exactly.
  const double gap = std::round(0.1 * f.units_per_em);
  double pen = 0.0, top = f.ascender, bottom = f.descender;
  pugi::xml_document doc;
  pugi::xml_node decl = doc.append_child(pugi::node_declaration);
  decl.append_attribute("version") = "1.0";
  decl.append_attribute("encoding") = "UTF-8";
  pugi::xml_node svg = doc.append_child("svg");
  svg.append_attribute("xmlns") = "http://www.w3.org/2000/svg";
  pugi::xml_node group = svg.append_child("g");
  group.append_attribute("fill") = "black";
  for (const Glyph& g : glyphs.glyphs) {
    for (const Contour& c : g.outline.contours)
      for (const Segment& s : c.segments)
        for_each_point(s, [&](Vec2 p) { top = std::max(top, p.y); bottom = std::min(bottom, p.y); });
    pugi::xml_node path = group.append_child("path");
    path.append_attribute("data-glyph-name") = g.name.c_str();
    path.append_attribute("data-advance") = shortest_decimal(g.advance_width).c_str();
    path.append_attribute("data-origin-x") = shortest_decimal(pen).c_str();
    path.append_attribute("transform") = ("matrix(1 0 0 -1 " + shortest_decimal(pen) + " 0)").c_str();
    path.append_attribute("d") = format_svg_path_data(g.outline.contours).c_str();
    pen += std::ceil(std::max(g.advance_width, 0.0)) + gap;
  }
  const double margin = 0.05 * f.units_per_em;
  const double width = std::max(pen - gap, f.units_per_em * 0.5) + 2 * margin;
  const double height = top - bottom + 2 * margin;
  const std::string box = shortest_decimal(-margin) + " " + shortest_decimal(-top - margin) + " " +
                          shortest_decimal(width) + " " + shortest_decimal(height);
  svg.prepend_attribute("viewBox") = box.c_str();
  svg.append_attribute("data-units-per-em") = shortest_decimal(f.units_per_em).c_str();
  svg.append_attribute("data-ascender") = shortest_decimal(f.ascender).c_str();
  svg.append_attribute("data-descender") = shortest_decimal(f.descender).c_str();
  if (!f.family_name.empty()) svg.append_attribute("data-family-name") = f.family_name.c_str();
  std::ostringstream out;
  doc.save(out, "  ", pugi::format_default, pugi::encoding_utf8);
  return out.str();
}

void write_svg(const GlyphSet& glyphs, const std::filesystem::path& target,
               std::span<const std::filesystem::path> inputs) {
  write_file_atomically(target, svg_document(glyphs), inputs);
}

}  // namespace gf
