#include "io/svg_reader.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>

#include <pugixml.hpp>

#include "io/input_error.hpp"
#include "io/number_format.hpp"
#include "io/svg_path_data.hpp"

namespace fs = std::filesystem;

namespace gf {

namespace {

// x' = a x + c y + e, y' = b x + d y + f (SVG's matrix(a b c d e f)).
struct Affine {
  double a = 1, b = 0, c = 0, d = 1, e = 0, f = 0;
  Vec2 apply(Vec2 p) const { return {a * p.x + c * p.y + e, b * p.x + d * p.y + f}; }
  Affine then(const Affine& inner) const {  // this ∘ inner
    return {a * inner.a + c * inner.b, b * inner.a + d * inner.b, a * inner.c + c * inner.d,
            b * inner.c + d * inner.d, a * inner.e + c * inner.f + e, b * inner.e + d * inner.f + f};
  }
};

Affine parse_transform(std::string_view s, const std::string& where) {
  Affine m;
  std::size_t i = 0;
  const auto skip = [&] { while (i < s.size() && (std::isspace(static_cast<unsigned char>(s[i])) || s[i] == ',')) ++i; };
  for (skip(); i < s.size(); skip()) {
    std::size_t j = i;
    while (j < s.size() && std::isalpha(static_cast<unsigned char>(s[j]))) ++j;
    const std::string name(s.substr(i, j - i));
    i = j;
    skip();
    if (i >= s.size() || s[i] != '(') throw InputError(where + ": transform '" + std::string(s) + "' is malformed");
    ++i;
    std::vector<double> args;
    for (skip(); i < s.size() && s[i] != ')'; skip()) {
      double v = 0;
      const auto [end, ec] = std::from_chars(s.data() + i, s.data() + s.size(), v);
      if (ec != std::errc()) throw InputError(where + ": transform '" + std::string(s) + "' has a bad number");
      args.push_back(v);
      i = static_cast<std::size_t>(end - s.data());
    }
    if (i >= s.size()) throw InputError(where + ": transform '" + std::string(s) + "' lacks ')'");
    ++i;
    const auto arg = [&](std::size_t k, double fallback) { return k < args.size() ? args[k] : fallback; };
    Affine t;
    const double rad = radians(arg(0, 0));
    if (name == "matrix" && args.size() == 6) t = {args[0], args[1], args[2], args[3], args[4], args[5]};
    else if (name == "translate" && !args.empty()) t = {1, 0, 0, 1, args[0], arg(1, 0)};
    else if (name == "scale" && !args.empty()) t = {args[0], 0, 0, arg(1, args[0]), 0, 0};
    else if (name == "rotate" && !args.empty()) {
      const double cx = arg(1, 0), cy = arg(2, 0);
      const Affine r{std::cos(rad), std::sin(rad), -std::sin(rad), std::cos(rad), 0, 0};
      t = Affine{1, 0, 0, 1, cx, cy}.then(r).then(Affine{1, 0, 0, 1, -cx, -cy});
    } else if (name == "skewX" && args.size() == 1) t = {1, 0, std::tan(rad), 1, 0, 0};
    else if (name == "skewY" && args.size() == 1) t = {1, std::tan(rad), 0, 1, 0, 0};
    else throw InputError(where + ": transform '" + std::string(s) + "' is not understood");
    m = m.then(t);
  }
  return m;
}

std::optional<double> number_attribute(const pugi::xml_node& n, const char* name) {
  const pugi::xml_attribute a = n.attribute(name);
  if (!a) return std::nullopt;
  return parse_number(a.value());
}

struct Walker {
  std::string file;
  GlyphSet& set;
  int unnamed = 0;

  void walk(const pugi::xml_node& node, const Affine& ctm) {
    for (const pugi::xml_node child : node.children()) {
      if (child.type() != pugi::node_element) continue;
      const std::string name = child.name();
      if (name == "defs" || name == "clipPath" || name == "mask" || name == "symbol" || name == "pattern") continue;
      Affine m = ctm;
      if (const pugi::xml_attribute t = child.attribute("transform"))
        m = ctm.then(parse_transform(t.value(), file));
      if (name == "path") add_path(child, m);
      else walk(child, m);
    }
  }

  void add_path(const pugi::xml_node& path, const Affine& m) {
    Glyph g;
    if (const char* n = path.attribute("data-glyph-name").value(); *n) g.name = n;
    else if (const char* id = path.attribute("id").value(); *id) g.name = id;
    else g.name = "path" + std::to_string(++unnamed);
    const std::string where = file + ": glyph '" + g.name + "'";
    const double origin = number_attribute(path, "data-origin-x").value_or(0.0);
    g.outline.contours = parse_svg_path_data(path.attribute("d").value(), where);
    double max_x = 0.0;
    for (Contour& c : g.outline.contours)
      for (Segment& s : c.segments)
        std::visit([&](auto& b) {
          for (Vec2& p : b.p) {
            const Vec2 u = m.apply(p);
            p = {u.x - origin, -u.y};
            max_x = std::max(max_x, p.x);
          }
        }, s);
    g.advance_width = number_attribute(path, "data-advance").value_or(max_x);
    set.glyphs.push_back(std::move(g));
  }
};

}  // namespace

GlyphSet read_svg(const fs::path& svg) {
  const std::string file = svg.string();
  std::error_code ec;
  if (!fs::exists(svg, ec)) throw InputError(file + ": no such file");
  pugi::xml_document doc;
  if (const auto r = doc.load_file(svg.c_str()); !r)
    throw InputError(file + ": not well-formed XML: " + r.description() + " at byte " + std::to_string(r.offset));
  const pugi::xml_node root = doc.child("svg");
  if (!root) throw InputError(file + ": not an SVG document (no <svg> root element)");
  GlyphSet set;
  set.font.source_path = file;
  set.font.units_per_em = number_attribute(root, "data-units-per-em").value_or(1000.0);
  set.font.ascender = number_attribute(root, "data-ascender").value_or(0.8 * set.font.units_per_em);
  set.font.descender = number_attribute(root, "data-descender").value_or(-0.2 * set.font.units_per_em);
  if (const char* family = root.attribute("data-family-name").value(); *family) set.font.family_name = family;
  Walker walker{file, set};
  walker.walk(root, Affine{});
  if (set.glyphs.empty()) throw InputError(file + ": has no <path> elements");
  return set;
}

}  // namespace gf
