#include "render/proof_document.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>

#include <cairo-pdf.h>
#include <cairo-svg.h>
#include <cairo.h>

#include "check/contour_checks.hpp"
#include "geom/curvature_profile.hpp"
#include "io/atomic_output.hpp"
#include "io/file_extension.hpp"
#include "io/input_error.hpp"
#include "render/cairo_helpers.hpp"
#include "render/curvature_plot.hpp"
#include "render/glyph_painter.hpp"

namespace fs = std::filesystem;

namespace gf {

namespace {

std::vector<CurvatureProfile> profiles_of(const Outline& o) {
  std::vector<CurvatureProfile> out;
  for (const Contour& c : o.contours) out.push_back(curvature_profile(c));
  return out;
}

void extend(Box& b, const Outline& o) {
  for (const Contour& c : o.contours)
    for (const Segment& s : c.segments)
      for_each_point(s, [&](Vec2 p) {
        b.x0 = std::min(b.x0, p.x);
        b.x1 = std::max(b.x1, p.x);
        b.y0 = std::min(b.y0, p.y);
        b.y1 = std::max(b.y1, p.y);
      });
}

std::string unicode_list(const Glyph& g) {
  std::string out;
  for (const char32_t u : g.unicodes) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "U+%04X", static_cast<unsigned>(u));
    out += (out.empty() ? "" : " ") + std::string(buf);
  }
  return out;
}

std::size_t node_count(const Outline& o) {
  std::size_t n = 0;
  for (const Contour& c : o.contours)
    for (std::size_t i = 0; i < c.node_count(); ++i) n += c.nodes[i].implied ? 0 : 1;
  return n;
}

void paint_legend(cairo_t* cr, const ProofOptions& options) {
  const Box& b = page::legend;
  double x = b.x0;
  const double y = b.y0 + 8;
  const auto item = [&](colour::Rgba c, const std::string& what, auto&& symbol) {
    draw::set(cr, c);
    symbol(Vec2{x + 4, y - 3});
    draw::set(cr, colour::ink);
    draw::text(cr, {x + 11, y}, what, 6.5);
    x += 14 + draw::text_width(cr, what, 6.5) + 8;
  };
  item(colour::comb_positive, "comb: left turn", [&](Vec2 p) { draw::line(cr, p - Vec2{3, 0}, p + Vec2{3, 0}); cairo_set_line_width(cr, 2); cairo_stroke(cr); });
  item(colour::comb_negative, "right turn", [&](Vec2 p) { draw::line(cr, p - Vec2{3, 0}, p + Vec2{3, 0}); cairo_set_line_width(cr, 2); cairo_stroke(cr); });
  item(colour::inflection, "inflection", [&](Vec2 p) { draw::diamond(cr, p, 3); cairo_fill(cr); });
  item(colour::curvature_extremum, "curvature extremum", [&](Vec2 p) { draw::line(cr, p - Vec2{0, 4}, p + Vec2{0, 4}); cairo_set_line_width(cr, 1); cairo_stroke(cr); });
  item(colour::axis_extremum, "H/V extremum inside a segment", [&](Vec2 p) { draw::square(cr, p, 2.5); cairo_set_line_width(cr, 0.9); cairo_stroke(cr); });
  x = b.x0;
  const double y2 = y + 11;
  const auto item2 = [&](const std::string& what) {
    draw::set(cr, colour::ink);
    draw::text(cr, {x, y2}, what, 6.5);
    x += draw::text_width(cr, what, 6.5) + 10;
  };
  item2("\u25CF smooth node   \u25A0 corner   orange: kink (meant smooth, 0.05\u00B0 to 3\u00B0)   "
        "\u25CB off-curve   \u00B7 implied on-curve   green ring: start and direction");
  if (options.has_compare) {
    draw::set(cr, colour::compare);
    draw::text(cr, {x, y2}, "red: " + options.compare_label, 6.5, true);
  }
}

