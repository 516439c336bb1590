#include "io/ufo_reader.hpp"

#include <algorithm>
#include <map>
#include <set>

#include <pugixml.hpp>

#include "io/input_error.hpp"
#include "io/number_format.hpp"
#include "io/plist.hpp"

namespace fs = std::filesystem;

namespace gf {

namespace {

struct RawPoint {
  Vec2 p;
  std::string type;  // "" for offcurve
  bool smooth = false;
};

struct Component {
  std::string base;
  double xx = 1, xy = 0, yx = 0, yy = 1, dx = 0, dy = 0;
  Vec2 apply(Vec2 p) const { return {xx * p.x + yx * p.y + dx, xy * p.x + yy * p.y + dy}; }
};

struct RawGlyph {
  Glyph glyph;  // own contours only
  std::vector<Component> components;
};

class ContourBuilder {
 public:
  ContourBuilder(std::string where) : where_(std::move(where)) {}

  Contour build(std::vector<RawPoint> pts) {
    Contour c;
    if (pts.empty()) return c;
    const bool open = pts[0].type == "move";
    for (std::size_t i = 1; i < pts.size(); ++i)
      if (pts[i].type == "move") fail("a move point occurs after the first point of a contour");
    c.closed = !open;
    bool start_implied = false;
    if (!open) {
      const auto on = std::find_if(pts.begin(), pts.end(), [](const RawPoint& r) { return !r.type.empty(); });
      if (on == pts.end()) {
        // Only off-curve points: a quadratic loop whose on-curve points are all implied.
        const RawPoint start{(pts.back().p + pts.front().p) * 0.5, "qcurve", false};
        pts.insert(pts.begin(), start);
        start_implied = true;
      } else {
        std::rotate(pts.begin(), on, pts.end());
      }
      pts.push_back(pts.front());  // walk back to the start
    }
    c.nodes.push_back({start_implied, pts[0].smooth});
    Vec2 current = pts[0].p;
    std::vector<Vec2> offs;
    for (std::size_t i = 1; i < pts.size(); ++i) {
      const RawPoint& r = pts[i];
      if (r.type.empty()) {
        offs.push_back(r.p);
        continue;
      }
      const bool last = i + 1 == pts.size();
      if (r.type == "line") {
        if (!offs.empty()) fail("a line point has off-curve points before it");
        c.segments.push_back(Line{{current, r.p}});
      } else if (r.type == "curve") {
        if (offs.size() > 2) fail("too many off-curve points before a curve point");
        if (offs.empty()) c.segments.push_back(Line{{current, r.p}});
        else if (offs.size() == 1) c.segments.push_back(Quad{{current, offs[0], r.p}});
        else c.segments.push_back(Cubic{{current, offs[0], offs[1], r.p}});
      } else if (r.type == "qcurve") {
        if (offs.empty()) c.segments.push_back(Line{{current, r.p}});
        for (std::size_t k = 0; k < offs.size(); ++k) {
          const bool final_off = k + 1 == offs.size();
          const Vec2 end = final_off ? r.p : (offs[k] + offs[k + 1]) * 0.5;
          c.segments.push_back(Quad{{current, offs[k], end}});
          if (!final_off) c.nodes.push_back({true, std::nullopt});
          current = end;
        }
      } else if (r.type == "move") {
        fail("a move point occurs after the first point of a contour");
      } else {
        fail("unknown point type '" + r.type + "'");
      }
      offs.clear();
      current = r.p;
      if (!(last && !open)) c.nodes.push_back({false, r.smooth});
    }
    if (!offs.empty()) fail("an open contour ends with off-curve points");
    return c;
  }

