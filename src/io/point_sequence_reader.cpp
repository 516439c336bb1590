#include "io/point_sequence_reader.hpp"

#include <cmath>
#include <fstream>

#include <nlohmann/json.hpp>

#include "geom/bspline_fit.hpp"
#include "io/input_error.hpp"

namespace gf {

namespace {

using json = nlohmann::json;

Contour stroke_contour(const json& stroke, double tolerance, const std::string& where) {
  if (!stroke.is_object() || !stroke.contains("points") || !stroke["points"].is_array())
    throw InputError(where + ": a stroke needs \"points\": [[x, y], ...]");
  std::vector<Vec2> points;
  for (const json& p : stroke["points"]) {
    if (!p.is_array() || p.size() != 2 || !p[0].is_number() || !p[1].is_number())
      throw InputError(where + ": every point is [x, y] with two numbers");
    const Vec2 q{p[0].get<double>(), p[1].get<double>()};
    if (!std::isfinite(q.x) || !std::isfinite(q.y)) throw InputError(where + ": a point is not finite");
    if (points.empty() || q != points.back()) points.push_back(q);  // repeated samples add nothing
  }
  const bool closed = stroke.value("closed", false);
  if (closed && points.size() > 1 && points.front() != points.back()) points.push_back(points.front());
  if (points.size() < (closed ? 6u : 4u))
    throw InputError(where + ": too few distinct points for a cubic B-spline (" + std::to_string(points.size()) + ")");
  const BSplineFit fit = fit_cubic_bspline_within(points, tolerance, closed);
  if (fit.spans.empty() || fit.max_residual > tolerance)
    throw InputError(where + ": no B-spline within " + std::to_string(tolerance) + " units of the points (best " +
                     std::to_string(fit.max_residual) + ")");
  Contour c;
  c.closed = closed;
  for (const Cubic& span : fit.spans) c.segments.emplace_back(span);
  c.nodes.assign(closed ? c.segments.size() : c.segments.size() + 1, NodeFlags{false, true});
  if (!closed) c.nodes.front().smooth = c.nodes.back().smooth = false;
  return c;
}

}  // namespace

GlyphSet read_point_sequences(const std::filesystem::path& path) {
  const std::string file = path.string();
  std::ifstream in(path);
  if (!in) throw InputError(file + ": cannot be read");
  json doc;
  try {
    doc = json::parse(in);
  } catch (const json::exception& e) {
    throw InputError(file + ": not JSON: " + e.what());
  }
  if (!doc.is_object() || !doc.contains("glyphs") || !doc["glyphs"].is_array())
    throw InputError(file + ": expected {\"glyphs\": [...]} (docs/points-format.md)");
  GlyphSet set;
  set.font.source_path = file;
  set.font.units_per_em = doc.value("unitsPerEm", 1000.0);
  if (!(set.font.units_per_em > 0.0)) throw InputError(file + ": unitsPerEm must be positive");
  set.font.ascender = 0.8 * set.font.units_per_em;
  set.font.descender = -0.2 * set.font.units_per_em;
  set.font.family_name = doc.value("familyName", std::string("Point sequences"));
  const double tolerance = doc.value("fitTolerance", 0.0025 * set.font.units_per_em);
  if (!(tolerance > 0.0)) throw InputError(file + ": fitTolerance must be positive");
  for (std::size_t i = 0; i < doc["glyphs"].size(); ++i) {
    const json& g = doc["glyphs"][i];
    Glyph glyph;
    glyph.name = g.is_object() ? g.value("name", "") : "";
    if (glyph.name.empty()) throw InputError(file + ": glyph " + std::to_string(i) + " has no \"name\"");
    const std::string where = file + ": glyph '" + glyph.name + "'";
    glyph.advance_width = g.value("advanceWidth", 0.0);
    for (const json& u : g.value("unicodes", json::array())) {
      if (!u.is_number_unsigned()) throw InputError(where + ": unicodes are code points (numbers)");
      glyph.unicodes.push_back(static_cast<char32_t>(u.get<std::uint32_t>()));
    }
    for (const json& stroke : g.value("strokes", json::array()))
      glyph.outline.contours.push_back(stroke_contour(stroke, tolerance, where));
    set.glyphs.push_back(std::move(glyph));
  }
  return set;
}

}  // namespace gf
