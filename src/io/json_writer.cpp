#include "io/json_writer.hpp"

#include <cmath>
#include <cstdio>

#include <nlohmann/json.hpp>

#include "geom/arc_length.hpp"
#include "geom/critical_points.hpp"
#include "geom/join.hpp"
#include "io/atomic_output.hpp"

namespace gf {

namespace {

using nlohmann::json;

json point(Vec2 p) { return json::array({p.x, p.y}); }

json optional_number(const std::optional<double>& v) { return v ? json(*v) : json(nullptr); }

const char* segment_type(const Segment& s) {
  switch (degree_of(s)) {
    case 1: return "line";
    case 2: return "quadratic";
    default: return "cubic";
  }
}

json segment_json(const Segment& s) {
  json j;
  j["type"] = segment_type(s);
  json pts = json::array();
  for_each_point(s, [&](Vec2 p) { pts.push_back(point(p)); });
  j["points"] = pts;
  const ArcLength length = arc_length(s);
  j["length"] = length.length;
  if (!length.converged) j["length_error_estimate"] = length.error_estimate;
  const CriticalPoints cp = critical_points(s);
  const auto at = [&s](double t) { return json{{"t", t}, {"point", point(point_at(s, t))}}; };
  json inflections = json::array();
  for (const double t : cp.inflections) inflections.push_back(at(t));
  json extrema = json::array();
  for (const CurvatureExtremum& e : cp.curvature_extrema) {
    json x = at(e.t);
    x["curvature"] = e.curvature;
    x["kind"] = e.maximum ? "maximum" : "minimum";
    extrema.push_back(x);
  }
  json cusps = json::array();
  for (const double t : cp.cusps) cusps.push_back(at(t));
  json axis = json::array();
  for (const AxisExtremum& e : cp.axis_extrema) {
    json x = at(e.t);
    x["tangent"] = e.tangent == Axis::horizontal ? "horizontal" : "vertical";
    axis.push_back(x);
  }
  j["inflections"] = inflections;
  j["curvature_extrema"] = extrema;
  j["cusps"] = cusps;
  j["hv_extrema"] = axis;
  return j;
}

json contour_json(const Contour& c) {
  json j;
  j["closed"] = c.closed;
  if (c.closed) {
    const double area = signed_area(c);
    j["area"] = area;
    j["direction"] = area > 0 ? "counter-clockwise" : area < 0 ? "clockwise" : "none";
  }
  json segments = json::array();
  for (const Segment& s : c.segments) segments.push_back(segment_json(s));
  j["segments"] = segments;
  const std::vector<Join> joins = joins_of(c);
  json nodes = json::array();
  std::size_t next_join = 0;
  for (std::size_t i = 0; i < c.node_count(); ++i) {
    json n;
    n["point"] = point(c.node_point(i));
    n["implied"] = c.nodes[i].implied;
    n["smooth_flag"] = c.nodes[i].smooth ? json(*c.nodes[i].smooth) : json(nullptr);
    if (next_join < joins.size() && joins[next_join].node == i) {
      const Join& jn = joins[next_join++];
      n["join"] = {{"kind", to_string(jn.kind)},
                   {"angle_deg", jn.angle_deg},
                   {"curvature_in", optional_number(jn.curvature_in)},
                   {"curvature_out", optional_number(jn.curvature_out)},
                   {"dcurvature_ds_in", optional_number(jn.curvature_derivative_in)},
                   {"dcurvature_ds_out", optional_number(jn.curvature_derivative_out)}};
    } else {
      n["join"] = nullptr;
    }
    nodes.push_back(n);
  }
  j["nodes"] = nodes;
  return j;
}

std::string unicode_label(char32_t u) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "U+%04X", static_cast<unsigned>(u));
  return buf;
}

}  // namespace

std::string outline_json(const GlyphSet& glyphs) {
  const FontInfo& f = glyphs.font;
  json root;
  root["format"] = "glyphfair-outline";
  root["version"] = json_format_version;
  root["font"] = {{"source", f.source_path},
                  {"family_name", f.family_name},
                  {"style_name", f.style_name},
                  {"units_per_em", f.units_per_em},
                  {"ascender", f.ascender},
                  {"descender", f.descender},
                  {"x_height", optional_number(f.x_height)},
                  {"cap_height", optional_number(f.cap_height)}};
  json list = json::array();
  for (const Glyph& g : glyphs.glyphs) {
    json jg;
    jg["name"] = g.name;
    json unicodes = json::array();
    for (const char32_t u : g.unicodes) unicodes.push_back(unicode_label(u));
    jg["unicodes"] = unicodes;
    jg["advance_width"] = g.advance_width;
    json contours = json::array();
    for (const Contour& c : g.outline.contours) contours.push_back(contour_json(c));
    jg["contours"] = contours;
    list.push_back(jg);
  }
  root["glyphs"] = list;
  return root.dump(1) + "\n";
}

void write_json(const GlyphSet& glyphs, const std::filesystem::path& target,
                std::span<const std::filesystem::path> inputs) {
  write_file_atomically(target, outline_json(glyphs), inputs);
}

}  // namespace gf