 private:
  [[noreturn]] void fail(const std::string& why) const { throw InputError(where_ + ": " + why); }
  std::string where_;
};

double attr_number(const pugi::xml_node& n, const char* name, double fallback, const std::string& where) {
  const pugi::xml_attribute a = n.attribute(name);
  if (!a) return fallback;
  const std::string_view text = a.value();
  const std::optional<double> v = parse_number(text);
  if (!v) throw InputError(where + ": attribute " + name + "=\"" + std::string(text) + "\" is not a number");
  return *v;
}

RawGlyph read_glif(const fs::path& file, const std::string& expected_name, const std::string& ufo) {
  const std::string where = ufo + ": glyph '" + expected_name + "'";
  pugi::xml_document doc;
  if (const auto r = doc.load_file(file.c_str()); !r) {
    std::error_code ec;
    if (!fs::exists(file, ec)) throw InputError(where + ": its file " + file.filename().string() + " is missing");
    throw InputError(where + ": " + file.filename().string() + " is not well-formed XML: " + r.description());
  }
  const pugi::xml_node g = doc.child("glyph");
  if (!g) throw InputError(where + ": " + file.filename().string() + " has no <glyph> element");
  RawGlyph raw;
  raw.glyph.name = expected_name;
  raw.glyph.advance_width = attr_number(g.child("advance"), "width", 0.0, where);
  for (const pugi::xml_node u : g.children("unicode")) {
    const std::string hex = u.attribute("hex").value();
    char* end = nullptr;
    const unsigned long v = std::strtoul(hex.c_str(), &end, 16);
    if (hex.empty() || *end != '\0' || v > 0x10FFFF) throw InputError(where + ": unicode hex=\"" + hex + "\" is not a code point");
    raw.glyph.unicodes.push_back(static_cast<char32_t>(v));
  }
  ContourBuilder builder(where);
  for (const pugi::xml_node n : g.child("outline").children()) {
    const std::string kind = n.name();
    if (kind == "contour") {
      std::vector<RawPoint> pts;
      for (const pugi::xml_node p : n.children("point")) {
        RawPoint r{{attr_number(p, "x", 0.0, where), attr_number(p, "y", 0.0, where)}, p.attribute("type").value(),
                   std::string(p.attribute("smooth").value()) == "yes"};
        if (!p.attribute("x") || !p.attribute("y")) throw InputError(where + ": a point lacks x or y");
        if (r.type == "offcurve") r.type.clear();
        if (r.type.empty() && r.smooth) throw InputError(where + ": smooth attribute set on an off-curve point");
        pts.push_back(std::move(r));
      }
      Contour c = builder.build(std::move(pts));
      if (!c.segments.empty()) raw.glyph.outline.contours.push_back(std::move(c));
    } else if (kind == "component") {
      Component comp{n.attribute("base").value(),
                     attr_number(n, "xScale", 1, where), attr_number(n, "xyScale", 0, where),
                     attr_number(n, "yxScale", 0, where), attr_number(n, "yScale", 1, where),
                     attr_number(n, "xOffset", 0, where), attr_number(n, "yOffset", 0, where)};
      if (comp.base.empty()) throw InputError(where + ": a component has no base glyph");
      raw.components.push_back(std::move(comp));
    }
  }
  return raw;
}

Contour transformed(const Contour& c, const Component& t) {
  Contour out = c;
  for (Segment& s : out.segments)
    std::visit([&](auto& b) { for (Vec2& p : b.p) p = t.apply(p); }, s);
  return out;
}

void decompose(const std::string& name, const std::map<std::string, RawGlyph>& raw, std::vector<std::string>& stack,
               Outline& into, const Component& transform, const std::string& ufo) {
  const auto it = raw.find(name);
  if (it == raw.end())
    throw InputError(ufo + ": glyph '" + stack.front() + "': component base glyph '" + name + "' does not exist");
  if (std::find(stack.begin(), stack.end(), name) != stack.end())
    throw InputError(ufo + ": glyph '" + stack.front() + "': components refer to each other in a cycle");
  stack.push_back(name);
  for (const Contour& c : it->second.glyph.outline.contours) into.contours.push_back(transformed(c, transform));
  for (const Component& comp : it->second.components) {
    // Compose: the inner component's transform first, then the outer one.
    Component composed = transform;
    composed.xx = transform.xx * comp.xx + transform.yx * comp.xy;
    composed.xy = transform.xy * comp.xx + transform.yy * comp.xy;
    composed.yx = transform.xx * comp.yx + transform.yx * comp.yy;
    composed.yy = transform.xy * comp.yx + transform.yy * comp.yy;
    const Vec2 d = transform.apply({comp.dx, comp.dy});
    composed.dx = d.x;
    composed.dy = d.y;
    decompose(comp.base, raw, stack, into, composed, ufo);
  }
  stack.pop_back();
}

std::optional<double> info_number(const PlistDict& d, const char* key) {
  const auto it = d.find(key);
  return it == d.end() ? std::nullopt : it->second.number();
}

}  // namespace

GlyphSet read_ufo(const fs::path& ufo) {
  const std::string name = ufo.string();
  std::error_code ec;
  if (!fs::exists(ufo, ec)) throw InputError(name + ": no such file or directory");
  if (!fs::is_directory(ufo, ec)) throw InputError(name + ": a UFO is a directory, and this is not one");
  const PlistValue meta = read_plist(ufo / "metainfo.plist");
  const auto version = meta.dict() ? info_number(*meta.dict(), "formatVersion") : std::nullopt;
  if (!version || (*version != 2 && *version != 3))
    throw InputError(name + ": metainfo.plist does not give formatVersion 2 or 3");

  GlyphSet set;
  set.font.source_path = name;
  if (fs::exists(ufo / "fontinfo.plist", ec)) {
    const PlistValue info = read_plist(ufo / "fontinfo.plist");
    if (const PlistDict* d = info.dict()) {
      if (auto it = d->find("familyName"); it != d->end() && it->second.string()) set.font.family_name = *it->second.string();
      if (auto it = d->find("styleName"); it != d->end() && it->second.string()) set.font.style_name = *it->second.string();
      set.font.units_per_em = info_number(*d, "unitsPerEm").value_or(1000.0);
      set.font.ascender = info_number(*d, "ascender").value_or(0.8 * set.font.units_per_em);
      set.font.descender = info_number(*d, "descender").value_or(-0.2 * set.font.units_per_em);
      set.font.x_height = info_number(*d, "xHeight");
      set.font.cap_height = info_number(*d, "capHeight");
    }
  }
  if (set.font.units_per_em <= 0) throw InputError(name + ": fontinfo.plist gives unitsPerEm <= 0");

  std::string layer_dir = "glyphs";
  if (fs::exists(ufo / "layercontents.plist", ec)) {
    const PlistValue layers = read_plist(ufo / "layercontents.plist");
    const PlistArray* a = layers.array();
    if (!a || a->empty() || !(*a)[0].array() || (*a)[0].array()->size() != 2 || !(*(*a)[0].array())[1].string())
      throw InputError(name + ": layercontents.plist is not a list of [layer name, directory] pairs");
    layer_dir = *(*(*a)[0].array())[1].string();
  }
  const PlistValue contents = read_plist(ufo / layer_dir / "contents.plist");
  if (!contents.dict()) throw InputError(name + ": " + layer_dir + "/contents.plist is not a dictionary");

  std::map<std::string, RawGlyph> raw;
  for (const auto& [glyph, file] : *contents.dict()) {
    if (!file.string()) throw InputError(name + ": glyph '" + glyph + "': contents.plist maps it to no file name");
    raw.emplace(glyph, read_glif(ufo / layer_dir / *file.string(), glyph, name));
  }

  std::vector<std::string> order;
  std::set<std::string> placed;
  if (fs::exists(ufo / "lib.plist", ec)) {
    const PlistValue lib = read_plist(ufo / "lib.plist");
    if (const PlistDict* d = lib.dict())
      if (auto it = d->find("public.glyphOrder"); it != d->end() && it->second.array())
        for (const PlistValue& v : *it->second.array())
          if (v.string() && raw.count(*v.string()) && placed.insert(*v.string()).second) order.push_back(*v.string());
  }
  for (const auto& [glyph, r] : raw)
    if (placed.insert(glyph).second) order.push_back(glyph);

  for (const std::string& glyph : order) {
    const RawGlyph& r = raw.at(glyph);
    Glyph g = r.glyph;
    std::vector<std::string> stack{glyph};
    for (const Component& comp : r.components) decompose(comp.base, raw, stack, g.outline, comp, name);
    set.glyphs.push_back(std::move(g));
  }
  return set;
}

}  // namespace gf
