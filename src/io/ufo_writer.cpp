#include "io/ufo_writer.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>

#include <pugixml.hpp>

#include "geom/join.hpp"
#include "io/atomic_output.hpp"
#include "io/input_error.hpp"
#include "io/number_format.hpp"
#include "io/plist.hpp"
#include "io/ufo_file_names.hpp"

namespace fs = std::filesystem;

namespace gf {

namespace {

PlistValue number(double v) {
  if (v == std::floor(v) && std::abs(v) < 1e15) return {static_cast<long long>(v)};
  return {v};
}

const char* arriving_type(const Segment& s) {
  switch (degree_of(s)) {
    case 1: return "line";
    case 2: return "qcurve";
    default: return "curve";
  }
}

void add_point(pugi::xml_node contour, Vec2 p, const char* type, bool smooth) {
  pugi::xml_node n = contour.append_child("point");
  n.append_attribute("x") = shortest_decimal(p.x).c_str();
  n.append_attribute("y") = shortest_decimal(p.y).c_str();
  if (type) n.append_attribute("type") = type;
  if (smooth) n.append_attribute("smooth") = "yes";
}

void add_off_curves(pugi::xml_node contour, const Segment& s) {
  std::visit(
      [&](const auto& b) {
        for (std::size_t i = 1; i + 1 < b.p.size(); ++i) add_point(contour, b.p[i], nullptr, false);
      },
      s);
}

// A node is written unless it is an implied point between two quadratics (then the qcurve's
// consecutive off-curve points imply it again). Node 0 is always written: a contour needs an
// explicit on-curve point (fontmake fails on off-curve-only contours: sketch-refine-io.md §8).
bool written(const Contour& c, std::size_t node) {
  if (node == 0 || node >= c.segments.size() || !c.nodes[node].implied) return true;
  return degree_of(c.segments[node - 1]) != 2 || degree_of(c.segments[node]) != 2;
}

void add_contour(pugi::xml_node outline, const Contour& c) {
  if (c.segments.empty()) return;
  pugi::xml_node xc = outline.append_child("contour");
  std::vector<bool> smooth(c.node_count(), false);
  for (const Join& j : joins_of(c)) smooth[j.node] = j.kind == JoinKind::smooth;
  for (std::size_t i = 0; i < c.node_count(); ++i)
    if (c.nodes[i].smooth) smooth[i] = *c.nodes[i].smooth;
  const std::size_t n = c.segments.size();
  add_point(xc, c.node_point(0), c.closed ? arriving_type(c.segments[n - 1]) : "move", smooth[0]);
  for (std::size_t i = 0; i < n; ++i) {
    add_off_curves(xc, c.segments[i]);
    const std::size_t end = i + 1;
    if (c.closed && end == n) break;  // back at node 0, written first
    if (written(c, end)) add_point(xc, c.node_point(end), arriving_type(c.segments[i]), smooth[end]);
  }
}

std::string glif_xml(const Glyph& g) {
  pugi::xml_document doc;
  pugi::xml_node decl = doc.append_child(pugi::node_declaration);
  decl.append_attribute("version") = "1.0";
  decl.append_attribute("encoding") = "UTF-8";
  pugi::xml_node glyph = doc.append_child("glyph");
  glyph.append_attribute("name") = g.name.c_str();
  glyph.append_attribute("format") = "2";
  glyph.append_child("advance").append_attribute("width") = shortest_decimal(g.advance_width).c_str();
  for (const char32_t u : g.unicodes) {
    char hex[16];
    std::snprintf(hex, sizeof hex, "%04X", static_cast<unsigned>(u));
    glyph.append_child("unicode").append_attribute("hex") = hex;
  }
  pugi::xml_node outline = glyph.append_child("outline");
  for (const Contour& c : g.outline.contours) add_contour(outline, c);
  std::ostringstream out;
  doc.save(out, "  ", pugi::format_default, pugi::encoding_utf8);
  return out.str();
}

void write_text(const fs::path& path, const std::string& text) {
  std::ofstream f(path, std::ios::binary);
  f << text;
  f.close();
  if (!f) throw OutputError(path.string() + ": write failed");
}

}  // namespace

UfoWriter::UfoWriter(const fs::path& target, const FontInfo& f, std::span<const fs::path> inputs)
    : target_(target), out_(target, AtomicOutput::Kind::directory, inputs) {
  const fs::path root = out_.staging_path();
  write_text(root / "metainfo.plist",
             plist_to_xml(plist_dict({{"creator", {std::string("org.glyphfair")}}, {"formatVersion", {3LL}}})));
  PlistDict info{{"unitsPerEm", number(f.units_per_em)},
                 {"ascender", number(f.ascender)},
                 {"descender", number(f.descender)}};
  if (!f.family_name.empty()) info["familyName"] = {f.family_name};
  if (!f.style_name.empty()) info["styleName"] = {f.style_name};
  if (f.x_height) info["xHeight"] = number(*f.x_height);
  if (f.cap_height) info["capHeight"] = number(*f.cap_height);
  write_text(root / "fontinfo.plist", plist_to_xml(plist_dict(std::move(info))));
  write_text(root / "layercontents.plist",
             plist_to_xml(plist_array({plist_array({{std::string("public.default")}, {std::string("glyphs")}})})));
  std::error_code ec;
  fs::create_directory(root / "glyphs", ec);
  if (ec) throw OutputError(target.string() + ": cannot create glyphs/: " + ec.message());
}

UfoWriter::~UfoWriter() = default;

void UfoWriter::add(const Glyph& g) {
  if (contents_.count(g.name)) return;  // a name can be written once
  const std::string file = glif_file_name(g.name, taken_);
  write_text(out_.staging_path() / "glyphs" / file, glif_xml(g));
  contents_[g.name] = {file};
  order_.push_back({g.name});
}

void UfoWriter::commit() {
  const fs::path root = out_.staging_path();
  write_text(root / "glyphs" / "contents.plist", plist_to_xml(plist_dict(std::move(contents_))));
  write_text(root / "lib.plist", plist_to_xml(plist_dict({{"public.glyphOrder", plist_array(std::move(order_))}})));
  out_.commit();
}

void write_ufo(const GlyphSet& glyphs, const fs::path& target, std::span<const fs::path> inputs) {
  UfoWriter writer(target, glyphs.font, inputs);
  for (const Glyph& g : glyphs.glyphs) writer.add(g);
  writer.commit();
}

}  // namespace gf