void paint_page(cairo_t* cr, const ProofGlyph& pg, const FontInfo& font, const ProofOptions& options, std::size_t index,
                std::size_t count) {
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  const Glyph& g = pg.glyph;

  // Header.
  draw::set(cr, colour::ink);
  draw::text(cr, {page::header.x0, page::header.y0 + 14}, g.name, 16, true);
  const std::string uni = unicode_list(g);
  draw::text(cr, {page::header.x0 + draw::text_width(cr, g.name, 16) * 1.1 + 10, page::header.y0 + 14}, uni, 9);
  char facts[160];
  std::snprintf(facts, sizeof facts, "advance %g   contours %zu   nodes %zu   UPM %g", g.advance_width,
                g.outline.contours.size(), node_count(g.outline), font.units_per_em);
  draw::text(cr, {page::header.x0, page::header.y0 + 28}, facts, 7.5);
  const std::string right = options.title + "   " + std::to_string(index + 1) + " / " + std::to_string(count);
  draw::set(cr, colour::metrics);
  draw::text(cr, {page::header.x1 - draw::text_width(cr, right, 7.5), page::header.y0 + 14}, right, 7.5);

  // Glyph panel: the em box, the advance and the outline(s), with room for the combs.
  Box content{0.0, font.descender, std::max(g.advance_width, 0.0), font.ascender};
  extend(content, g.outline);
  if (pg.compare) extend(content, pg.compare->outline);
  const double pad = 0.12 * font.units_per_em;
  content = {content.x0 - pad, content.y0 - pad, content.x1 + pad, content.y1 + pad};
  const PanelMap map = fit(content, page::glyph_panel);
  const std::vector<CurvatureProfile> profiles = profiles_of(g.outline);
  const std::vector<CurvatureProfile> compare_profiles = pg.compare ? profiles_of(pg.compare->outline) : std::vector<CurvatureProfile>{};

  cairo_save(cr);
  cairo_rectangle(cr, page::glyph_panel.x0, page::glyph_panel.y0, page::glyph_panel.width(), page::glyph_panel.height());
  cairo_clip(cr);
  paint_metrics(cr, map, font, g.advance_width, page::glyph_panel);
  paint_outline(cr, map, g.outline, colour::ink, true);
  paint_combs(cr, map, profiles, comb_gain(profiles, font.units_per_em), 0.3 * font.units_per_em);
  if (pg.compare) {
    paint_outline(cr, map, pg.compare->outline, {colour::compare.r, colour::compare.g, colour::compare.b, 0.85}, false);
    paint_points(cr, map, pg.compare->outline, colour::compare, false);
  }
  paint_points(cr, map, g.outline, colour::ink, true);
  paint_marks(cr, map, g.outline);
  cairo_restore(cr);
  if (options.has_compare && !pg.compare) {
    draw::set(cr, colour::compare);
    draw::text(cr, {page::glyph_panel.x0, page::glyph_panel.y1 - 4}, options.compare_label + " has no glyph of this name", 8);
  }

  std::vector<PlotSeries> series{{profiles, colour::ink}};
  if (pg.compare) series.push_back({compare_profiles, colour::compare});
  paint_curvature_plot(cr, page::plot_panel, series, font.units_per_em);
  paint_legend(cr, options);
}

// The counts a designer scans the overview for, from the same checks `glyphfair check` runs
// (so a proof and a report never disagree).
struct GlyphSummary {
  int inflections = 0, curvature_extrema = 0, missing_extrema = 0, kinks = 0;
};

GlyphSummary summarise(const Glyph& g, const FontInfo& font) {
  const GlyphReport r = check_glyph(g, font, *check_profile("text"));
  GlyphSummary s{r.fairness.inflections, r.fairness.curvature_extrema, 0, 0};
  for (const Finding& f : r.findings) {
    s.missing_extrema += f.check == "missing-extremum";
    s.kinks += f.check == "kink";
  }
  return s;
}

constexpr std::size_t overview_columns = 6, overview_rows = 7;
constexpr std::size_t overview_cells = overview_columns * overview_rows;

// A contact sheet: every glyph small, with the counts that point at curve problems and the
// page of its proof.
void paint_overview(cairo_t* cr, std::span<const ProofGlyph> glyphs, const FontInfo& font, const ProofOptions& options,
                    std::size_t sheet, std::size_t sheets) {
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  draw::set(cr, colour::ink);
  draw::text(cr, {page::header.x0, page::header.y0 + 14}, "Overview", 16, true);
  char facts[160];
  std::snprintf(facts, sizeof facts, "%zu glyphs   UPM %g   per glyph: inflections, curvature extrema, missing extrema, kinks",
                glyphs.size(), font.units_per_em);
  draw::text(cr, {page::header.x0, page::header.y0 + 28}, facts, 7.5);
  const std::string right = options.title + "   " + std::to_string(sheet + 1) + " / " + std::to_string(sheets);
  draw::set(cr, colour::metrics);
  draw::text(cr, {page::header.x1 - draw::text_width(cr, right, 7.5), page::header.y0 + 14}, right, 7.5);

  const Box area{page::header.x0, page::glyph_panel.y0, page::header.x1, page::legend.y1};
  const double cw = area.width() / overview_columns, ch = area.height() / overview_rows;
  const std::size_t first = sheet * overview_cells;
  for (std::size_t k = 0; k < overview_cells && first + k < glyphs.size(); ++k) {
    const Glyph& g = glyphs[first + k].glyph;
    const double x0 = area.x0 + cw * double(k % overview_columns), y0 = area.y0 + ch * double(k / overview_columns);
    const Box cell{x0 + 4, y0 + 4, x0 + cw - 4, y0 + ch - 26};
    cairo_set_line_width(cr, 0.3);
    draw::set(cr, colour::metrics);
    cairo_rectangle(cr, x0 + 1, y0 + 1, cw - 2, ch - 2);
    cairo_stroke(cr);
    Box content{0.0, font.descender, std::max(g.advance_width, 1.0), font.ascender};
    extend(content, g.outline);
    const PanelMap map = fit(content, cell);
    paint_outline(cr, map, g.outline, colour::ink, true);
    const GlyphSummary s = summarise(g, font);
    draw::set(cr, colour::ink);
    draw::text(cr, {x0 + 5, y0 + ch - 15}, g.name, 7.5, true);
    char counts[96];
    std::snprintf(counts, sizeof counts, "%d  %d  %d  %d   p. %zu", s.inflections, s.curvature_extrema, s.missing_extrema,
                  s.kinks, sheets + first + k + 1);
    draw::set(cr, s.kinks || s.missing_extrema ? colour::join_kink : colour::metrics);
    draw::text(cr, {x0 + 5, y0 + ch - 5}, counts, 6.5);
  }
}

struct SurfaceCloser {
  void operator()(cairo_surface_t* s) const { cairo_surface_destroy(s); }
};
struct ContextCloser {
  void operator()(cairo_t* c) const { cairo_destroy(c); }
};

void check(cairo_surface_t* surface, cairo_t* cr, const fs::path& target) {
  const cairo_status_t s = cr ? cairo_status(cr) : CAIRO_STATUS_SUCCESS;
  const cairo_status_t t = cairo_surface_status(surface);
  if (s != CAIRO_STATUS_SUCCESS || t != CAIRO_STATUS_SUCCESS)
    throw OutputError(target.string() + ": cairo: " + cairo_status_to_string(s != CAIRO_STATUS_SUCCESS ? s : t));
}

}  // namespace

std::optional<ProofFormat> proof_format_for(const fs::path& target) {
  const std::string ext = lower_extension(target);
  if (ext == ".pdf") return ProofFormat::pdf;
  if (ext == ".png") return ProofFormat::png;
  if (ext == ".svg") return ProofFormat::svg;
  return std::nullopt;
}

void write_proof(std::span<const ProofGlyph> glyphs, const FontInfo& font, const ProofOptions& options,
                 const fs::path& target, std::span<const fs::path> inputs) {
  const std::optional<ProofFormat> format = proof_format_for(target);
  if (!format) throw OutputError(target.string() + ": unknown proof format (use .pdf, .png or .svg)");
  AtomicOutput out(target, AtomicOutput::Kind::file, inputs);
  const std::string staging = out.staging_path().string();
  const std::size_t n = glyphs.size();

  if (*format == ProofFormat::pdf) {
    std::unique_ptr<cairo_surface_t, SurfaceCloser> surface(cairo_pdf_surface_create(staging.c_str(), page::width, page::height));
    std::unique_ptr<cairo_t, ContextCloser> cr(cairo_create(surface.get()));
    // Several glyphs open with contact sheets; each glyph then has its own page.
    const std::size_t sheets = n > 1 ? (n + overview_cells - 1) / overview_cells : 0;
    for (std::size_t k = 0; k < sheets; ++k) {
      paint_overview(cr.get(), glyphs, font, options, k, sheets);
      cairo_show_page(cr.get());
    }
    for (std::size_t i = 0; i < n; ++i) {
      paint_page(cr.get(), glyphs[i], font, options, sheets + i, sheets + n);
      cairo_show_page(cr.get());
    }
    check(surface.get(), cr.get(), target);
    cr.reset();
    cairo_surface_finish(surface.get());
    check(surface.get(), nullptr, target);
  } else {
    // One image: the pages in a grid, at most four across.
    const std::size_t columns = std::min<std::size_t>(std::max<std::size_t>(n, 1), 4);
    const std::size_t rows = (std::max<std::size_t>(n, 1) + columns - 1) / columns;
    const double scale = *format == ProofFormat::png ? (n <= 4 ? 2.0 : 1.0) : 1.0;
    const double w = page::width * double(columns) * scale, h = page::height * double(rows) * scale;
    if (*format == ProofFormat::png && h > 32000)
      throw OutputError(target.string() + ": " + std::to_string(n) + " glyphs are too many for one PNG; write a PDF");
    std::unique_ptr<cairo_surface_t, SurfaceCloser> surface(
        *format == ProofFormat::png
            ? cairo_image_surface_create(CAIRO_FORMAT_ARGB32, static_cast<int>(std::ceil(w)), static_cast<int>(std::ceil(h)))
            : cairo_svg_surface_create(staging.c_str(), w, h));
    std::unique_ptr<cairo_t, ContextCloser> cr(cairo_create(surface.get()));
    for (std::size_t i = 0; i < n; ++i) {
      cairo_save(cr.get());
      cairo_scale(cr.get(), scale, scale);
      cairo_translate(cr.get(), page::width * double(i % columns), page::height * double(i / columns));
      cairo_rectangle(cr.get(), 0, 0, page::width, page::height);
      cairo_clip(cr.get());
      paint_page(cr.get(), glyphs[i], font, options, i, n);
      cairo_restore(cr.get());
    }
    check(surface.get(), cr.get(), target);
    cr.reset();
    if (*format == ProofFormat::png) {
      if (cairo_surface_write_to_png(surface.get(), staging.c_str()) != CAIRO_STATUS_SUCCESS)
        throw OutputError(target.string() + ": cannot write the PNG");
    } else {
      cairo_surface_finish(surface.get());
      check(surface.get(), nullptr, target);
    }
  }
  out.commit();
}

}  // namespace gf
